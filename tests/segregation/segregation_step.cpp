// The segregation modules on small hand-checkable grids: face visiting, eq. (64), the time step,
// the reconstruction, and the configuration the kinematic drum reuses unchanged (a drum-shaped inside
// mask, coefficients of random sign, a stream-function flow, compressible mass fluxes).
#include "core/error.hpp"
#include "flow/faces/convection.hpp"
#include "kinematic/kinematic_flow.hpp"
#include "segregation/bulk_transport.hpp"
#include "segregation/column.hpp"
#include "segregation/invariants.hpp"
#include "segregation/reconstruction.hpp"
#include "segregation/segregation_solver.hpp"

#include <boost/test/unit_test.hpp>

#include <cfloat>
#include <cmath>
#include <random>

using namespace granseg;
namespace tt = boost::test_tools;

namespace {

/// A 2-D grid in the x-z plane whose inside cells form a disc of radius 0.95 (edge cells outside).
Grid drum(int n) {
    Grid g = Grid::plane_xz(n, n, -1.1, -1.1, 2.2, 2.2);
    g.inside.assign(g.cells(), 0);
    for (int k = 0; k < n; ++k)
        for (int i = 0; i < n; ++i) g.inside[g.index(i, 0, k)] = std::hypot(g.center(0, i), g.center(2, k)) < 0.95;
    return g;
}

bool within_bounds(const Grid& g, const std::vector<double>& phi, const std::vector<double>& Phi) {
    for (std::size_t c = 0; c < phi.size(); ++c)
        if (g.is_inside(c) && !(phi[c] >= 0.0 && phi[c] <= Phi[c])) return false;
    return true;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(segregation_step_tests)

BOOST_AUTO_TEST_CASE(faces_know_their_cells_walls_and_periodic_wrap) {
    Grid g = Grid::plane_xz(3, 2, 0.0, 0.0, 3.0, 2.0);
    std::vector<FaceCells> faces;
    for_each_face(g, 0, [&](const FaceCells& f) { faces.push_back(f); });
    BOOST_TEST(faces.size() == 8u);  // 4 layers x 2 rows
    BOOST_TEST(faces[0].lower == kNoCell);
    BOOST_TEST(faces[0].upper == 0u);
    BOOST_TEST(faces[1].lower == 0u);
    BOOST_TEST(faces[1].upper == 1u);
    BOOST_TEST(faces[3].upper == kNoCell);
    BOOST_TEST(faces[5].face == g.face_index(0, 1, 0, 1));
    g.periodic[0] = true;
    faces.clear();
    for_each_face(g, 0, [&](const FaceCells& f) { faces.push_back(f); });
    BOOST_TEST(faces[0].lower == 2u);
    BOOST_TEST(faces[3].lower == 2u);
    BOOST_TEST(faces[3].upper == 0u);
    BOOST_TEST(faces[3].duplicate);
    BOOST_TEST(!faces[0].duplicate);
}

BOOST_AUTO_TEST_CASE(flux_difference_telescopes_and_skips_outside_cells) {
    Grid g = Grid::column(4, 1.0);
    g.inside = {1, 1, 1, 0};
    std::vector<double> u = {1.0, 2.0, 3.0, 7.0}, F = {0.0, 0.5, -0.25, 0.0, 0.0};
    apply_flux_difference(g, 2, F, 0.1, u);
    BOOST_TEST(u[0] == 1.0 - 0.1 / 0.25 * 0.5, tt::tolerance(1e-15));
    BOOST_TEST(u[1] == 2.0 - 0.1 / 0.25 * (-0.25 - 0.5), tt::tolerance(1e-15));
    BOOST_TEST(u[3] == 7.0);  // outside: untouched
    BOOST_TEST(u[0] + u[1] + u[2] == 6.0 - 0.1 / 0.25 * (F[3] - F[0]), tt::tolerance(1e-15));
}

BOOST_AUTO_TEST_CASE(cfl_above_one_is_rejected) {
    SegregationOptions o;
    o.cfl = 1.5;
    BOOST_CHECK_THROW(SegregationSolver(Grid::column(4, 1.0), o), InputError);
    o.cfl = 0.0;
    BOOST_CHECK_THROW(SegregationSolver(Grid::column(4, 1.0), o), InputError);
    o.cfl = 1.0;
    BOOST_CHECK_NO_THROW(SegregationSolver(Grid::column(4, 1.0), o));
}

BOOST_AUTO_TEST_CASE(time_step_follows_the_documented_formula) {
    ColumnSetup s;
    s.cells = 10;
    s.S = 2.0;
    s.Phi = [](double) { return 0.5; };
    s.T = [](double z) { return z < 0.5 ? 1.0 : 4.0; };  // a = 2 and 4
    s.D = 0.01;
    const Column c = make_column(s);
    const double h = 0.1;
    SegregationOptions o;
    o.cfl = 0.5;
    BOOST_TEST(SegregationSolver(c.grid, o).time_step(c.fields) == 0.5 / (4.0 / h + 2 * 0.01 / (h * h)), tt::tolerance(1e-14));
    o.scheme = SegregationScheme::modified_godunov_2;
    BOOST_TEST(SegregationSolver(c.grid, o).time_step(c.fields) == 0.5 * 2.0 / (2 * 4.0 / h + 2 * 0.01 / (h * h)),
               tt::tolerance(1e-14));
}

BOOST_AUTO_TEST_CASE(interface_rule_exact_or_mean) {
    ColumnSetup s;
    s.cells = 4;
    s.Phi = [](double z) { return 0.5 + 0.2 * z * z; };
    s.T = [](double z) { return 1.0 + z; };
    const Column exact = make_column(s);
    s.interface = InterfaceRule::mean;
    const Column mean = make_column(s);
    BOOST_TEST(exact.fields.Phi_face[2][2] == 0.5 + 0.2 * 0.25, tt::tolerance(1e-15));  // face at z = 0.5
    BOOST_TEST(mean.fields.Phi_face[2][2] == 0.5 * (mean.fields.Phi[1] + mean.fields.Phi[2]), tt::tolerance(1e-15));
    BOOST_TEST(exact.fields.a_face[2][2] == std::sqrt(1.5), tt::tolerance(1e-15));
    BOOST_TEST((parse_interface_rule("mean") == InterfaceRule::mean));
    BOOST_CHECK_THROW(parse_interface_rule("harmonic"), InputError);
}

BOOST_AUTO_TEST_CASE(scheme_names_round_trip) {
    for (const auto& name : scheme_names()) BOOST_TEST(scheme_name(parse_scheme(name)) == name);
    for (const auto& name : limiter_names()) BOOST_TEST(limiter_name(parse_limiter(name)) == name);
    BOOST_CHECK_THROW(parse_scheme("godunov"), InputError);
}

BOOST_AUTO_TEST_CASE(reconstruction_stays_between_neighbours_and_averages_to_phi) {
    const Grid g = Grid::column(6, 1.0);
    const std::vector<double> Phi = {0.5, 0.6, 0.3, 0.62, 0.55, 0.4};
    const std::vector<double> phi = {0.1, 0.3, 0.2, 0.6, 0.0, 0.4};
    for (Limiter limiter : {Limiter::minmod, Limiter::mc}) {
        std::vector<double> lower, upper;
        reconstruct_faces(g, 2, phi, Phi, limiter, lower, upper);
        for (int i = 1; i < 5; ++i) {
            const double lo = std::min({phi[i - 1] / Phi[i - 1], phi[i] / Phi[i], phi[i + 1] / Phi[i + 1]});
            const double hi = std::max({phi[i - 1] / Phi[i - 1], phi[i] / Phi[i], phi[i + 1] / Phi[i + 1]});
            for (double v : {lower[i], upper[i]}) {
                BOOST_TEST(v >= Phi[i] * lo - 1e-15);
                BOOST_TEST(v <= Phi[i] * hi + 1e-15);
            }
            BOOST_TEST(0.5 * (lower[i] + upper[i]) == phi[i], tt::tolerance(1e-14));
        }
        BOOST_TEST(lower[0] == phi[0]);  // next to the wall: first order
    }
    BOOST_TEST(limited_slope(0.1, 0.3, Limiter::mc) == 0.2, tt::tolerance(1e-15));
    BOOST_TEST(limited_slope(0.1, 0.3, Limiter::minmod) == 0.1);
    BOOST_TEST(limited_slope(0.1, -0.3, Limiter::mc) == 0.0);
}

// The kinematic drum (src/tumbler/) reuses this set-up unchanged: a drum, a_k of random sign per cell, a rotation.
BOOST_AUTO_TEST_CASE(drum_with_random_sign_coefficients_keeps_bounds_and_mass) {
    const Grid g = drum(24);
    std::mt19937 random(5);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    FrozenFields fields;
    fields.Phi.assign(g.cells(), 0.0);
    std::vector<double> phi(g.cells(), 0.0);
    for (std::size_t c = 0; c < g.cells(); ++c)
        if (g.is_inside(c)) fields.Phi[c] = 0.55 + 0.05 * unit(random), phi[c] = fields.Phi[c] * (0.5 + 0.5 * unit(random));
    for (int axis : {0, 2}) {
        fields.a[axis].resize(g.cells());
        for (double& a : fields.a[axis]) a = unit(random);
    }
    const FaceFields M = stream_function_mass_fluxes(g, [](double x, double z) { return 0.3 * (x * x + z * z); });
    for (SegregationScheme scheme : {SegregationScheme::modified_godunov, SegregationScheme::modified_godunov_2}) {
        std::vector<double> u = phi, Phi = fields.Phi;
        SegregationOptions o;
        o.scheme = scheme;
        o.cfl = 1.0;
        SegregationSolver solver(g, o);
        const double mass = total_amount(g, u);
        for (int step = 0; step < 200; ++step) {
            const double dt = std::min(bulk_time_step(g, Phi, M, 1.0), solver.time_step(fields));
            transport_bulk(g, Phi, M, FaceFields{}, dt, u);
            apply_mass_fluxes(g, M, dt, Phi);  // divergence-free: Phi stays put to round-off
            solver.step(fields, dt, u);
        }
        BOOST_TEST(within_bounds(g, u, fields.Phi));
        BOOST_TEST(solver.largest_correction() <= kBoundRoundOff);
        BOOST_TEST(total_amount(g, u) == mass, tt::tolerance(1e-13));
        double drift = 0.0;
        for (std::size_t c = 0; c < g.cells(); ++c) drift = std::max(drift, std::fabs(Phi[c] - fields.Phi[c]));
        BOOST_TEST(drift <= 200 * 4 * DBL_EPSILON);  // round-off of 200 divergence-free updates
    }
}

// The kinematic rolling drum (src/tumbler/) drives the bulk step and the split
// segregation step unchanged: its face fields are FaceFields, its grid a Grid with a bed mask.
BOOST_AUTO_TEST_CASE(kinematic_drum_of_issue5_drives_the_steps_unchanged) {
    const RollingDrumFields drum = discretize(RollingDrumFlow(RollingDrumParameters{}), 40, 0.6);
    const Grid& g = drum.grid;
    FrozenFields fields;
    fields.Phi.assign(g.cells(), 0.0);
    std::vector<double> phi(g.cells(), 0.0);
    for (std::size_t c = 0; c < g.cells(); ++c)
        if (g.is_inside(c)) fields.Phi[c] = 0.6, phi[c] = 0.3;
    for (int axis : {0, 2}) {  // a coefficient that changes sign across the drum
        fields.a[axis].resize(g.cells());
        for (int k = 0; k < g.n[2]; ++k)
            for (int i = 0; i < g.n[0]; ++i)
                fields.a[axis][g.index(i, 0, k)] = 0.01 * std::sin(200.0 * (axis == 0 ? g.center(0, i) : g.center(2, k)));
    }
    SegregationSolver solver(g, SegregationOptions{});
    const double mass = total_amount(g, phi);
    const double dt = std::min(bulk_time_step(g, fields.Phi, drum.M, 0.9), solver.time_step(fields));
    for (int step = 0; step < 300; ++step) {
        transport_bulk(g, fields.Phi, drum.M, FaceFields{}, dt, phi);
        solver.step(fields, dt, phi);
    }
    BOOST_TEST(within_bounds(g, phi, fields.Phi));
    BOOST_TEST(solver.largest_correction() <= kBoundRoundOff);
    BOOST_TEST(total_amount(g, phi) == mass, tt::tolerance(1e-13));
}

BOOST_AUTO_TEST_CASE(bulk_step_is_a_convex_combination_of_phi_hat) {
    const Grid g = drum(16);
    std::mt19937 random(7);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    std::vector<double> Phi(g.cells(), 0.0), phi(g.cells(), 0.0);
    for (std::size_t c = 0; c < g.cells(); ++c)
        if (g.is_inside(c)) Phi[c] = 0.01 + 0.5 * unit(random), phi[c] = Phi[c] * unit(random);
    FaceFields M;
    for (int axis : {0, 2}) {
        M[axis].assign(g.faces(axis), 0.0);
        for_each_face(g, axis, [&](const FaceCells& f) {
            if (is_open_face(g, f)) M[axis][f.face] = 0.2 * (unit(random) - 0.5);
        });
    }
    const double dt = bulk_time_step(g, Phi, M, 1.0);
    std::vector<double> Phi_new = Phi, phi_new = phi;
    apply_mass_fluxes(g, M, dt, Phi_new);
    transport_bulk(g, Phi, M, FaceFields{}, dt, phi_new);
    for (std::size_t c = 0; c < g.cells(); ++c) {
        if (!g.is_inside(c)) continue;
        BOOST_TEST(Phi_new[c] >= -1e-15);
        BOOST_TEST(phi_new[c] >= -1e-15);
        BOOST_TEST(phi_new[c] <= Phi_new[c] + 1e-15);  // phi_hat_new in [0, 1]
    }
    BOOST_TEST(total_amount(g, phi_new) == total_amount(g, phi), tt::tolerance(1e-13));
    M[0][g.face_index(0, 0, 0, 8)] = 0.1;  // a face between two outside cells (a wall)
    BOOST_CHECK_THROW(transport_bulk(g, Phi, M, FaceFields{}, dt, phi_new), InvariantError);
}

BOOST_AUTO_TEST_CASE(stream_function_fluxes_vanish_on_walls) {
    const Grid g = drum(20);
    const FaceFields M = stream_function_mass_fluxes(g, [](double x, double z) { return 1.0 + x * x + std::sin(z); });
    long nonzero_on_walls = 0;
    for (int axis : {0, 2})
        for_each_face(g, axis, [&](const FaceCells& f) {
            if (!is_open_face(g, f) && M[axis][f.face] != 0.0) ++nonzero_on_walls;
        });
    BOOST_TEST(nonzero_on_walls == 0);
    Grid slab;
    slab.n = {2, 2, 2};  // a 3-D slab has no 2-D stream function
    BOOST_CHECK_THROW(stream_function_mass_fluxes(slab, [](double, double) { return 0.0; }), InputError);
}

BOOST_AUTO_TEST_SUITE_END()
