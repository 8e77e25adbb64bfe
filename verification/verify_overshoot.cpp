// Sect. 4.1 and Fig. 6: the classic schemes overshoot phi <= Phi, the modified ones do not; and
// the compressible steady state (Sect. 4.1).
//
// Set-up (docs/assumptions.md G4; the paper does not give its profiles): eq. (66) on [0, 1],
// S = 1, Phi(z) = 0.62 - 0.08 cos^2(pi z), T(z) = 0.2 + 0.8 z, phi = Phi/2 at t = 0, t = 0.75.
// What is checked, and against what, for every row of the scheme table (src/segregation/scheme.hpp):
//   - rows not marked bounded (classic upwind and classic Godunov with interface Phi, T exact at
//     the face; Rusanov): max over the run of phi - Phi is > 0 at every N = 50 .. 3200 and falls
//     like 1/N (fitted order near 1), the grid-scale error of Sect. 4.1;
//   - rows marked bounded (modified-godunov, modified-godunov-2): max(phi - Phi) <= 0 and
//     min(phi) >= 0 to round-off;
//   - every run: the sum of phi is conserved to 1e-13 (zero-flux ends) and stays finite;
//   - long runs (T > 0): phi = Phi below z*, 0 above, with z* from int_0^z* Phi = initial mass
//     (computed by GSL quadrature and root finding, independently of the solver), for the Fig. 6
//     profiles and for a Phi with a jump.
// Writes fig6_profiles.dat (N = 50, every scheme) and fig6_overshoot.dat for figures/fig6*.gp
// (one column per row of the table, in its order).
//
// Run: build/verification/verify_overshoot [--data DIR]   (about a second)
#include "harness/check_table.hpp"
#include "harness/program.hpp"
#include "harness/segregation_run.hpp"
#include "segregation/invariants.hpp"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_integration.h>
#include <gsl/gsl_roots.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <string>
#include <vector>

using namespace granseg;
using namespace granseg::verify;

namespace {

// Tolerances and bounds, each with its reason.
// Conservation: eq. (64) moves the same rounded amount through each face; the sum of phi drifts
// only by the rounding of the additions, of order DBL_EPSILON; 1e-13 leaves decades of margin.
constexpr double kMassTolerance = 1e-13;
// Bounds of the modified schemes: round-off of one update (invariants.hpp), relative to Phi <= 0.62.
constexpr double kBoundTolerance = kBoundRoundOff;
// The overshoot of a first-order scheme is a grid-scale error: it should fall like 1/N. The
// fitted order over N = 50 .. 3200 must lie within 0.2 of 1 (the program prints it).
constexpr double kOvershootOrderTolerance = 0.2;
// Steady state: cells fully below (above) the interface must equal Phi (0) to round-off of the
// last updates of a full cell (a few DBL_EPSILON of Phi).
constexpr double kSteadyTolerance = 1e-14;
// Interface height: the initial mass on the grid is the midpoint rule of int phi0, so the
// discrete z* differs from the exact one by O(h^2); |error| <= h^2 covers it with a wide margin
// (the program prints the error in units of h^2).
constexpr double kInterfaceConstant = 1.0;

const std::vector<int> kCells = {50, 100, 200, 400, 800, 1600, 3200};
const std::vector<SegregationScheme> kSchemes = SegregationScheme::all();

double Phi_fig6(double z) { return 0.62 - 0.08 * std::pow(std::cos(M_PI * z), 2); }
double T_fig6(double z) { return 0.2 + 0.8 * z; }

ColumnSetup fig6_setup(int cells, InterfaceRule rule = InterfaceRule::exact) {
    ColumnSetup s;
    s.cells = cells;
    s.S = 1.0;
    s.Phi = Phi_fig6;
    s.T = T_fig6;
    s.interface = rule;
    return s;
}

/// Running worst values over every run of the program.
struct EveryRun {
    double mass = 0.0, bounds = 0.0;
    long nonfinite = 0, runs = 0;
    void add(const ColumnRun& r, bool bounded) {
        mass = std::max(mass, r.mass_drift);
        if (bounded) bounds = std::max({bounds, r.max_excess, -r.min_phi, r.correction});
        nonfinite += r.nonfinite;
        ++runs;
    }
};

void check_overshoot(CheckTable& t, const ProgramOptions& options, EveryRun& every) {
    t.note("max over the run of phi - Phi, t = 0.75 (classic: interface Phi, T exact at the faces;");
    t.note("bounded rows: the larger of it and the round-off clip if there was one, assumption G5):");
    std::string header = "      N";
    for (SegregationScheme s : kSchemes) {
        char cell[40];
        std::snprintf(cell, sizeof cell, "  %19s", scheme_name(s).c_str());
        header += cell;
    }
    t.note(header);
    DataTable table;
    std::vector<std::vector<double>> excess(kSchemes.size());
    for (int N : kCells) {
        const Column column = make_column(fig6_setup(N));
        const auto phi0 = column_profile(column, [](double z) { return 0.5 * Phi_fig6(z); });
        TableRow row{{"N", static_cast<double>(N)}};
        char line[160];
        std::string text;
        for (std::size_t s = 0; s < kSchemes.size(); ++s) {
            const ColumnRun run = run_column(column, phi0, scheme_options(kSchemes[s]), 0.75);
            every.add(run, preserves_bounds(kSchemes[s]));
            // Modified schemes: also what the round-off guard clipped (an upper bound of the
            // excess the scheme itself produced).
            const double e = run.correction > 0.0 ? std::max(run.max_excess, run.correction) : run.max_excess;
            excess[s].push_back(e);
            row.add(scheme_column(kSchemes[s]), e);
            std::snprintf(line, sizeof line, "  %19.4e", e);
            text += line;
        }
        std::snprintf(line, sizeof line, "%7d", N);
        t.note(line + text);
        table.row(row);
    }
    write_data(options, "fig6_overshoot.dat", table);

    for (std::size_t s = 0; s < kSchemes.size(); ++s) {
        const std::string name = scheme_name(kSchemes[s]);
        if (preserves_bounds(kSchemes[s])) {
            t.at_most(name + ": max(phi - Phi) over all N", *std::max_element(excess[s].begin(), excess[s].end()),
                      kBoundTolerance * 0.62);
            continue;
        }
        const long below = std::count_if(excess[s].begin(), excess[s].end(), [](double e) { return !(e > 0.0); });
        t.count(name + ": resolutions without overshoot (of 7)", below, 0);
        t.near(name + ": overshoot ~ N^-p, fitted p", fitted_order(kCells, excess[s]), 1.0, kOvershootOrderTolerance);
    }
    // The interface rule hardly matters (docs/assumptions.md G2): the mean overshoots too.
    const Column mean = make_column(fig6_setup(50, InterfaceRule::mean));
    const ColumnRun run = run_column(mean, column_profile(mean, [](double z) { return 0.5 * Phi_fig6(z); }),
                                     scheme_options(SegregationScheme::classic_godunov), 0.75);
    every.add(run, false);
    t.at_least("classic-godunov, Phi_face = mean, N = 50: max(phi - Phi)", run.max_excess, 1e-4);
}

void write_profiles(const ProgramOptions& options, EveryRun& every) {
    const Column column = make_column(fig6_setup(50));
    const auto phi0 = column_profile(column, [](double z) { return 0.5 * Phi_fig6(z); });
    std::vector<std::vector<double>> phi;
    for (SegregationScheme s : kSchemes) {
        const ColumnRun run = run_column(column, phi0, scheme_options(s), 0.75);
        every.add(run, preserves_bounds(s));
        phi.push_back(run.phi);
    }
    DataTable table;
    table.comment("Fig. 6 set-up, N = 50, t = 0.75, cfl = 0.9 (docs/assumptions.md G4)");
    for (std::size_t k = 0; k < phi0.size(); ++k) {
        TableRow row{{"z", column.z[k]}, {"Phi", column.fields.Phi[k]}, {"T", column.T[k]}, {"phi0", phi0[k]}};
        for (std::size_t s = 0; s < kSchemes.size(); ++s) row.add(scheme_column(kSchemes[s]), phi[s][k]);
        table.row(row);
    }
    write_data(options, "fig6_profiles.dat", table);
}

struct HeightProblem {
    const std::function<double(double)>* Phi;
    gsl_integration_workspace* work;
    double mass;
};

double Phi_at(double z, void* p) { return (*static_cast<HeightProblem*>(p)->Phi)(z); }

/// int_0^x Phi dz - mass, by GSL adaptive quadrature (QAGS).
double mass_below_minus_target(double x, void* p) {
    auto* problem = static_cast<HeightProblem*>(p);
    gsl_function f{Phi_at, problem};
    double value = 0.0, error = 0.0;
    gsl_integration_qags(&f, 0.0, x, 1e-15, 1e-13, 200, problem->work, &value, &error);
    return value - problem->mass;
}

/// z* with int_0^z* Phi dz = mass (Brent's method on the quadrature).
double interface_height(const std::function<double(double)>& Phi, double mass) {
    HeightProblem problem{&Phi, gsl_integration_workspace_alloc(200), mass};
    gsl_function residual{mass_below_minus_target, &problem};
    gsl_root_fsolver* solver = gsl_root_fsolver_alloc(gsl_root_fsolver_brent);
    gsl_root_fsolver_set(solver, &residual, 1e-9, 1.0);
    double x = 0.5;
    for (int i = 0; i < 200; ++i) {
        gsl_root_fsolver_iterate(solver);
        x = gsl_root_fsolver_root(solver);
        if (gsl_root_test_interval(gsl_root_fsolver_x_lower(solver), gsl_root_fsolver_x_upper(solver), 1e-15, 0) == GSL_SUCCESS)
            break;
    }
    gsl_root_fsolver_free(solver);
    gsl_integration_workspace_free(problem.work);
    return x;
}

/// Long run to the steady state of a compressible column; checks its shape and interface height.
void check_steady_state(CheckTable& t, const std::string& label, const ColumnSetup& base,
                        const std::function<double(double)>& phi0, double mass, EveryRun& every) {
    const double z_star = interface_height(base.Phi, mass);
    t.note("steady state (t = 8), " + label + ": exact interface z* = " + format(z_star));
    for (SegregationScheme scheme : {SegregationScheme::modified_godunov, SegregationScheme::modified_godunov_2}) {
        for (int N : {50, 200}) {
            ColumnSetup setup = base;
            setup.cells = N;
            const Column column = make_column(setup);
            const ColumnRun run = run_column(column, column_profile(column, phi0), scheme_options(scheme), 8.0);
            every.add(run, true);
            const double h = 1.0 / N;
            double worst = 0.0, filled = 0.0;  // filled: height of small particles, sum phi/Phi h
            for (int k = 0; k < N; ++k) {
                const double z = column.z[k], expected = z < z_star ? column.fields.Phi[k] : 0.0;
                if (std::fabs(z - z_star) > 1.5 * h) worst = std::max(worst, std::fabs(run.phi[k] - expected));
                filled += run.phi[k] / column.fields.Phi[k] * h;
            }
            const std::string tag = "  " + scheme_name(scheme) + ", N = " + std::to_string(N);
            t.at_most(tag + ": max |phi - steady|, |z - z*| > 1.5h", worst, kSteadyTolerance);
            t.at_most(tag + ": |z*(grid) - z*|", std::fabs(filled - z_star), kInterfaceConstant * h * h);
        }
    }
}

}  // namespace

int main(int argc, char** argv) {
    const ProgramOptions options = parse_program_options(argc, argv);
    gsl_set_error_handler_off();
    CheckTable t("Sect. 4.1 / Fig. 6: overshoot of the classic schemes, bounds of the modified ones");
    EveryRun every;
    check_overshoot(t, options, every);
    write_profiles(options, every);

    // Steady state of the Fig. 6 column from phi0 = Phi/3: int_0^1 Phi/3 dz = 0.58/3.
    check_steady_state(
        t, "Fig. 6 Phi and T, phi0 = Phi/3", fig6_setup(50), [](double z) { return Phi_fig6(z) / 3.0; }, 0.58 / 3.0, every);
    // A jump in Phi inside the filled layer (at a face of both grids, so the midpoint rule of the
    // initial mass is exact) and a smooth T > 0; phi0 = 0.45 Phi: mass 0.45 int Phi.
    ColumnSetup jump = fig6_setup(50);
    jump.Phi = [](double z) { return z < 0.36 ? 0.5 : 0.6; };
    jump.T = [](double z) { return 0.1 + 0.9 * std::pow(std::sin(M_PI * z), 2); };
    check_steady_state(
        t, "Phi jumps 0.5 -> 0.6 at z = 0.36, phi0 = 0.45 Phi", jump, [&](double z) { return 0.45 * jump.Phi(z); },
        0.45 * (0.36 * 0.5 + 0.64 * 0.6), every);

    t.note("every run of this program (" + std::to_string(every.runs) + " runs):");
    t.at_most("every run: max relative change of sum(phi)", every.mass, kMassTolerance);
    t.at_most("every run, modified: bound violation incl. round-off clip", every.bounds, kBoundTolerance * 0.62);
    t.count("every run: non-finite values", every.nonfinite, 0);
    return t.finish();
}
