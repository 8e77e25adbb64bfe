// Verification of the kinematic rolling-drum flow (src/kinematic/kinematic_flow.hpp) on the grid of
// Sect. 4.2 (100 cells per diameter), the velocity field the tumbler-kinematic scene transports with.
//
// What is checked, and against what independent expectation:
//   - geometry: the filled area (cells in the bed) against the circular-segment formula;
//   - discrete mass balance: the divergence of the face fluxes vanishes to round-off in every bed
//     cell, and every face next to the wall, the free surface or the grid boundary carries exactly 0;
//   - the face fluxes are the model's exact face integrals (stream-function property): M h/Phi
//     against a 4000-point midpoint quadrature of u.n along the face (velocity() of the model);
//   - the velocity gradient (inertial and relative) against central differences of the velocity;
//   - solid-body rotation below the layer: u = Omega x x (Eigen's cross product), grad u_rel = 0,
//     the direction procedure reports no shear;
//   - the layer as documented: surface speed (Omega L^2/delta0) sqrt(1 - s^2/L^2) downslope,
//     thickness delta0 at the middle (from the cells where the shear rate is non-zero), the shear
//     rate across the middle of the layer against a formula derived by hand;
//   - d_s (from the relative velocity and its gradient) within the stated angles of the surface
//     normal (central half of the surface) and of the local streamline normal (|s| <= 0.8 L).
// Writes kinematic_cells.dat and kinematic_outline.dat for figures/fig7b_kinematic.gp.
//
// Run: build/verification/verify_kinematic_flow [--data DIR]   (about a second)
#include "direction/segregation_direction.hpp"
#include "harness/check_table.hpp"
#include "harness/program.hpp"
#include "harness/tolerances.hpp"
#include "kinematic/kinematic_flow.hpp"
#include "kinematic/kinematic_tables.hpp"

#include <Eigen/Geometry>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <random>

using namespace granseg;
using Eigen::Matrix3d, Eigen::Vector3d;
using granseg::verify::CheckTable;
using granseg::verify::kRoundOff;

namespace {

constexpr int kCells = 100;   // per diameter (Sect. 4.2)
constexpr double kPhi = 0.6;  // constant granular volume fraction of the kinematic scene

// Tolerances and stated bounds, each with its reason.
// Bed area of stair-stepped cells vs the exact segment: the boundary cuts ~pi D/h cells, each
// off by at most h^2/2 with errors of both signs; 1% is about a third of that worst case.
constexpr double kAreaTol = 0.01;
// Divergence of one cell: four face fluxes of size |M| cancel; each carries a relative error
// of eps from the corner difference, and 64 eps covers the sum.
constexpr double kDivergenceTol = kRoundOff;
// Midpoint quadrature of u.n over a face with N = 4000 points: where the face crosses the layer
// bottom, du/dz jumps by up to ~75 1/s (near the ends, where the layer is thin), and the face
// average errs by at most jump h/(8 N^2) = 6e-10 m/s.
constexpr int kQuadraturePoints = 4000;
constexpr double kQuadratureTol = 2e-9;  // m/s
// Central differences of u with step 1e-7 m: truncation |u'''| step^2/6 ~ 1e-9 1/s,
// round-off eps |u|/step ~ 1e-9 1/s; relative to the shear rate ~ 20 1/s.
constexpr double kGradientTol = 1e-7;  // relative to Omega L^2/delta0^2
constexpr double kFdStep = 1e-7;       // m
// Solid-body velocity vs Omega x x: a few roundings of O(Omega R).
constexpr double kSolidTol = kRoundOff;  // relative to Omega R
// The surface points sit 1e-12 m below the surface, where u differs by gamma_dot * 1e-12.
constexpr double kSurfaceSpeedTol = 1e-9;  // relative to the middle surface speed
// Stated bounds of the direction in the layer (docs/sect2.3_direction.md, section 6; the
// continuous suprema, sampled on a 400 x 400 (s, chi) grid, are 11.4 and 13.0 degrees).
constexpr double kCentralAngleBound = 12.0;     // deg, d_s vs surface normal, |s| <= L/2
constexpr double kStreamlineAngleBound = 15.0;  // deg, d_s vs streamline normal, |s| <= 0.8 L
constexpr double kMedianAngleBound = 6.0;       // deg, median over the whole layer vs surface normal

double degrees(double cosine) { return std::acos(std::min(1.0, std::fabs(cosine))) * 180 / M_PI; }

void check_geometry(CheckTable& t, const RollingDrumFlow& flow, const RollingDrumFields& f) {
    const double R = flow.radius(), d = flow.surface_distance();
    long bed = 0;
    for (std::size_t c = 0; c < f.grid.cells(); ++c) bed += f.grid.is_inside(c);
    const double cap = R * R * std::acos(d / R) - d * std::sqrt(R * R - d * d);  // the empty segment above the chord
    t.note("geometry: R = " + verify::format(R) + " m, surface at d = " + verify::format(d) +
           " m, half chord L = " + verify::format(flow.half_chord()) + " m, " + std::to_string(bed) + " bed cells");
    t.near_relative("filled area (bed cells h^2) vs pi R^2 - segment", bed * f.grid.h[0] * f.grid.h[2], M_PI * R * R - cap,
                    kAreaTol);
}

void check_discrete_fluxes(CheckTable& t, const RollingDrumFields& f) {
    const Grid& g = f.grid;
    double worst_div = 0, largest = 0;
    for (const auto axis : {0, 2})
        for (double m : f.M[axis]) largest = std::max(largest, std::fabs(m));
    long surface = 0, wall = 0, boundary_faces = 0;
    for_each_bed_cell(g, [&](const BedCell& b) {
        const int i = b.i, k = b.k;
        double div = 0;
        for (const auto axis : {0, 2}) {
            const std::size_t lower = g.face_index(axis, i, 0, k), upper = lower + g.face_stride(axis);
            div += (f.M[axis][upper] - f.M[axis][lower]) / g.h[axis];
            // Neighbours across the two faces: outside the grid, in the air, or beyond the wall.
            for (const int side : {-1, 1}) {
                const int ni = i + (axis == 0 ? side : 0), nk = k + (axis == 2 ? side : 0);
                const bool off_grid = ni < 0 || ni >= g.n[0] || nk < 0 || nk >= g.n[2];
                if (!off_grid && g.is_inside(g.index(ni, 0, nk))) continue;
                const double m = f.M[axis][side < 0 ? lower : upper];
                ++boundary_faces;
                if (m == 0.0) continue;
                (!off_grid && f.in_drum[g.index(ni, 0, nk)] ? surface : wall) += 1;
            }
        }
        worst_div = std::max(worst_div, std::fabs(div));
    });
    t.at_most("max |div M| h / max |M| over bed cells", worst_div * g.h[0] / largest, kDivergenceTol);
    t.note("  " + std::to_string(boundary_faces) + " faces between the bed and the air, the wall or the grid boundary");
    t.count("faces bed|air (free surface) with M != 0", surface, 0);
    t.count("faces bed|wall or grid boundary with M != 0", wall, 0);
}

/// Faces whose two corners carry the model's psi: M h/Phi is the exact flux through the face.
void check_face_integrals(CheckTable& t, const RollingDrumFlow& flow, const RollingDrumFields& f) {
    const Grid& g = f.grid;
    const int nx = g.n[0];
    // A corner carries the model's psi when all four cells around it are bed cells.
    const auto analytic = [&](int i, int k) {
        for (int ci = i - 1; ci <= i; ++ci)
            for (int ck = k - 1; ck <= k; ++ck)
                if (ci < 0 || ci >= nx || ck < 0 || ck >= g.n[2] || !g.is_inside(g.index(ci, 0, ck))) return false;
        return true;
    };
    double worst = 0;
    long faces = 0;
    for (int k = 0; k < g.n[2]; ++k)
        for (int i = 0; i <= nx; ++i) {  // x-faces at x_i from z_k to z_k+1
            if (!analytic(i, k) || !analytic(i, k + 1)) continue;
            const double x = g.origin[0] + i * g.h[0], z0 = g.origin[2] + k * g.h[2];
            double flux = 0;
            for (int q = 0; q < kQuadraturePoints; ++q)
                flux += flow.velocity(x, z0 + (q + 0.5) * g.h[2] / kQuadraturePoints)(0) / kQuadraturePoints;
            worst = std::max(worst, std::fabs(f.M[0][g.face_index(0, i, 0, k)] / kPhi - flux));
            ++faces;
        }
    t.note("  " + std::to_string(faces) + " x-faces with model corner values");
    t.at_most("max |M/Phi - face average of u_x| (stream function) [m/s]", worst, kQuadratureTol);
}

void check_gradient(CheckTable& t, const RollingDrumFlow& flow) {
    std::mt19937_64 rng(75);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    const double L = flow.half_chord(), d = flow.surface_distance();
    double worst = 0, worst_rel = 0;
    for (int n = 0; n < 2000; ++n) {
        // Layer points away from its ends, its bottom (the kink) and the surface (the bed's edge).
        const double s = L * (1.9 * unit(rng) - 0.95), chi = 0.02 + 0.96 * unit(rng);
        const Vector3d X = (d - chi * flow.layer_depth(s)) * flow.normal() + s * flow.tangent();
        Matrix3d fd = Matrix3d::Zero(), fd_rel = Matrix3d::Zero();
        for (const int j : {0, 2}) {
            const Vector3d e = kFdStep * Vector3d::Unit(j), a = X + e, b = X - e;
            fd.col(j) = (flow.velocity(a(0), a(2)) - flow.velocity(b(0), b(2))) / (2 * kFdStep);
            fd_rel.col(j) = (flow.relative_velocity(a(0), a(2)) - flow.relative_velocity(b(0), b(2))) / (2 * kFdStep);
        }
        worst = std::max(worst, (fd - flow.velocity_gradient(X(0), X(2))).cwiseAbs().maxCoeff());
        worst_rel = std::max(worst_rel, (fd_rel - flow.relative_velocity_gradient(X(0), X(2))).cwiseAbs().maxCoeff());
    }
    t.at_most("grad u vs central differences, 2000 layer points (rel.)", worst / flow.layer_shear_rate(), kGradientTol);
    t.at_most("grad u_rel vs central differences of u_rel (rel.)", worst_rel / flow.layer_shear_rate(), kGradientTol);
}

void check_solid_body(CheckTable& t, const RollingDrumFlow& flow, const RollingDrumFields& f) {
    const Grid& g = f.grid;
    const Vector3d omega(0, -flow.Omega(), 0);  // counter-clockwise in the x-z plane seen with y into the page
    double worst = 0;
    long sheared = 0, not_no_shear = 0, core = 0;
    for_each_bed_cell(g, [&](const BedCell& b) {
        const std::size_t c = b.c;
        if (f.in_layer[c]) return;
        ++core;
        const Vector3d x(b.x, 0, b.z);
        worst = std::max(worst, (cell_vector(f.u, c) - omega.cross(x)).norm());
        const Matrix3d grad_rel = cell_tensor(f.grad_rel, c);
        sheared += grad_rel.cwiseAbs().maxCoeff() != 0.0;
        not_no_shear += segregation_direction(grad_rel, cell_vector(f.u_rel, c)).status != DirectionStatus::no_shear;
    });
    t.note("solid-body core: " + std::to_string(core) + " bed cells below the layer");
    t.at_most("max |u - Omega x x| / (Omega R) below the layer", worst / (std::fabs(flow.Omega()) * flow.radius()), kSolidTol);
    t.count("cells below the layer with grad u_rel != 0", sheared, 0);
    t.count("cells below the layer with direction status != no_shear", not_no_shear, 0);
}

void check_layer(CheckTable& t, const RollingDrumFlow& flow, const RollingDrumFields& f) {
    const double L = flow.half_chord(), d = flow.surface_distance(), delta0 = flow.parameters().layer_thickness;
    double worst_speed = 0;
    for (int n = -19; n <= 19; ++n) {  // points just below the surface, s = -0.95 L .. 0.95 L
        const double s = n * L / 20;
        const Vector3d X = (d - 1e-12) * flow.normal() + s * flow.tangent();
        worst_speed = std::max(worst_speed, (flow.velocity(X(0), X(2)) - flow.surface_speed(s) * flow.tangent()).norm());
    }
    t.note("flowing layer: documented surface speed (Omega L^2/delta0) sqrt(1 - s^2/L^2) = " +
           verify::format(flow.surface_speed(0)) +
           " m/s at the middle, shear rate Omega L^2/delta0^2 = " + verify::format(flow.layer_shear_rate()) + " 1/s");
    t.at_most("surface velocity vs documented, |s| <= 0.95 L (rel.)", worst_speed / flow.surface_speed(0), kSurfaceSpeedTol);

    // Thickness at the middle: the deepest cell centre with non-zero shear within |s| < h.
    const Grid& g = f.grid;
    double deepest = 0;
    for_each_bed_cell(g, [&](const BedCell& b) {
        const auto [s, n] = flow.surface_coordinates(b.x, b.z);
        if (std::fabs(s) < g.h[0] && shear_rate(cell_tensor(f.grad_rel, b.c)) > 0) deepest = std::max(deepest, -n);
    });
    t.near("layer thickness at the middle (deepest sheared cell centre) [m]", deepest, delta0, std::sqrt(2.0) * g.h[0]);

    // Shear rate across the middle of the layer (s = 0), derived by hand (docs/sect2.3_direction.md,
    // section 6): kappa_max - kappa_min = 2 psi_sb/delta0^2 - 2 m' Omega (d - chi delta0)/delta0
    // + psi_sb m' chi/L^2, psi_sb = Omega (L^2 + 2 d chi delta0 - chi^2 delta0^2)/2, m' = 2 - 2 chi.
    const double Omega = std::fabs(flow.Omega());
    double worst_shear = 0;
    for (const double chi : {0.1, 0.5, 0.9}) {
        const Vector3d X = (d - chi * delta0) * flow.normal();
        const double psi_sb = Omega * (L * L + 2 * d * chi * delta0 - chi * chi * delta0 * delta0) / 2, m1 = 2 - 2 * chi;
        const double expected =
            2 * psi_sb / (delta0 * delta0) - 2 * m1 * Omega * (d - chi * delta0) / delta0 + psi_sb * m1 * chi / (L * L);
        const double measured =
            segregation_direction(flow.relative_velocity_gradient(X(0), X(2)), Vector3d::UnitX()).principal_shear;
        worst_shear = std::max(worst_shear, std::fabs(measured / expected - 1));
        if (chi == 0.5)
            t.note("  shear rate at s = 0, chi = 1/2: " + verify::format(measured) +
                   " 1/s = " + verify::format(measured / flow.layer_shear_rate()) + " Omega L^2/delta0^2");
    }
    t.at_most("shear rate at s = 0, chi = 0.1, 0.5, 0.9 vs hand formula (rel.)", worst_shear, kRoundOff);
}

/// d_s in the layer, from the relative velocity and gradient of every layer cell; writes the cell data.
void check_direction(CheckTable& t, const RollingDrumFlow& flow, const RollingDrumFields& f,
                     const verify::ProgramOptions& options) {
    const Grid& g = f.grid;
    const double L = flow.half_chord();
    std::vector<double> angles;
    double central = 0, streamline = 0;
    long not_ok = 0;
    DataTable cells;
    cells.comment(
        "bed cells of the kinematic drum (inertial frame, m and m/s); d_s signed upwards; angle: d_s vs surface normal");
    for_each_bed_cell(g, [&](const BedCell& b) {
        const std::size_t c = b.c;
        const Vector3d u = cell_vector(f.u, c), u_rel = cell_vector(f.u_rel, c);
        const SegregationDirection r = segregation_direction(cell_tensor(f.grad_rel, c), u_rel);
        const Vector3d d_s = r.d_s(2) < 0 ? Vector3d(-r.d_s) : r.d_s;
        const double angle = r.segregates() ? degrees(d_s.dot(flow.normal())) : 0.0;
        cells.row({{"x", b.x},
                   {"z", b.z},
                   {"in_layer", double(f.in_layer[c])},
                   {"ux", u(0)},
                   {"uz", u(2)},
                   {"urel_x", u_rel(0)},
                   {"urel_z", u_rel(2)},
                   {"ds_x", d_s(0)},
                   {"ds_z", d_s(2)},
                   {"speed", u.norm()},
                   {"angle_deg", angle}});
        if (!f.in_layer[c]) return;
        not_ok += r.status != DirectionStatus::ok;
        angles.push_back(angle);
        const double s = flow.surface_coordinates(b.x, b.z)[0];
        if (std::fabs(s) <= L / 2) central = std::max(central, angle);
        if (std::fabs(s) <= 0.8 * L) streamline = std::max(streamline, 90 - degrees(d_s.dot(u_rel.normalized())));
    });
    verify::write_data(options, "kinematic_cells.dat", cells);
    std::sort(angles.begin(), angles.end());
    t.note("direction in the " + std::to_string(angles.size()) + " layer cells: angle to the surface normal p50 " +
           verify::format(angles[angles.size() / 2]) + ", p90 " + verify::format(angles[angles.size() * 9 / 10]) + ", max " +
           verify::format(angles.back()) + " deg (largest at the ends of the surface, where the layer thins)");
    t.count("layer cells with direction status != ok", not_ok, 0);
    t.at_most("max angle(d_s, surface normal), |s| <= L/2 [deg]", central, kCentralAngleBound);
    t.at_most("median angle(d_s, surface normal), whole layer [deg]", angles[angles.size() / 2], kMedianAngleBound);
    t.at_most("max angle(d_s, streamline normal of u_rel), |s| <= 0.8 L [deg]", streamline, kStreamlineAngleBound);
}

}  // namespace

int main(int argc, char** argv) {
    const auto options = verify::parse_program_options(argc, argv);
    const RollingDrumFlow flow{RollingDrumParameters{}};
    const RollingDrumFields fields = discretize(flow, kCells, kPhi);
    CheckTable table("Kinematic rolling drum (Sect. 4.2 geometry, 100 cells per diameter)");
    check_geometry(table, flow, fields);
    check_discrete_fluxes(table, fields);
    check_face_integrals(table, flow, fields);
    check_gradient(table, flow);
    check_solid_body(table, flow, fields);
    check_layer(table, flow, fields);
    check_direction(table, flow, fields, options);
    verify::write_data(options, "kinematic_outline.dat", drum_outline(flow));
    return table.finish();
}
