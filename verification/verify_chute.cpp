// The steady inclined chute (the 2-D part of the Gray-Thornton reduction): eq. (47) in the x-z plane with a
// sheared bulk velocity u(z) along x, solved with the coupling of the project (bulk transport of
// phi with the face mass fluxes of a stream function, then the segregation sub-step along z,
// eq. 52b) and compared with the exact solution of Gray & Thornton (2005).
//
// Set-up: [0, L] x [0, 1], L = 0.8; Phi = 0.6, T = 1, S = 1 (so a_z = 1, no segregation along x);
// u(z) = alpha + 2 (1 - alpha) z with alpha = 0.5 (depth-averaged velocity 1); inflow at x = 0
// with the homogeneous composition psi0 = 0.5, outflow at x = L, zero flux at the base and the
// free surface. Steady state, by marching to t = 4 (5 transit times of the slowest layer).
// Exact solution: with the stream function s(z) = int_0^z u = alpha z + (1 - alpha) z^2,
// u d_x psi - d_z(psi (1 - psi)) = 0 becomes d_x psi - d_s(psi (1 - psi)) = 0: the batch
// problem with t -> x and z -> s, so psi(x, z) = homogeneous_batch(psi0, 1, x)(s(z)).
// Checked: L1 error of phi at 4 resolutions and its fitted order; bounds; the steady budget of
// small particles (inflow = outflow); Phi unchanged by its own mass fluxes (divergence-free).
// Writes chute_phi.dat (N = 64) for inspection.
//
// Run: build/verification/verify_chute [--data DIR]   (a few seconds)
#include "flow/faces/convection.hpp"
#include "harness/check_table.hpp"
#include "harness/gray_thornton.hpp"
#include "harness/program.hpp"
#include "harness/segregation_run.hpp"
#include "segregation/bulk_transport.hpp"
#include "segregation/invariants.hpp"
#include "segregation/segregation_solver.hpp"

#include <algorithm>
#include <cfloat>
#include <cmath>

using namespace granseg;
using namespace granseg::verify;

namespace {

// Tolerances and bounds, each with its reason.
// First-order donor cell and Godunov on a 2-D steady problem with two curved shocks: L1 error
// O(h); fitted order over N = 16 .. 128 >= 0.8 (a margin for the curved shocks' grid effects).
constexpr double kChuteOrder = 0.8;
// Steady budget: at the steady state of the split scheme (equal steps), the small-particle
// outflow equals the inflow; after 5 transit times the transient has decayed to round-off; 1e-10
// relative leaves room and still catches a leak or an unsteady state.
constexpr double kBudgetTolerance = 1e-10;
// Divergence-free mass fluxes from corner values of a stream function: Phi changes by round-off
// of the differences of corner values only; 16 DBL_EPSILON of Phi.
constexpr double kDivergenceTolerance = 16 * DBL_EPSILON;

constexpr double kLength = 0.8, kPhi = 0.6, kAlpha = 0.5, kPsi0 = 0.5, kEnd = 4.0;

double stream(double z) { return kAlpha * z + (1.0 - kAlpha) * z * z; }
/// z with stream(z) = s (the positive root of (1 - alpha) z^2 + alpha z - s = 0).
double stream_inverse(double s) {
    return (-kAlpha + std::sqrt(kAlpha * kAlpha + 4.0 * (1.0 - kAlpha) * s)) / (2.0 * (1.0 - kAlpha));
}

/// Exact average of psi over [x0, x1] x [z0, z1]: exact in z (psi is piecewise constant in z at
/// fixed x, with jumps at z = stream_inverse(shock)), 4-point Gauss-Legendre in x on pieces split
/// where a shock crosses z0 or z1 (so each piece is smooth).
double exact_cell_average(double x0, double x1, double z0, double z1) {
    const auto column_integral = [&](double x) {
        const PiecewiseLinear p = homogeneous_batch(kPsi0, 1.0, x);
        double sum = 0.0;
        std::vector<double> cuts = {z0, z1};
        for (double s : p.breaks) {
            const double z = stream_inverse(std::clamp(s, 0.0, 1.0));
            if (z > z0 && z < z1) cuts.push_back(z);
        }
        std::sort(cuts.begin(), cuts.end());
        for (std::size_t i = 0; i + 1 < cuts.size(); ++i)
            sum += (cuts[i + 1] - cuts[i]) * p.value(stream(0.5 * (cuts[i] + cuts[i + 1])));
        return sum;
    };
    std::vector<double> xs = {x0, x1};
    for (double z : {z0, z1}) {
        for (double x : {stream(z) / kPsi0, (1.0 - stream(z)) / (1.0 - kPsi0)})  // lower, upper shock at z
            if (x > x0 && x < x1) xs.push_back(x);
    }
    std::sort(xs.begin(), xs.end());
    double integral = 0.0;
    for (std::size_t i = 0; i + 1 < xs.size(); ++i) integral += gauss_legendre4(column_integral, xs[i], xs[i + 1]);
    return integral / ((x1 - x0) * (z1 - z0));
}

struct ChuteResult {
    double l1 = 0.0, bound = 0.0, budget = 0.0, divergence = 0.0;
    std::vector<double> phi;
};

ChuteResult run_chute(int N) {
    const Grid grid = Grid::plane_xz(N, N, 0.0, 0.0, kLength, 1.0);
    const std::vector<double> Phi(grid.cells(), kPhi);
    const FaceFields M = stream_function_mass_fluxes(grid, [](double, double z) { return kPhi * stream(z); });
    FaceFields inflow;
    inflow[0].assign(grid.faces(0), kPsi0);  // read only on the inflow faces at x = 0
    FrozenFields fields;
    fields.Phi = Phi;
    fields.a[2].assign(grid.cells(), 1.0);  // a_z = S sqrt(T) = 1; nothing along x
    SegregationSolver segregation(grid, scheme_options(SegregationScheme::modified_godunov));
    // A whole number of equal steps: the steady state of the split scheme depends on dt, so a
    // shortened last step would move the state off it.
    const double dt_max = std::min(bulk_time_step(grid, Phi, M, 0.9), segregation.time_step(fields));
    const long steps = static_cast<long>(std::ceil(kEnd / dt_max));
    const double dt = kEnd / steps;

    ChuteResult r;
    std::vector<double> phi(grid.cells(), kPsi0 * kPhi), Phi_check = Phi;
    apply_mass_fluxes(grid, M, dt, Phi_check);
    for (std::size_t c = 0; c < Phi.size(); ++c) r.divergence = std::max(r.divergence, std::fabs(Phi_check[c] - kPhi));
    for (long n = 0; n < steps; ++n) {
        transport_bulk(grid, Phi, M, inflow, dt, phi);  // bulk first (Lie splitting) ...
        segregation.step(fields, dt, phi);              // ... then segregation with Phi frozen (eq. 52b)
        r.bound = std::max(r.bound, bound_violation(phi, Phi));
    }
    // Small particles in through x = 0 and out through x = L (mass flux times donor phi_hat).
    double in = 0.0, out = 0.0;
    for (int k = 0; k < N; ++k) {
        in += M[0][grid.face_index(0, 0, 0, k)] * kPsi0;
        out += M[0][grid.face_index(0, N, 0, k)] * phi[grid.index(N - 1, 0, k)] / kPhi;
    }
    r.budget = std::fabs(out - in) / in;
    const double hx = kLength / N, hz = 1.0 / N;
    for (int k = 0; k < N; ++k)
        for (int i = 0; i < N; ++i) {
            const double exact = kPhi * exact_cell_average(i * hx, (i + 1) * hx, k * hz, (k + 1) * hz);
            r.l1 += std::fabs(phi[grid.index(i, 0, k)] - exact) * hx * hz;
        }
    r.phi = phi;
    return r;
}

}  // namespace

int main(int argc, char** argv) {
    const ProgramOptions options = parse_program_options(argc, argv);
    CheckTable t("Steady chute with sheared u(z): Gray-Thornton through the stream function (2-D, eq. 65)");
    const std::vector<int> cells = {16, 32, 64, 128};
    std::vector<double> errors;
    double bound = 0.0, budget = 0.0, divergence = 0.0;
    t.note("      N x N    L1 error of phi   steady budget |out - in|/in");
    for (int N : cells) {
        const ChuteResult r = run_chute(N);
        errors.push_back(r.l1);
        bound = std::max(bound, r.bound);
        budget = std::max(budget, r.budget);
        divergence = std::max(divergence, r.divergence);
        char line[120];
        std::snprintf(line, sizeof line, "%5d x %-5d  %14.4e  %14.3e", N, N, r.l1, r.budget);
        t.note(line);
        if (N != 64) continue;
        DataTable table;
        const Grid grid = Grid::plane_xz(N, N, 0.0, 0.0, kLength, 1.0);
        for (int i = 0; i < N; ++i) {
            for (int k = 0; k < N; ++k) {
                const double x0 = i * kLength / N, z0 = k * 1.0 / N;
                table.row({{"x", grid.center(0, i)},
                           {"z", grid.center(2, k)},
                           {"phi", r.phi[grid.index(i, 0, k)]},
                           {"exact", kPhi * exact_cell_average(x0, x0 + kLength / N, z0, z0 + 1.0 / N)}});
            }
            table.blank();
        }
        write_data(options, "chute_phi.dat", table);
    }
    t.at_least("L1 error: fitted order over N = 16 .. 128", fitted_order(cells, errors), kChuteOrder);
    t.at_most("max bound violation (0 <= phi <= Phi), every step", bound, kBoundRoundOff * kPhi);
    t.at_most("steady budget of small particles |out - in|/in", budget, kBudgetTolerance);
    t.at_most("Phi change under its own mass fluxes (divergence)", divergence, kDivergenceTolerance * kPhi);
    return t.finish();
}
