// Verification of the transport of Phi and phi (docs/flow_solver.md, transport): the donor cell and the
// high-resolution scheme (transport/muscl_hancock.hpp for Phi, segregation/bulk_transport_fct.hpp
// for phi), against exact solutions.
//
// A. The transport alone. Phi and phi are carried once around a circular domain (radius R = 1,
//    staircase wall) by a prescribed rigid rotation (face velocities from the stream function
//    omega (R^2 - r^2)/2, discretely divergence-free, 0 on every wall face) with the schemes as the
//    coupled drum uses them: Phi_new = Phi - dt div M, M = U times the value the upwind cell gives
//    the face (its Phi, or its MUSCL-Hancock value), and phi by the bulk transport with that M. After
//    one turn the exact fields are the initial ones. Two initial states: smooth (a C^3 bump in Phi
//    and in phi_hat) and discontinuous (a disc of Phi holding a smaller disc of small grains). The
//    observed order in L1 between 64 and 128 cells per diameter must reach, on smooth data, 1 for
//    the donor cell and 2 for the high-resolution scheme (each up to the share an extremum-clipping
//    limiter costs, below), and at the discontinuity the orders theory gives for a contact carried
//    by a linear scheme of order p, p/(p + 1): 1/2 and 2/3 (Harten, Hyman & Lax, CPAM 29, 1976;
//    LeVeque, "Finite Volume Methods for Hyperbolic Problems", 2002, Sect. 8.6). Every step keeps
//    Phi >= 0 and 0 <= phi <= Phi (phi_hat in [0, 1]) and the amount of each phase to round-off,
//    and phi_hat makes no new extremum.
// B. The flow solver's mass balance. A smooth Phi (below the loosest packing: no yield pressure)
//    carried by a uniform velocity (1, 0.5) m/s across a box periodic along x and z, no gravity,
//    T at its floor (the pressure ~1e-12 Pa/rho: the velocity stays uniform): after a quarter of
//    the period along x the exact Phi is the initial one shifted by (1, 0.5) m/s times the time.
//    Observed order in L1 between 32 and 64 cells, each transport.
// C. The bounds under stress: random compressible steps (random Phi from 1e-3 to 0.6, phi_hat of
//    0, 1 or random in jumps, random face mass fluxes scaled so that no cell loses more than 0.9 of
//    its Phi, as the flow's outflow bound guarantees) on a 24 x 24 box with walls. The FCT step must
//    keep phi_hat in [0, 1] and the amount of phi to round-off in every step; the same high-order
//    flux without the limiter must leave [0, 1] in some steps (so the check can fail).
// Writes transport_orders.dat.
//
// Run: build/verification/verify_transport [--data DIR]   (a few seconds)
#include "core/error.hpp"
#include "flow/faces/convection.hpp"
#include "flow/flow_solver.hpp"
#include "harness/check_table.hpp"
#include "harness/flow_reference.hpp"
#include "harness/program.hpp"
#include "segregation/bulk_transport.hpp"
#include "segregation/bulk_transport_fct.hpp"
#include "segregation/reconstruction.hpp"
#include "transport/muscl_hancock.hpp"

#include <algorithm>
#include <cmath>
#include <random>
#include <string>
#include <vector>

using namespace granseg;
using granseg::verify::CheckTable;

namespace {

// Orders (64 -> 128 cells per diameter in A, 32 -> 64 in B). On smooth data the limiters clip
// the extrema to first order in a band of O(h) cells around each, which costs a fraction of the
// order at these grids: at least 0.8 of the formal order (1.6 of 2, 0.8 of 1).
constexpr double kSmoothShare = 0.8;
// At the discontinuity: within 0.15 of p/(p + 1); measured orders at finite grids scatter about
// the asymptotic value by that much (LeVeque 2002, Fig. 8.5 shows 0.5-0.6 for upwind).
constexpr double kContactBand = 0.15;
// Round-off: a few ulps of the amounts passing through a cell per step, over ~1000 steps.
constexpr double kMassTol = 1e-12;
constexpr double kBoundTol = 1e-13;

enum class Scheme { donor_cell, high_resolution };
const char* scheme_name(Scheme s) { return s == Scheme::donor_cell ? "donor-cell" : "muscl"; }

/// A C^3 bump of height 1 and radius a about (x0, z0): (1 - (r/a)^2)^4 inside, 0 outside.
double bump(double x, double z, double x0, double z0, double a) {
    const double s = ((x - x0) * (x - x0) + (z - z0) * (z - z0)) / (a * a);
    return s < 1.0 ? std::pow(1.0 - s, 4) : 0.0;
}
double disc(double x, double z, double x0, double z0, double a) {
    return (x - x0) * (x - x0) + (z - z0) * (z - z0) < a * a ? 1.0 : 0.0;
}

struct Errors {
    double Phi = 0, phi = 0;  // L1 over the domain (area-weighted) at the end
    double min_Phi = INFINITY, min_hat = INFINITY, max_hat = -INFINITY;
    double mass_Phi = 0, mass_phi = 0;  // largest relative change over the run
    double hat_lo = 0, hat_hi = 0;      // extremes of the initial phi_hat over material cells
};

/// The initial fields of part A at (x, z): Phi and phi_hat, smooth or discontinuous.
struct Initial {
    bool smooth;
    double Phi(double x, double z) const {
        return smooth ? 0.3 + 0.2 * bump(x, z, kX0, 0.0, 0.5) : 0.1 + 0.4 * disc(x, z, kX0, 0.0, 0.4);
    }
    double phi_hat(double x, double z) const {
        return smooth ? 0.2 + 0.6 * bump(x, z, kX0, 0.0, 0.45) : disc(x, z, kX0, 0.0, 0.25);
    }
    static constexpr double kX0 = 0.3;  // centre of the profiles
};

/// Part A on n x n cells: a quarter turn of the rigid rotation with `scheme`.
Errors rotate(int n, Scheme scheme, const Initial& initial) {
    const double R = 1.0, omega = 2.0 * M_PI, t_end = 0.25;
    Grid grid = Grid::plane_xz(n, n, -R, -R, 2 * R, 2 * R);
    grid.inside.assign(grid.cells(), 0);
    for (int k = 0; k < n; ++k)
        for (int i = 0; i < n; ++i) {
            const double x = grid.center(0, i), z = grid.center(2, k);
            grid.inside[grid.index(i, 0, k)] = x * x + z * z < R * R;
        }
    const FaceFields U =
        stream_function_mass_fluxes(grid, [&](double x, double z) { return 0.5 * omega * (R * R - x * x - z * z); });
    std::vector<double> Phi(grid.cells(), 0.0), phi(grid.cells(), 0.0);
    Errors e;
    e.hat_lo = INFINITY, e.hat_hi = -INFINITY;
    for_each_bed_cell(grid, [&](const BedCell& b) {
        Phi[b.c] = initial.Phi(b.x, b.z);
        phi[b.c] = initial.phi_hat(b.x, b.z) * Phi[b.c];
        e.hat_lo = std::min(e.hat_lo, phi[b.c] / Phi[b.c]), e.hat_hi = std::max(e.hat_hi, phi[b.c] / Phi[b.c]);
    });
    // dt: Courant number 0.4 on |u_x| + |u_z| <= sqrt(2) omega R, a whole number of steps.
    const double h = grid.h[0];
    const long steps = static_cast<long>(std::ceil(t_end / (0.4 * h / (std::sqrt(2.0) * omega * R))));
    const double dt = t_end / steps;
    MusclHancock reconstruction(grid, Limiter::mc);
    BulkTransport donor(grid);
    FctBulkTransport fct(grid, Limiter::mc);
    FaceFields M = U;
    auto total = [&](const std::vector<double>& f) {
        long double s = 0;
        for (std::size_t c = 0; c < grid.cells(); ++c) s += f[c];
        return static_cast<double>(s);
    };
    const double mass_Phi0 = total(Phi), mass_phi0 = total(phi);
    std::vector<double> Phi_old;
    for (long s = 0; s < steps; ++s) {
        if (scheme == Scheme::high_resolution) reconstruction.face_values(Phi, refs(U), dt, MusclHancock::Form::conservative);
        for (int a : {0, 2})
            for_each_face(grid, a, [&](const FaceCells& f) {
                const double u = U[a][f.face];
                if (u == 0.0 || !is_open_face(grid, f)) return void(M[a][f.face] = 0.0);
                const double value = scheme == Scheme::donor_cell ? (u > 0.0 ? Phi[f.lower] : Phi[f.upper])
                                     : u > 0.0                    ? reconstruction.from_lower()[a][f.face]
                                                                  : reconstruction.from_upper()[a][f.face];
                M[a][f.face] = u * value;
            });
        Phi_old = Phi;
        apply_mass_fluxes(grid, M, dt, Phi);
        if (scheme == Scheme::donor_cell)
            donor.step(Phi_old, refs(M), {}, dt, phi);
        else
            fct.step(Phi_old, Phi, refs(M), {}, dt, phi);
        for_each_bed_cell(grid, [&](const BedCell& b) {
            e.min_Phi = std::min(e.min_Phi, Phi[b.c]);
            e.min_hat = std::min(e.min_hat, phi[b.c] / Phi[b.c]), e.max_hat = std::max(e.max_hat, phi[b.c] / Phi[b.c]);
        });
        e.mass_Phi = std::max(e.mass_Phi, std::fabs(total(Phi) / mass_Phi0 - 1.0));
        e.mass_phi = std::max(e.mass_phi, std::fabs(total(phi) / mass_phi0 - 1.0));
    }
    // The exact fields at t_end: the initial ones turned by omega t_end.
    const double turn = omega * t_end, ct = std::cos(turn), st = std::sin(turn);
    for_each_bed_cell(grid, [&](const BedCell& b) {
        const double x = ct * b.x + st * b.z, z = -st * b.x + ct * b.z;
        const double Phi_exact = initial.Phi(x, z);
        e.Phi += std::fabs(Phi[b.c] - Phi_exact) * h * h;
        e.phi += std::fabs(phi[b.c] - initial.phi_hat(x, z) * Phi_exact) * h * h;
    });
    return e;
}

/// Part B on n x n cells: L1 error of Phi after one period along x (half a period along z).
double periodic_box(const Material& m, int n, Transport transport) {
    const double L = 0.1, ux = 1.0, uz = 0.5;
    Grid grid = Grid::plane_xz(n, n, 0.0, 0.0, L, L);
    grid.periodic[0] = grid.periodic[2] = true;
    FlowSettings s;
    s.transport = transport;
    s.dt_max = 1.0;  // the Courant number alone sets dt: refined with h
    Frame frame;
    frame.gravity = 0.0;
    FlowSolver solver(grid, m, s, frame);
    auto profile = [&](double x, double z) { return 0.3 + 0.1 * std::sin(2 * M_PI * x / L) * std::sin(2 * M_PI * z / L); };
    std::vector<double> Phi(grid.cells()), T(grid.cells(), s.T_floor);
    std::array<std::vector<double>, 3> u{std::vector<double>(grid.cells(), ux), std::vector<double>(grid.cells(), 0.0),
                                         std::vector<double>(grid.cells(), uz)};
    for (int k = 0; k < n; ++k)
        for (int i = 0; i < n; ++i) Phi[grid.index(i, 0, k)] = profile(grid.center(0, i), grid.center(2, k));
    solver.set_state(Phi, u, T);
    const double t_end = L / (4 * ux);
    while (solver.time() < t_end) solver.step(t_end);
    double error = 0.0;
    for (int k = 0; k < n; ++k)
        for (int i = 0; i < n; ++i) {  // the exact Phi at t_end: shifted by (ux, uz) t_end
            const double exact = profile(grid.center(0, i) - ux * t_end, grid.center(2, k) - uz * t_end);
            error += std::fabs(solver.Phi()[grid.index(i, 0, k)] - exact) * grid.h[0] * grid.h[2];
        }
    return error / (L * L);
}

/// Part C: what random compressible steps do to phi_hat, with the FCT step and with its unlimited
/// high-order flux.
struct StressResult {
    long steps = 0, unlimited_outside = 0;          // steps; steps whose unlimited update left [0, 1]
    double worst_excess = 0.0, worst_amount = 0.0;  // FCT: largest excursion of phi_hat beyond [0, 1]; |change of sum phi|/sum
};
StressResult stress(long steps) {
    const int n = 24;
    const Grid grid = Grid::plane_xz(n, n, 0.0, 0.0, 1.0, 1.0);
    std::mt19937 rng(20261204);
    std::uniform_real_distribution<double> uniform(0.0, 1.0);
    MusclHancock high_order(grid, Limiter::mc);
    FctBulkTransport fct(grid, Limiter::mc);
    StressResult r;
    const double dt = 1.0, h = grid.h[0];
    for (long s = 0; s < steps; ++s, ++r.steps) {
        std::vector<double> Phi(grid.cells()), phi(grid.cells());
        for (std::size_t c = 0; c < grid.cells(); ++c) {
            Phi[c] = std::exp(std::log(1e-3) + uniform(rng) * std::log(600.0));  // 1e-3 .. 0.6, log-uniform
            const double pick = uniform(rng);
            phi[c] = (pick < 0.3 ? 0.0 : pick < 0.6 ? 1.0 : uniform(rng)) * Phi[c];
        }
        FaceFields M;
        std::vector<double> out(grid.cells(), 0.0);
        for (int a : {0, 2}) {
            M[a].assign(grid.faces(a), 0.0);
            for_each_face(grid, a, [&](const FaceCells& f) {
                if (!is_open_face(grid, f)) return;
                M[a][f.face] = (2.0 * uniform(rng) - 1.0) * std::max(Phi[f.lower], Phi[f.upper]);
                out[M[a][f.face] > 0.0 ? f.lower : f.upper] += std::fabs(M[a][f.face]) * dt / h;
            });
        }
        for (int a : {0, 2})  // no cell loses more than 0.9 of its Phi (the flow's outflow bound)
            for_each_face(grid, a, [&](const FaceCells& f) {
                double& m = M[a][f.face];
                if (m == 0.0) return;
                const std::size_t from = m > 0.0 ? f.lower : f.upper;
                m *= std::min(1.0, 0.9 * Phi[from] / out[from]);
            });
        std::vector<double> Phi_new = Phi;
        apply_mass_fluxes(grid, M, dt, Phi_new);
        // The unlimited high-order update: phi - dt div(M phi_hat_f), phi_hat_f the MUSCL-Hancock value.
        std::vector<double> hat(grid.cells());
        for (std::size_t c = 0; c < grid.cells(); ++c) hat[c] = composition(phi[c], Phi[c]);
        FaceFields velocity, G;
        for (int a : {0, 2}) {
            velocity[a].assign(grid.faces(a), 0.0);
            for_each_face(grid, a, [&](const FaceCells& f) {
                const double m = M[a][f.face];
                if (m != 0.0) velocity[a][f.face] = m / Phi[m > 0.0 ? f.lower : f.upper];
            });
        }
        high_order.face_values(hat, refs(velocity), dt, MusclHancock::Form::advective);
        for (int a : {0, 2}) {
            G[a].assign(grid.faces(a), 0.0);
            for_each_face(grid, a, [&](const FaceCells& f) {
                const double m = M[a][f.face];
                if (m != 0.0)
                    G[a][f.face] = m * (m > 0.0 ? high_order.from_lower()[a][f.face] : high_order.from_upper()[a][f.face]);
            });
        }
        std::vector<double> unlimited = phi;
        apply_mass_fluxes(grid, G, dt, unlimited);
        bool outside = false;
        for (std::size_t c = 0; c < grid.cells(); ++c)
            outside |= unlimited[c] < -kBoundTol * Phi_new[c] || unlimited[c] > (1.0 + kBoundTol) * Phi_new[c];
        r.unlimited_outside += outside;
        long double before = 0, after = 0;
        for (double v : phi) before += v;
        fct.step(Phi, Phi_new, refs(M), {}, dt, phi);
        for (std::size_t c = 0; c < grid.cells(); ++c) {
            after += phi[c];
            r.worst_excess = std::max({r.worst_excess, -phi[c] / Phi_new[c], phi[c] / Phi_new[c] - 1.0});
        }
        r.worst_amount = std::max(r.worst_amount, static_cast<double>(std::fabs(after - before) / before));
    }
    return r;
}

}  // namespace

int main(int argc, char** argv) {
    const verify::FlowProgram program = verify::flow_program(argc, argv);
    CheckTable table("Transport of Phi and phi: donor cell and MUSCL-Hancock (+ FCT for phi) against exact solutions");
    DataTable data;
    const int sizes[] = {32, 64, 128};
    for (const Scheme scheme : {Scheme::donor_cell, Scheme::high_resolution}) {
        const double p = scheme == Scheme::donor_cell ? 1.0 : 2.0;
        for (const bool smooth : {true, false}) {
            const std::string tag = std::string("[A, ") + scheme_name(scheme) + (smooth ? ", smooth] " : ", discontinuous] ");
            std::vector<Errors> runs;
            for (int n : sizes) {
                runs.push_back(rotate(n, scheme, Initial{smooth}));
                const Errors& e = runs.back();
                data.row({{"part", 0.0},
                          {"order", p},
                          {"smooth", smooth ? 1.0 : 0.0},
                          {"n", static_cast<double>(n)},
                          {"error_Phi", e.Phi},
                          {"error_phi", e.phi}});
                table.note(tag + "n = " + std::to_string(n) + ": L1 error Phi " + verify::format(e.Phi) + ", phi " +
                           verify::format(e.phi));
            }
            const double order_Phi = std::log2(runs[1].Phi / runs[2].Phi), order_phi = std::log2(runs[1].phi / runs[2].phi);
            table.note(tag + "orders 32 -> 64: Phi " + verify::format(std::log2(runs[0].Phi / runs[1].Phi)) + ", phi " +
                       verify::format(std::log2(runs[0].phi / runs[1].phi)));
            if (smooth) {
                table.at_least(tag + "order of Phi 64 -> 128", order_Phi, kSmoothShare * p);
                table.at_least(tag + "order of phi 64 -> 128", order_phi, kSmoothShare * p);
            } else {
                table.near(tag + "order of Phi 64 -> 128", order_Phi, p / (p + 1), kContactBand);
                table.near(tag + "order of phi 64 -> 128", order_phi, p / (p + 1), kContactBand);
            }
            double min_Phi = INFINITY, min_hat = INFINITY, max_hat = -INFINITY, mass = 0;
            for (const Errors& e : runs) {
                min_Phi = std::min(min_Phi, e.min_Phi), min_hat = std::min(min_hat, e.min_hat - e.hat_lo);
                max_hat = std::max(max_hat, e.max_hat - e.hat_hi), mass = std::max({mass, e.mass_Phi, e.mass_phi});
            }
            table.at_least(tag + "min Phi over every step", min_Phi, 0.0);
            table.at_least(tag + "min phi_hat - its initial min", min_hat, -kBoundTol);
            table.at_most(tag + "max phi_hat - its initial max", max_hat, kBoundTol);
            table.at_most(tag + "largest change of either phase's amount", mass, kMassTol);
        }
    }
    for (const Transport transport : {Transport::donor_cell, Transport::muscl}) {
        const double p = transport == Transport::donor_cell ? 1.0 : 2.0;
        const std::string tag = std::string("[B, ") + choice_name(kTransports, transport) + "] ";
        double errors[3];
        for (int q = 0; q < 3; ++q) {
            const int n = sizes[q] / 2;
            errors[q] = periodic_box(program.material, n, transport);
            data.row({{"part", 1.0},
                      {"order", p},
                      {"smooth", 1.0},
                      {"n", static_cast<double>(n)},
                      {"error_Phi", errors[q]},
                      {"error_phi", NAN}});
            table.note(tag + "n = " + std::to_string(n) + ": L1 error of Phi " + verify::format(errors[q]));
        }
        table.note(tag + "order 16 -> 32: " + verify::format(std::log2(errors[0] / errors[1])));
        table.at_least(tag + "flow solver: order of Phi 32 -> 64", std::log2(errors[1] / errors[2]), kSmoothShare * p);
    }
    const StressResult st = stress(200);
    table.note("[C] " + std::to_string(st.steps) + " random compressible steps on 24 x 24 cells (outflow <= 0.9 Phi per step)");
    table.at_most("[C, FCT] largest excursion of phi_hat beyond [0, 1]", st.worst_excess, kBoundTol);
    table.at_most("[C, FCT] largest relative change of the amount of phi in a step", st.worst_amount, kMassTol);
    table.at_least("[C] steps whose unlimited high-order update left [0, 1]", static_cast<double>(st.unlimited_outside), 1.0);
    verify::write_data(program.options, "transport_orders.dat", data);
    return table.finish();
}
