// Work-precision benchmark of the segregation schemes (Sect. 4.1): L1 error against CPU
// time for every scheme, N = 50 .. 12800, on
//   two-shock  the homogeneous Gray-Thornton batch (Phi = 0.6, q = 1, psi0 = 0.4, t = 0.6), exact;
//   fig6       the Fig. 6 column (docs/assumptions.md G4, t = 0.75) against a much finer run,
//              modified-godunov at N = 102400 (its own L1 error is estimated at ~3e-6, so
//              errors near 1e-5 carry a reference error of ~25 %);
//   graded     the normally graded batch (fan and shocks, z0 = 0.6, t = 1), exact.
// CPU time (CLOCK_PROCESS_CPUTIME_ID) of the time loop only, median of 5 runs (min and max too);
// cell updates per second. It reports; it asserts nothing. The machine is shared: the load
// average (/proc/loadavg) is written before and after.
//
// Writes bench_segregation.dat (one row per problem, scheme, N) and prints, per problem and
// scheme, the CPU time needed for L1 error 1e-3 (log-log interpolation between resolutions).
// Writes bench_segregation.md, the table docs/sect4.1_overshoot.md shows (docs/checked_pages.md,
// "Generated tables"): per scheme, that CPU time on the two-shock batch and the median rate of
// cell updates (one per cell and Runge-Kutta stage) on the Fig. 6 column for N >= 800.
//
// Run: build/bench/bench_segregation [--data DIR]   (several minutes; `make bench`)
#include "harness/gray_thornton.hpp"
#include "harness/program.hpp"
#include "harness/segregation_run.hpp"
#include "harness/table_provenance.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <functional>
#include <string>
#include <vector>

using namespace granseg;
using namespace granseg::verify;

namespace {

constexpr int kRepetitions = 5;
constexpr int kReferenceCells = 102400;
constexpr double kTarget = 1e-3;     // the L1 error whose cost the summary quotes
constexpr int kRateFromCells = 800;  // the rate of cell updates is the median over N >= this

const std::vector<int> kCells = {50, 100, 200, 400, 800, 1600, 3200, 6400, 12800};
const std::vector<SegregationScheme> kSchemes = {SegregationScheme::modified_godunov, SegregationScheme::modified_godunov_2,
                                                 SegregationScheme::classic_upwind, SegregationScheme::classic_godunov};

struct Problem {
    std::string name;
    ColumnSetup setup;
    std::function<std::vector<double>(const Column&)> initial;
    std::function<std::vector<double>(int N)> reference;  // cell averages at t_end
    double t_end;
};

std::vector<double> scaled(std::vector<double> v, double factor) {
    for (double& x : v) x *= factor;
    return v;
}

ColumnSetup constant_setup() {
    ColumnSetup s;
    s.Phi = [](double) { return 0.6; };
    s.T = [](double) { return 1.0; };
    return s;
}

double Phi_fig6(double z) { return 0.62 - 0.08 * std::pow(std::cos(M_PI * z), 2); }

/// The Fig. 6 reference, averaged onto N cells (N divides kReferenceCells).
std::vector<double> fig6_reference(int N) {
    static std::vector<double> fine;
    if (fine.empty()) {
        ColumnSetup s;
        s.cells = kReferenceCells;
        s.Phi = Phi_fig6;
        s.T = [](double z) { return 0.2 + 0.8 * z; };
        const Column c = make_column(s);
        std::fprintf(stderr, "bench_segregation: reference run, modified-godunov, N = %d ...\n", kReferenceCells);
        fine = run_column(c, column_profile(c, [](double z) { return 0.5 * Phi_fig6(z); }),
                          scheme_options(SegregationScheme::modified_godunov), 0.75, false)
                   .phi;
    }
    std::vector<double> coarse(N, 0.0);
    const int m = kReferenceCells / N;
    for (int k = 0; k < kReferenceCells; ++k) coarse[k / m] += fine[k] / m;
    return coarse;
}

std::vector<Problem> problems() {
    Problem fig6{"fig6", {}, nullptr, fig6_reference, 0.75};
    fig6.setup.Phi = Phi_fig6;
    fig6.setup.T = [](double z) { return 0.2 + 0.8 * z; };
    fig6.initial = [](const Column& c) { return column_profile(c, [](double z) { return 0.5 * Phi_fig6(z); }); };
    const auto graded = [](double t) {
        if (t == 0.0) return PiecewiseLinear{[](double z) { return z < 0.6 ? 0.0 : 1.0; }, {0.6}};
        return graded_batch(0.6, 1.0, t);
    };
    return {
        {"two-shock", constant_setup(),
         [](const Column& c) { return scaled(cell_averages(homogeneous_batch(0.4, 1.0, 0.0), c.z.size()), 0.6); },
         [](int N) { return scaled(cell_averages(homogeneous_batch(0.4, 1.0, 0.6), N), 0.6); }, 0.6},
        fig6,
        {"graded", constant_setup(), [=](const Column& c) { return scaled(cell_averages(graded(0.0), c.z.size()), 0.6); },
         [=](int N) { return scaled(cell_averages(graded(1.0), N), 0.6); }, 1.0},
    };
}

/// One row of the markdown table: a scheme's cost to kTarget on the two-shock batch and its rate.
struct MarkdownRow {
    double seconds_to_target = NAN;
    std::vector<double> fig6_rates;  // million cell updates per second, N >= kRateFromCells
};

/// The markdown table of bench_segregation.md.
std::string markdown_table(const std::vector<MarkdownRow>& rows) {
    std::string out =
        "| scheme | CPU time to L1 = 1e-3, two-shock batch | million cell updates per second, Fig. 6 column, N >= " +
        std::to_string(kRateFromCells) + " |\n|---|---|---|\n";
    for (std::size_t s = 0; s < kSchemes.size(); ++s) {
        char line[200];
        std::snprintf(line, sizeof line, "| %s | %.2f ms | %.0f |\n", scheme_name(kSchemes[s]).c_str(),
                      1e3 * rows[s].seconds_to_target, median(rows[s].fig6_rates));
        out += line;
    }
    return out;
}

/// CPU time at which the error curve (log-log linear between resolutions) reaches kTarget; NaN
/// if it never does.
double time_to_target(const std::vector<double>& error, const std::vector<double>& seconds) {
    for (std::size_t i = 0; i + 1 < error.size(); ++i)
        if (error[i] >= kTarget && error[i + 1] <= kTarget) {
            const double w = std::log(error[i] / kTarget) / std::log(error[i] / error[i + 1]);
            return std::exp(std::log(seconds[i]) + w * std::log(seconds[i + 1] / seconds[i]));
        }
    return error.front() <= kTarget ? seconds.front() : NAN;
}

}  // namespace

int main(int argc, char** argv) {
    const ProgramOptions options = parse_program_options(argc, argv);
    const std::string load_before = load_average();
    DataTable table;
    table.comment(
        "problem: 0 two-shock, 1 fig6, 2 graded; scheme: 0 modified-godunov, 1 modified-godunov-2, "
        "2 classic-upwind, 3 classic-godunov; CPU seconds, median of " +
        std::to_string(kRepetitions) + " runs");
    table.comment("load average before: " + load_before);
    std::printf("%-10s %-19s %6s %11s %11s %11s %9s\n", "problem", "scheme", "N", "L1", "cpu median", "(min..max)", "Mupd/s");
    std::vector<std::string> summary;
    std::vector<MarkdownRow> markdown(kSchemes.size());
    int p = 0;
    for (const Problem& problem : problems()) {
        for (std::size_t s = 0; s < kSchemes.size(); ++s) {
            std::vector<double> errors, medians;
            for (int N : kCells) {
                ColumnSetup setup = problem.setup;
                setup.cells = N;
                const Column column = make_column(setup);
                const std::vector<double> phi0 = problem.initial(column), reference = problem.reference(N);
                std::vector<double> seconds;
                ColumnRun run;
                for (int r = 0; r < kRepetitions; ++r) {
                    run = run_column(column, phi0, scheme_options(kSchemes[s]), problem.t_end, false);
                    seconds.push_back(run.seconds);
                }
                std::sort(seconds.begin(), seconds.end());
                const double median = seconds[kRepetitions / 2], rate = run.updates / median / 1e6;
                const double error = l1_distance(run.phi, reference, 1.0 / N);
                errors.push_back(error);
                medians.push_back(median);
                if (problem.name == "fig6" && N >= kRateFromCells) markdown[s].fig6_rates.push_back(rate);
                table.row({{"problem", static_cast<double>(p)},
                           {"scheme", static_cast<double>(s)},
                           {"N", static_cast<double>(N)},
                           {"L1", error},
                           {"cpu_median", median},
                           {"cpu_min", seconds.front()},
                           {"cpu_max", seconds.back()},
                           {"updates", static_cast<double>(run.updates)},
                           {"Mupdates_per_s", rate}});
                std::printf("%-10s %-19s %6d %11.4e %11.4e %5.0f..%-5.0f%% %9.1f\n", problem.name.c_str(),
                            scheme_name(kSchemes[s]).c_str(), N, error, median, 100 * seconds.front() / median,
                            100 * seconds.back() / median, rate);
                std::fflush(stdout);
            }
            char line[160];
            std::snprintf(line, sizeof line, "%-10s %-19s CPU time to L1 = %g: %.3g s", problem.name.c_str(),
                          scheme_name(kSchemes[s]).c_str(), kTarget, time_to_target(errors, medians));
            summary.push_back(line);
            if (problem.name == "two-shock") markdown[s].seconds_to_target = time_to_target(errors, medians);
            table.blank();
            table.blank();
        }
        ++p;
    }
    table.comment("load average after: " + load_average());
    write_data(options, "bench_segregation.dat", table);
    write_generated_table(options.data_dir + "/bench_segregation.md", markdown_table(markdown), {"segregation"});
    std::printf("\nload average before: %s, after: %s\n", load_before.c_str(), load_average().c_str());
    for (const auto& line : summary) std::printf("%s\n", line.c_str());
    return 0;
}
