// Stress test of the bound-preserving segregation schemes: it tries to break
// 0 <= phi <= Phi, conservation and finiteness with hostile but valid input.
//
// 1-D columns (eq. 66 with optional remixing), modified-godunov and modified-godunov-2:
//   random Phi(z): smooth, piecewise constant with sharp jumps, or cell-by-cell alternating, with
//   values down to 1e-3; random T(z) >= 0, zero on random intervals and with jumps; random S and
//   D; random initial phi in [0, Phi] (noise, blocks of empty and full cells, uniform); CFL up to
//   1.0 (a quarter of the runs exactly 1); long runs (up to 40 segregation times).
// 2-D grids in the x-z plane with a circular wall (the kinematic drum of Sect. 4.2): the coupled step of the
// project (bulk transport with the flow's face mass fluxes, then segregation with Phi frozen)
// with coefficients a_x, a_z of random sign that change sign between cells, and either a
// divergence-free rotation from a stream function (constant Phi) or random compressible mass
// fluxes (Phi changes every step; phi follows through phi_hat).
// Checked over every run: no non-finite value, no violation of the bounds beyond round-off
// (exact violations are counted too), conservation of the sum of phi to 1e-13 (closed domains).
// Prints how many runs and cell updates it tried. The classic schemes are not stressed here:
// they break the bounds by design (verify_overshoot).
//
// Run: build/verification/verify_segregation_stress [--data DIR]   (15-25 s)
#include "flow/faces/convection.hpp"
#include "harness/check_table.hpp"
#include "harness/program.hpp"
#include "harness/segregation_run.hpp"
#include "segregation/bulk_transport.hpp"
#include "segregation/invariants.hpp"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <functional>
#include <random>

using namespace granseg;
using namespace granseg::verify;

namespace {

// Tolerances, each with its reason.
// Bounds: one update rounds a few times; kBoundRoundOff (8 DBL_EPSILON) of the largest Phi.
constexpr double kBoundTolerance = kBoundRoundOff;
// Conservation of the sum of phi (closed domains) can only be broken by round-off: each cell
// update (eq. 64, (u + g_low) - g_up) rounds twice, each time by at most DBL_EPSILON/2 of a value
// below 1.25 Phi_max. So |change| <= kUpdateRoundOff * Phi_max * (cell updates) is a rigorous
// bound; a leak (a lost or doubled flux) is many orders of magnitude larger. The shorter runs of
// the other verification programs stay below 1e-13 relative; long runs here add up more rounding.
constexpr double kUpdateRoundOff = 2 * DBL_EPSILON;

// Most columns start away from a steady state, so phi must change in most runs (the
// program prints the share; the rest start all empty, or with full cells below empty ones, or behind T = 0): a solver
// that does nothing would pass every other check here, and changes nothing in any run.
constexpr double kMovedShare = 0.9;

constexpr unsigned kSeed = 20200245;  // fixed: the same runs every time
constexpr int kColumnRuns = 2000, kDrumRuns = 240;

using Profile = std::function<double(double)>;

struct Tally {
    long runs = 0, nonfinite = 0, exact_violations = 0, beyond_round_off = 0, mass_beyond_round_off = 0, moved = 0;
    long long updates = 0;
    double worst_correction = 0.0, worst_mass = 0.0;
    /// Records the change of the sum of phi over a run against its round-off bound.
    void mass(double before, double after, double Phi_max, long long run_updates) {
        worst_mass = std::max(worst_mass, std::fabs(after - before) / before);
        if (!(std::fabs(after - before) <= kUpdateRoundOff * Phi_max * static_cast<double>(run_updates))) ++mass_beyond_round_off;
    }
    /// violation: max(-phi, phi - Phi) over a run, as the solver left phi; correction: the
    /// largest clip its round-off guard made (what the scheme itself produced before the clip).
    void bounds(double violation, double correction, double Phi_max) {
        if (violation > 0.0) ++exact_violations;
        worst_correction = std::max(worst_correction, correction / Phi_max);
        if (correction > kBoundTolerance * Phi_max) ++beyond_round_off;
    }
};

class Random {
public:
    double uniform(double a, double b) { return std::uniform_real_distribution<double>(a, b)(engine_); }
    int integer(int a, int b) { return std::uniform_int_distribution<int>(a, b)(engine_); }
    double log_uniform(double a, double b) { return std::exp(uniform(std::log(a), std::log(b))); }
    bool chance(double p) { return uniform(0.0, 1.0) < p; }

    /// A smooth profile with values in [lo, hi]: a random sum of sines, rescaled.
    Profile smooth(double lo, double hi) {
        std::vector<double> c, p;
        double total = 0.0;
        for (int k = 1; k <= 4; ++k) {
            c.push_back(uniform(-1.0, 1.0) / k);
            p.push_back(uniform(0.0, 2 * M_PI));
            total += std::fabs(c.back());
        }
        return [=](double z) {
            double s = 0.0;
            for (int k = 1; k <= 4; ++k) s += c[k - 1] * std::sin(2 * M_PI * k * z + p[k - 1]);
            return lo + (hi - lo) * std::clamp(0.5 + 0.5 * s / total, 0.0, 1.0);
        };
    }
    /// Piecewise constant with `jumps` random jumps, values log-uniform in [lo, hi].
    Profile steps(double lo, double hi, int jumps) {
        std::vector<double> at, value = {log_uniform(lo, hi)};
        for (int j = 0; j < jumps; ++j) at.push_back(uniform(0.0, 1.0)), value.push_back(log_uniform(lo, hi));
        std::sort(at.begin(), at.end());
        return [=](double z) { return value[std::upper_bound(at.begin(), at.end(), z) - at.begin()]; };
    }

private:
    std::mt19937_64 engine_{kSeed};
};

Profile random_Phi(Random& r, int cells) {
    const double lo = r.log_uniform(1e-3, 0.3), hi = r.uniform(lo, 0.99);
    switch (r.integer(0, 3)) {
        case 0:
            return r.smooth(lo, hi);
        case 1:
            return r.steps(lo, hi, r.integer(1, 12));
        case 2: {  // alternating from cell to cell: the sharpest jumps a grid can hold
            const int n = cells;
            return [=](double z) { return static_cast<int>(z * n) % 2 ? 1e-3 : 0.99; };
        }
        default: {  // smooth with jumps
            const Profile a = r.smooth(lo, hi), b = r.steps(lo, hi, r.integer(1, 5));
            return [=](double z) { return std::min(0.99, 0.5 * (a(z) + b(z))); };
        }
    }
}

Profile random_T(Random& r) {
    const Profile base = r.chance(0.5) ? r.smooth(0.0, r.uniform(0.1, 4.0)) : r.steps(1e-4, 4.0, r.integer(1, 8));
    std::vector<std::pair<double, double>> zero;  // T = 0 on these intervals
    for (int k = r.integer(0, 3); k > 0; --k) {
        const double a = r.uniform(0.0, 1.0);
        zero.push_back({a, a + r.uniform(0.01, 0.3)});
    }
    return [=](double z) {
        for (const auto& [a, b] : zero)
            if (z >= a && z <= b) return 0.0;
        return base(z);
    };
}

std::vector<double> random_phi(Random& r, const std::vector<double>& Phi) {
    std::vector<double> phi(Phi.size());
    const int kind = r.integer(0, 2);
    const double constant = r.uniform(0.0, 1.0);
    int block = 0;
    bool full = r.chance(0.5);
    for (std::size_t i = 0; i < Phi.size(); ++i) {
        double fraction = constant;
        if (kind == 0) fraction = r.chance(0.1) ? (r.chance(0.5) ? 0.0 : 1.0) : r.uniform(0.0, 1.0);
        if (kind == 1) {
            if (--block < 0) block = r.integer(1, 20), full = !full;
            fraction = full ? 1.0 : 0.0;
        }
        phi[i] = fraction * Phi[i];  // <= Phi exactly: rounding is monotone
    }
    return phi;
}

void stress_columns(Random& r, Tally& tally) {
    for (int run = 0; run < kColumnRuns; ++run) {
        ColumnSetup setup;
        setup.cells = r.integer(8, 160);
        setup.S = r.log_uniform(0.1, 5.0);
        setup.D = r.chance(0.2) ? r.log_uniform(1e-4, 0.05) : 0.0;
        setup.Phi = random_Phi(r, setup.cells);
        setup.T = random_T(r);
        const Column column = make_column(setup);
        const double cfl = r.chance(0.25) ? 1.0 : r.uniform(0.3, 1.0);
        const SegregationScheme scheme = run % 2 ? SegregationScheme::modified_godunov_2 : SegregationScheme::modified_godunov;
        const double a_max = *std::max_element(column.fields.a[2].begin(), column.fields.a[2].end());
        const double t_end = r.uniform(0.5, r.chance(0.1) ? 40.0 : 8.0) / std::max(a_max, 1e-3);
        const std::vector<double> phi0 = random_phi(r, column.fields.Phi);
        const ColumnRun result = run_column(column, phi0, scheme_options(scheme, cfl), t_end);
        const double Phi_max = *std::max_element(column.fields.Phi.begin(), column.fields.Phi.end());
        tally.bounds(std::max(result.max_excess, -result.min_phi), result.correction, Phi_max);
        tally.nonfinite += result.nonfinite;
        tally.mass(total_amount(column.grid, phi0), total_amount(column.grid, result.phi), Phi_max, result.updates);
        tally.moved += result.phi != phi0;  // segregation happened (a solver doing nothing keeps every bound)
        tally.updates += result.updates;
        ++tally.runs;
    }
}

/// Random face mass fluxes on the open faces (M = 0 on walls), magnitude up to `scale`.
FaceFields random_mass_fluxes(Random& r, const Grid& grid, double scale) {
    FaceFields M;
    for (int axis : {0, 2}) {
        M[axis].assign(grid.faces(axis), 0.0);
        for_each_face(grid, axis, [&](const FaceCells& f) {
            if (is_open_face(grid, f)) M[axis][f.face] = scale * r.uniform(-1.0, 1.0);
        });
    }
    return M;
}

void stress_drums(Random& r, Tally& tally) {
    for (int run = 0; run < kDrumRuns; ++run) {
        const int n = r.integer(12, 40);
        Grid grid = Grid::plane_xz(n, n, -1.1, -1.1, 2.2, 2.2);  // the edge cells lie outside the drum
        grid.inside.assign(grid.cells(), 0);
        for (int k = 0; k < n; ++k)
            for (int i = 0; i < n; ++i)
                grid.inside[grid.index(i, 0, k)] = std::hypot(grid.center(0, i), grid.center(2, k)) < 0.95;
        const bool rotation = run % 2 == 0;  // else random compressible mass fluxes
        std::vector<double> Phi(grid.cells(), 0.0);
        const Profile Phi_profile = r.smooth(r.log_uniform(1e-3, 0.3), 0.9);
        const double Phi_const = r.uniform(1e-3, 0.9);
        for (std::size_t c = 0; c < Phi.size(); ++c)
            if (grid.is_inside(c)) Phi[c] = rotation ? Phi_const : Phi_profile(r.uniform(0.0, 1.0));
        FrozenFields fields;
        for (int axis : {0, 2}) {  // a_k of random sign, changing sign between neighbouring cells
            fields.a[axis].resize(grid.cells());
            const double wave = r.uniform(1.0, 12.0), phase = r.uniform(0.0, 2 * M_PI), noise = r.uniform(0.0, 1.0);
            for (int k = 0; k < n; ++k)
                for (int i = 0; i < n; ++i)
                    fields.a[axis][grid.index(i, 0, k)] =
                        std::sin(wave * (grid.center(0, i) + 0.7 * grid.center(2, k)) + phase) + noise * r.uniform(-1, 1);
        }
        const double Omega = r.uniform(0.5, 3.0);
        const FaceFields rotation_M =
            stream_function_mass_fluxes(grid, [&](double x, double z) { return 0.5 * Phi_const * Omega * (x * x + z * z); });
        const double cfl = r.chance(0.25) ? 1.0 : r.uniform(0.3, 1.0);
        SegregationSolver solver(
            grid, scheme_options(run % 4 < 2 ? SegregationScheme::modified_godunov : SegregationScheme::modified_godunov_2, cfl));
        std::vector<double> phi = random_phi(r, Phi);
        const double mass0 = total_amount(grid, phi);
        double violation = 0.0;
        long long bulk_updates = 0;
        const FlowMesh mesh(grid);  // the mass balance's cell rows, built once for every step
        BulkTransport bulk(grid);
        const int steps = r.integer(100, 400);
        for (int s = 0; s < steps; ++s) {
            const FaceFields M = rotation ? rotation_M : random_mass_fluxes(r, grid, 0.05);
            // dt: the bulk outflow condition, the segregation CFL, and Phi_new <= 0.99.
            double dt = std::min(bulk_time_step(grid, Phi, M, cfl), 0.5);
            std::vector<double> Phi_new;
            for (dt *= 2.0; Phi_new.empty() || *std::max_element(Phi_new.begin(), Phi_new.end()) > 0.99;) {
                dt *= 0.5;
                Phi_new = Phi;
                apply_mass_fluxes(mesh, M, dt, Phi_new);
            }
            bulk.step(Phi, refs(M), FaceFields{}, dt, phi);
            fields.Phi = Phi_new;
            for (std::size_t c = 0; c < Phi_new.size(); ++c) fields.Phi[c] = std::max(0.0, Phi_new[c]);
            double left = dt;  // segregation sub-steps within the bulk step, each within its CFL
            while (left > 0.0) {
                const double h = std::min(left, solver.time_step(fields));
                solver.step(fields, h, phi);
                left = h == left ? 0.0 : left - h;
            }
            Phi = fields.Phi;
            for (std::size_t c = 0; c < phi.size(); ++c) {
                if (!std::isfinite(phi[c])) ++tally.nonfinite;
                violation = std::max({violation, -phi[c], phi[c] - Phi[c]});
            }
            bulk_updates += static_cast<long long>(n) * n;
        }
        tally.bounds(violation, solver.largest_correction(), 0.99);
        tally.mass(mass0, total_amount(grid, phi), 0.99, bulk_updates + solver.cell_updates());
        tally.updates += bulk_updates + solver.cell_updates();
        ++tally.runs;
    }
}

}  // namespace

int main(int argc, char** argv) {
    (void)parse_program_options(argc, argv);
    CheckTable t("Stress: random Phi (down to 1e-3, jumps), T (zero intervals), phi, CFL up to 1, 1-D and drums");
    Tally columns, drums;
    Random random;
    stress_columns(random, columns);
    stress_drums(random, drums);
    for (const auto& [name, tally] : {std::pair<std::string, const Tally&>{"1-D columns", columns}, {"2-D drums", drums}}) {
        t.note(name + ": " + std::to_string(tally.runs) + " runs, " + std::to_string(tally.updates) +
               " cell updates; largest round-off clip " + format(tally.worst_correction) +
               " of Phi_max; largest relative change of sum(phi) " + format(tally.worst_mass));
        t.count(name + ": non-finite values", tally.nonfinite, 0);
        t.count(name + ": runs with phi < 0 or phi > Phi (any size)", tally.exact_violations, 0);
        t.count(name + ": runs whose scheme left [0, Phi] beyond round-off", tally.beyond_round_off, 0);
        t.count(name + ": runs with |change of sum(phi)| above round-off", tally.mass_beyond_round_off, 0);
    }
    t.at_least("1-D columns: share of runs in which phi changed", static_cast<double>(columns.moved) / columns.runs, kMovedShare);
    t.note("tried " + std::to_string(columns.runs + drums.runs) + " runs and " + std::to_string(columns.updates + drums.updates) +
           " cell updates (seed " + std::to_string(kSeed) + ")");
    return t.finish();
}
