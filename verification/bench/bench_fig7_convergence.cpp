// Solution verification of the paper's drum (Fig. 7, verification/scenes/tumbler.toml):
// how much of each Fig. 7 quantity is the model and how much the grid and the time step.
//
//   1. runs (study/fig7_study.hpp): the coupled drum with each --transports at each --cells
//      (50, 70, 100, 140: ratios near sqrt 2, even counts), dt_max proportional to h so that it
//      sets the steps on every grid; the explicit time stepping at each --explicit-cells; the dt
//      study at the coarsest and the finest grid (dt_max times factors below 1); a passive tracer
//      in the core at each --cells, the model and the tracer at a lower T_floor;
//   2. per quantity (angle of repose, flowing-layer thickness, segregation index, ring, periphery,
//      core, Fig. 7d contrast, small-particle share within 0.05 D of the axis) and series: the
//      convergence condition, least-squares order, limit and uncertainty with the sampling errors
//      weighing in (harness/grid_convergence.hpp, fig7_report.hpp);
//   3. work against error: wall time against |value - reference|, and the cheapest run for a
//      quick look, a figure and a paper (fig7_work.hpp);
//   4. the share of steps dt_max set in every run and the paper's statements as checks on the
//      finest run, bounds widened by their band (checks f-j, fig7_core.hpp: the one check table of
//      this program), and the core's measured parts.
// Writes to DIR: fig7_runs.dat, fig7_convergence.dat/.md, fig7_summary.md, fig7_work.dat/.md,
// fig7_core.md, fig7_checks.md (the .md files are ready for docs/generated/), and every run under fig7_convergence/ (its scene
// NAME.toml and its files NAME/); figures/bench_fig7_convergence.gp and bench_fig7_work.gp plot them.
//
// A study stopped (Ctrl-C, a job's time limit, a power cut) and run again with the same options skips
// the runs that finished and resumes the others from their checkpoints (study/fig7_study.hpp).
// Run: build/bench/bench_fig7_convergence [--data DIR] [options]    (--help lists them)
//   the default is the real study, long (see docs/sect4.2_fig7_study.md); a test of
//   everything in a few minutes:
//   --cells 26,36,50,70 --transports muscl --t-end 2 --average-from 1 --jitter-window 0.5
#include "core/error.hpp"
#include "flow/fields/flow_settings.hpp"
#include "harness/program.hpp"
#include "harness/side_by_side.hpp"
#include "scenes/tumbler.hpp"
#include "study/fig7_core.hpp"
#include "study/fig7_report.hpp"
#include "study/fig7_study.hpp"
#include "study/fig7_work.hpp"
#include "study/study_options.hpp"

#include <boost/program_options.hpp>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <mutex>
#include <sstream>

using namespace granseg;
using namespace granseg::verify;
namespace po = boost::program_options;

namespace {

constexpr const char* kProgram = "bench_fig7_convergence";

[[noreturn]] void bad_option(const std::string& option, const std::string& what, const std::string& allowed) {
    verify::bad_option(kProgram, option, what, allowed);
}

Fig7Options parse(int argc, char** argv) {
    Fig7Options o;
    std::string cells = "50,70,100,140", explicit_cells = "none", transports = "muscl,donor-cell", dt_coarse = "0.5,0.25",
                dt_fine = "0.5";
    po::options_description d("bench_fig7_convergence: solution verification of the paper's drum (Fig. 7)");
    d.add_options()("help", "this list")("data", po::value(&o.data_dir)->default_value(o.data_dir), "output directory")(
        "cells", po::value(&cells)->default_value(cells), "cells per diameter of the grid series, coarse to fine (3 or more)")(
        "transports", po::value(&transports)->default_value(transports),
        "[flow] transport of each grid series; the first is the reference")(
        "explicit-cells", po::value(&explicit_cells)->default_value(explicit_cells),
        "explicit time stepping (none, or 2 or more)")("dt-ref", po::value(&o.dt_ref)->default_value(o.dt_ref),
                                                       "s, dt_max at 50 cells per diameter; every run takes dt_ref 50/cells")(
        "dt-coarse", po::value(&dt_coarse)->default_value(dt_coarse), "dt_max factors of the dt study at the coarsest grid")(
        "dt-fine", po::value(&dt_fine)->default_value(dt_fine), "dt_max factors of the dt study at the finest grid")(
        "no-dt-study", "skip the dt study")("no-core-study", "skip the tracer and T_floor runs (check d)")(
        "T-floor-low", po::value(&o.T_floor_low)->default_value(o.T_floor_low), "m^2/s^2, T_floor of the floor runs");
    add_run_options(d, o);
    const po::variables_map vm = parse_study_command_line(kProgram, argc, argv, d, o);
    o.cells = cell_list(kProgram, "cells", cells), o.explicit_cells = cell_list(kProgram, "explicit-cells", explicit_cells);
    o.transports = transport_list(kProgram, transports);
    o.dt_coarse = number_list(kProgram, "dt-coarse", dt_coarse, 0.0, 1.0),
    o.dt_fine = number_list(kProgram, "dt-fine", dt_fine, 0.0, 1.0);
    o.dt_study = !vm.count("no-dt-study"), o.core_study = !vm.count("no-core-study");
    if (o.cells.size() < 3) bad_option("cells", "\"" + cells + "\" has fewer than three grids", "three or more");
    if (o.explicit_cells.size() == 1) bad_option("explicit-cells", "one grid", "none, or two or more");
    if (o.dt_study && (o.dt_coarse.empty() || o.dt_fine.empty()))
        bad_option("dt-coarse", "no dt factor at one end", "one or more factors at each end, or --no-dt-study");
    if (!(o.dt_ref > 0.0 && o.dt_ref <= 0.1)) bad_option("dt-ref", fig7_number(o.dt_ref), "0 < dt_ref <= 0.1 s");
    if (!(o.T_floor_low > 0.0 && o.T_floor_low < 1e-2)) bad_option("T-floor-low", fig7_number(o.T_floor_low), "0 < T < 0.01");
    check_run_options(kProgram, o);
    return o;
}

}  // namespace

int main(int argc, char** argv) {
    verify::parse_program_options(1, argv);  // only for its handling of the library's errors (exit 2, 3)
    const Fig7Options o = parse(argc, argv);
    const std::vector<Fig7Run> plan = plan_fig7_runs(o);
    std::printf(
        "bench_fig7_convergence: %zu runs of verification/scenes/tumbler.toml, t_end %g s, %d thread(s) each, "
        "%d side by side%s\n",
        plan.size(), o.t_end, o.threads, o.lanes, o.reuse ? ", reusing unchanged runs" : "");
    const auto start = std::chrono::steady_clock::now();
    std::vector<Fig7Result> results(plan.size());
    std::mutex print;
    verify::run_side_by_side(static_cast<int>(plan.size()), o.lanes, [&](int j) {
        const Fig7Run& run = plan[j];
        results[j] = run_fig7(run, o);
        const Fig7Result& r = results[j];
        const std::lock_guard<std::mutex> lock(print);
        std::printf(
            "run %-22s %8.1f s wall (%.1f s CPU), %7.0f steps: angle %.3f deg, layer %.2f mm, index %.4f, ring %.4f, periphery "
            "%.4f, "
            "core %.4f, contrast %.4f, axis %.4f\n",
            run.name.c_str(), r.wall, r.cpu, r.steps, r.value[0], r.value[1], r.value[2], r.value[3], r.value[4], r.value[5],
            r.value[6], r.value[7]);
        std::fflush(stdout);
    });
    std::printf("all runs: %.1f s wall\n", std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    const Fig7Analysis analysis = analyse_fig7(std::move(results), o);
    write_fig7_convergence(analysis, o);
    const std::vector<std::string> answers = write_fig7_work(analysis, o);
    std::printf("\n");
    for (const Fig7Estimate& e : analysis.estimates)
        std::printf("%-9s %-8s %-12s p %-8s Fs %-4s f0 %-10s%s U %-9s (se %s)\n", fig7_quantities()[e.quantity].name,
                    e.series.c_str(), convergence_name(e.g.condition).c_str(), fig7_number(e.g.p, 4).c_str(),
                    fig7_number(e.g.fs, 3).c_str(), fig7_number(e.g.f0).c_str(), e.g.outside_bounds ? " (outside its range)" : "",
                    fig7_number(e.g.uncertainty, 4).c_str(), fig7_number(e.se_max, 3).c_str());
    std::printf("\n");
    for (const std::string& a : answers) std::printf("%s\n", a.c_str());
    std::printf("\n");
    return check_fig7_statements(analysis, o);
}
