// The reduction to Gray-Thornton (Sect. 2.2, end; the 1-D part): with constant
// Phi and T, eq. (47) is the Gray-Thornton equation for psi = phi/Phi, the modified flux
// (eq. 63) is its classic Godunov flux, and the solver converges to its exact solutions.
//
// What is checked, and against what independent expectation:
//   - interface by interface: eq. (63) with Phi_L = Phi_R against the textbook Godunov flux of
//     g(psi) = q psi (psi - 1) (min over [psi_L, psi_R] if psi_L <= psi_R, else max), written out
//     here, on 200000 random states of both signs of the coefficient; and, on every face at every
//     step of a run, the modified flux against the library's classic Godunov flux;
//   - the homogeneous two-shock batch and the normally graded batch (fan and shocks) of
//     harness/gray_thornton.hpp: L1 errors of the cell averages at 5 resolutions, fitted
//     orders against a lower bound, and the shock width against a bound in cells;
//   - the classic upwind (Murman-Roe) flux keeps the entropy-violating stationary expansion shock
//     of the graded batch: it does not converge (why the paper's Godunov-type flux matters);
//   - conservation (1e-13) and bounds (round-off) in every run.
// Writes gt_batch_profiles.dat (N = 200) and gt_convergence.dat.
//
// Run: build/verification/verify_gray_thornton [--data DIR]   (about a second)
#include "harness/check_table.hpp"
#include "harness/gray_thornton.hpp"
#include "harness/program.hpp"
#include "harness/segregation_run.hpp"
#include "riemann/segregation_flux.hpp"
#include "segregation/face_fluxes.hpp"
#include "segregation/invariants.hpp"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <functional>
#include <random>

using namespace granseg;
using namespace granseg::verify;

namespace {

// Tolerances and bounds, each with its reason.
// Flux identity: both sides evaluate the same quadratic at the same point, at most a few
// roundings apart: 8 DBL_EPSILON of the largest flux value |a| Phi/4.
constexpr double kFluxTolerance = 8 * DBL_EPSILON;
// First-order monotone schemes resolve a shock of a convex flux in O(1) cells: L1 error = O(h).
// Fitted order over N = 100 .. 1600 must be >= 0.85 (a margin for the fit's finite range of N).
constexpr double kShockOrder = 0.85;
// Shock width: L1 error / (h * sum of the jumps) is the number of cells the shocks are smeared
// over; a monotone scheme keeps it within a cell.
constexpr double kShockCells = 1.0;
// Fan plus shocks, first order: the centred fan costs a log factor, O(h log h): fitted >= 0.75,
// below 1 by what the log factor takes over N = 100 .. 1600.
constexpr double kFanOrderFirst = 0.75;
// Second order with the MC limiter: the fan converges at order ~2, the shocks at 1, the corners
// of the fan clip: fitted >= 1.0 over N = 200 .. 3200 (the shocks' order bounds it from below).
constexpr double kFanOrderSecond = 1.0;
// The upwind flux leaves the expansion shock standing: its L1 error stays near the area of the
// missing fan, 0.3; >= 0.1 at every N says it does not converge.
constexpr double kUpwindStuck = 0.1;
constexpr double kMassTolerance = 1e-13;  // as in verify_overshoot

constexpr double kPhi = 0.6;  // constant granular volume fraction (any value in (0, 1) reduces)

/// The textbook Godunov flux of g(psi) = q psi (psi - 1), independent of the library: the
/// minimum of g over [psi_L, psi_R] if psi_L <= psi_R, else the maximum over [psi_R, psi_L].
double godunov_gray_thornton(double psi_L, double psi_R, double q) {
    const auto g = [q](double p) { return q * p * (p - 1.0); };
    if (psi_L <= psi_R) return q >= 0.0 ? g(std::clamp(0.5, psi_L, psi_R)) : std::min(g(psi_L), g(psi_R));
    return q >= 0.0 ? std::max(g(psi_L), g(psi_R)) : g(std::clamp(0.5, psi_R, psi_L));
}

void check_flux_identity(CheckTable& t) {
    std::mt19937_64 random(20200245);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    double worst = 0.0;
    for (int i = 0; i < 200000; ++i) {
        const double Phi = 0.001 + 0.998 * unit(random), q = (unit(random) - 0.5) * 4.0;
        // Half of the states on the grid psi in {0, 1/4, 1/2, 3/4, 1}, where the cases switch.
        const double psi_L = i % 2 ? unit(random) : std::floor(5 * unit(random)) / 4;
        const double psi_R = i % 2 ? unit(random) : std::floor(5 * unit(random)) / 4;
        const double expected = Phi * godunov_gray_thornton(psi_L, psi_R, q);  // phi = Phi psi
        const double modified = modified_godunov_flux({{Phi * psi_L, Phi, q}, {Phi * psi_R, Phi, q}});
        worst = std::max(worst, std::fabs(modified - expected) / (std::fabs(q) * Phi / 4 + 1e-300));
    }
    t.at_most("eq. (63), const Phi: vs Godunov of Gray-Thornton (rel.)", worst, kFluxTolerance);
}

/// A batch problem: exact psi at time t (t = 0 is the initial state), final time, and the sum of
/// the jumps of psi at t_end (for the shock width).
struct Problem {
    std::string name;
    std::function<PiecewiseLinear(double t)> exact;
    double t_end, jumps;
    std::vector<int> cells;
};

/// Exact cell averages of phi = Phi psi at time t.
std::vector<double> averages(const Problem& p, double t, int N) {
    std::vector<double> avg = cell_averages(p.exact(t), N);
    for (double& v : avg) v *= kPhi;
    return avg;
}

Problem two_shock_problem() {
    return {"two-shock batch (psi0 = 0.4, t = 0.6)",
            [](double t) { return homogeneous_batch(0.4, 1.0, t); },
            0.6,
            1.0,
            {100, 200, 400, 800, 1600}};
}

Problem graded_problem() {
    const auto exact = [](double t) {
        if (t == 0.0) return PiecewiseLinear{[](double z) { return z < 0.6 ? 0.0 : 1.0; }, {0.6}};
        return graded_batch(0.6, 1.0, t);
    };
    return {"graded batch (small on top, z0 = 0.6, t = 1)", exact, 1.0, 1.0, {200, 400, 800, 1600, 3200}};
}

const std::vector<SegregationScheme> kSchemes = {SegregationScheme::modified_godunov, SegregationScheme::modified_godunov_2,
                                                 SegregationScheme::classic_godunov, SegregationScheme::classic_upwind};

void check_convergence(CheckTable& t, const ProgramOptions& options, double& mass, double& bounds) {
    ColumnSetup setup;
    setup.S = 1.0;
    setup.Phi = [](double) { return kPhi; };
    setup.T = [](double) { return 1.0; };  // q = S sqrt(T) = 1
    DataTable table;
    table.comment("problem 0: two-shock batch, 1: graded batch; L1 errors of phi (Phi = 0.6, q = 1)");
    DataTable profiles;
    profiles.comment("N = 200; block 0: two-shock batch at t = 0.6, block 1: graded batch at t = 1");
    int which = 0;
    for (const Problem& p : {two_shock_problem(), graded_problem()}) {
        std::vector<std::vector<double>> errors(kSchemes.size());
        t.note(p.name + ": L1 error of phi against the exact cell averages");
        t.note("      N   modified-godunov  modified-godunov-2  classic-godunov  classic-upwind");
        for (int N : p.cells) {
            setup.cells = N;
            const Column column = make_column(setup);
            const std::vector<double> phi0 = averages(p, 0.0, N), exact = averages(p, p.t_end, N);
            TableRow row{{"problem", static_cast<double>(which)}, {"N", static_cast<double>(N)}};
            std::vector<std::vector<double>> finals;
            char line[200];
            std::snprintf(line, sizeof line, "%7d", N);
            std::string text = line;
            for (std::size_t s = 0; s < kSchemes.size(); ++s) {
                const ColumnRun run = run_column(column, phi0, scheme_options(kSchemes[s]), p.t_end);
                const double e = l1_distance(run.phi, exact, 1.0 / N);
                errors[s].push_back(e);
                row.add(scheme_column(kSchemes[s]), e);
                finals.push_back(run.phi);
                mass = std::max(mass, run.mass_drift);
                if (preserves_bounds(kSchemes[s])) bounds = std::max({bounds, run.max_excess, -run.min_phi, run.correction});
                std::snprintf(line, sizeof line, "  %16.4e", e);
                text += line;
            }
            t.note(text);
            table.row(row);
            if (N != 200) continue;
            for (int k = 0; k < N; ++k) {
                TableRow cells{{"z", column.z[k]}, {"exact", exact[k]}};
                for (std::size_t s = 0; s < kSchemes.size(); ++s) cells.add(scheme_column(kSchemes[s]), finals[s][k]);
                profiles.row(cells);
            }
            profiles.blank();
            profiles.blank();
        }
        for (std::size_t s = 0; s < 2; ++s) {
            const std::string name = "  " + scheme_name(kSchemes[s]);
            const double order = fitted_order(p.cells, errors[s]);
            if (which == 0) {
                t.at_least(name + ": fitted order", order, kShockOrder);
                t.at_most(name + ": shock width in cells, finest N", errors[s].back() * p.cells.back() / (kPhi * p.jumps),
                          kShockCells);
            } else {
                t.at_least(name + ": fitted order", order, s == 0 ? kFanOrderFirst : kFanOrderSecond);
            }
        }
        double same = 0.0;
        for (std::size_t i = 0; i < p.cells.size(); ++i) same = std::max(same, std::fabs(errors[2][i] - errors[0][i]));
        t.at_most("  classic-godunov vs modified-godunov: max |L1 difference|", same, kFluxTolerance);
        if (which == 1)
            t.at_least("  classic-upwind: min L1 error over N (stuck expansion shock)",
                       *std::min_element(errors[3].begin(), errors[3].end()), kUpwindStuck);
        ++which;
    }
    write_data(options, "gt_convergence.dat", table);
    write_data(options, "gt_batch_profiles.dat", profiles);
}

/// Every face, every step of a two-shock run: eq. (63) against the library's classic Godunov flux.
void check_faces_during_run(CheckTable& t) {
    ColumnSetup setup;
    setup.cells = 400;
    setup.Phi = [](double) { return kPhi; };
    setup.T = [](double) { return 1.0; };
    const Column column = make_column(setup);
    std::vector<double> phi = averages(two_shock_problem(), 0.0, setup.cells);
    SegregationSolver solver(column.grid, scheme_options(SegregationScheme::modified_godunov));
    std::vector<double> F_modified, F_classic;
    double worst = 0.0;
    long faces = 0;
    solver.advance(column.fields, 0.6, phi, [&](double, double) {
        segregation_face_fluxes(column.grid, 2, column.fields, SegregationScheme::modified_godunov, phi, phi, phi, F_modified);
        segregation_face_fluxes(column.grid, 2, column.fields, SegregationScheme::classic_godunov, phi, phi, phi, F_classic);
        for (std::size_t f = 0; f < F_modified.size(); ++f) worst = std::max(worst, std::fabs(F_modified[f] - F_classic[f]));
        faces += static_cast<long>(F_modified.size());
    });
    t.at_most("every face and step (" + std::to_string(faces) + "): |F_modified - F_classic|", worst, kFluxTolerance * kPhi / 4);
}

/// The split step treats every axis alike: the two-shock batch laid along x, y or z of a grid
/// (the other two axes one cell wide) must give the same profile to the last bit.
void check_axes_alike(CheckTable& t) {
    const int N = 200;
    const std::vector<double> phi0 = averages(two_shock_problem(), 0.0, N);
    std::vector<std::vector<double>> results;
    for (int axis = 0; axis < 3; ++axis) {
        Grid grid;
        grid.n[axis] = N;
        grid.h[axis] = 1.0 / N;
        FrozenFields fields;
        fields.Phi.assign(N, kPhi);
        fields.a[axis].assign(N, 1.0);
        for (SegregationScheme scheme : {SegregationScheme::modified_godunov, SegregationScheme::modified_godunov_2}) {
            SegregationSolver solver(grid, scheme_options(scheme));
            std::vector<double> phi = phi0;
            solver.advance(fields, 0.6, phi);
            results.push_back(phi);
        }
    }
    double worst = 0.0;
    for (std::size_t r = 2; r < results.size(); ++r)
        for (int k = 0; k < N; ++k) worst = std::max(worst, std::fabs(results[r][k] - results[r % 2][k]));
    t.at_most("batch along x, y, z (both orders): max |difference|", worst, 0.0);
}

}  // namespace

int main(int argc, char** argv) {
    const ProgramOptions options = parse_program_options(argc, argv);
    CheckTable t("Reduction to Gray-Thornton: constant Phi and T (Sect. 2.2, eq. 63)");
    check_flux_identity(t);
    check_faces_during_run(t);
    check_axes_alike(t);
    double mass = 0.0, bounds = 0.0;
    check_convergence(t, options, mass, bounds);
    t.at_most("every run: max relative change of sum(phi)", mass, kMassTolerance);
    t.at_most("every run, modified: bound violation incl. round-off clip", bounds, kBoundRoundOff * kPhi);
    return t.finish();
}
