// The coupled drum's time-step error (study/dt_study.hpp): the paper's drum on fixed grids with
// dt_max refined, without and with packing feedback, for each transport; per series and quantity
// the observed order in dt, the dt -> 0 limit and the time error at the largest step; the full
// model's error against cost at each --cost-dt-max and at the coupled drum's default step; and as
// the one check table of this program the accuracy that default step (kCoupledDtMax and
// kCoupledAcousticCourantMax, coupled/coupled_tumbler.hpp) is meant to hold on the full model
// (kAngleTarget, kShareTarget below).
// Writes to DIR: time_step_runs.dat, time_step.dat, time_step.md, time_step_cost.dat,
// time_step_cost.md (the .md ready for docs/generated/), and every run under time_step/ (its scene
// NAME.toml and its files NAME/); figures/bench_time_step.gp plots time_step.dat.
//
// Run: build/bench/bench_time_step [--data DIR] [options]    (--help lists them)
//   the default is the whole study (about eight CPU-hours, two runs side by side); a test of
//   everything in a few minutes:
//   --grids "26:2e-3,1e-3" --transports donor-cell --t-end 2 --average-from 1 --jitter-window 0.5
#include "core/error.hpp"
#include "harness/check_table.hpp"
#include "harness/program.hpp"
#include "harness/side_by_side.hpp"
#include "study/dt_study.hpp"
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

constexpr const char* kProgram = "bench_time_step";

// The accuracy of the default step on the full model (the feedback part): within this of the
// dt -> 0 limit, the time step adds less to the angle than the figure's grid series resolves and
// less to the shares than their differences between the drum's regions.
constexpr double kAngleTarget = 0.2;   // deg
constexpr double kShareTarget = 0.01;  // of the small-particle share (axis, core)

/// "50:2e-3,1e-3;100:2e-3,1e-3" -> the grids with their time steps (each list strictly decreasing).
std::vector<DtGrid> grid_list(const std::string& text) {
    std::vector<DtGrid> grids;
    std::istringstream in(text);
    for (std::string item; std::getline(in, item, ';');) {
        const std::size_t colon = item.find(':');
        if (colon == std::string::npos) bad_option(kProgram, "grids", "\"" + item + "\" has no ':'", "CELLS:DT,DT,...;CELLS:...");
        const std::vector<int> cells = cell_list(kProgram, "grids", item.substr(0, colon));
        DtGrid g{cells.empty() ? 0 : cells.front(), number_list(kProgram, "grids", item.substr(colon + 1), 0.0, 10.0)};
        if (cells.size() != 1 || g.dt_max.size() < 2 || !std::is_sorted(g.dt_max.rbegin(), g.dt_max.rend()) ||
            std::adjacent_find(g.dt_max.begin(), g.dt_max.end()) != g.dt_max.end())
            bad_option(kProgram, "grids", "\"" + item + "\"", "one grid and two or more decreasing dt_max per item");
        grids.push_back(g);
    }
    if (grids.empty()) bad_option(kProgram, "grids", "\"" + text + "\"", "one or more items CELLS:DT,DT,...");
    return grids;
}

DtStudyOptions parse(int argc, char** argv) {
    DtStudyOptions o;
    o.run.study_dir = "time_step";
    std::string grids = "50:2e-3,1e-3,5e-4,2.5e-4;100:1e-3,5e-4,2.5e-4", transports = "muscl,donor-cell",
                parts = "no-feedback,feedback", cost = "1e-3,2e-3,3e-3,4e-3";
    po::options_description d("bench_time_step: the coupled drum's time-step error");
    d.add_options()("help", "this list")("data", po::value(&o.run.data_dir)->default_value(o.run.data_dir), "output directory")(
        "grids", po::value(&grids)->default_value(grids),
        "CELLS:DT_MAX,... per grid, ';' between grids, largest dt_max first (the default step)")(
        "transports", po::value(&transports)->default_value(transports), "[flow] transport of each series")(
        "parts", po::value(&parts)->default_value(parts), "no-feedback, feedback or both ([coupling] packing_feedback)")(
        "cost-dt-max", po::value(&cost)->default_value(cost),
        "s, dt_max of the error-against-cost runs (the full model on every grid, at the flow solver's acoustic Courant "
        "number; a run at the coupled drum's default step is always added)");
    add_run_options(d, o.run);
    parse_study_command_line(kProgram, argc, argv, d, o.run);
    o.grids = grid_list(grids);
    o.run.transports = transport_list(kProgram, transports);
    o.cost_dt_max = number_list(kProgram, "cost-dt-max", cost, 0.0, 10.0);
    if (parts == "no-feedback")
        o.feedback = {false};
    else if (parts == "feedback")
        o.feedback = {true};
    else if (parts != "no-feedback,feedback")
        bad_option(kProgram, "parts", "\"" + parts + "\"", "no-feedback, feedback, no-feedback,feedback");
    check_run_options(kProgram, o.run);
    return o;
}

}  // namespace

int main(int argc, char** argv) {
    verify::parse_program_options(1, argv);  // only for its handling of the library's errors (exit 2, 3)
    const DtStudyOptions o = parse(argc, argv);
    const std::vector<Fig7Run> plan = plan_dt_runs(o);
    std::printf("%s: %zu runs of verification/scenes/tumbler.toml, t_end %g s, %d thread(s) each, %d side by side%s\n", kProgram,
                plan.size(), o.run.t_end, o.run.threads, o.run.lanes, o.run.reuse ? ", reusing unchanged runs" : "");
    const auto start = std::chrono::steady_clock::now();
    std::vector<Fig7Result> results(plan.size());
    std::mutex print;
    run_side_by_side(static_cast<int>(plan.size()), o.run.lanes, [&](int j) {
        results[j] = run_fig7(plan[j], o.run);
        const Fig7Result& r = results[j];
        const std::lock_guard<std::mutex> lock(print);
        std::printf(
            "run %-34s %8.1f s wall, %7.0f steps (%.3f set by dt_max, %.3f by the acoustic bound): "
            "angle %.3f deg, layer %.2f mm, index %.4f, ring %.4f, core %.4f, contrast %.4f, axis %.4f\n",
            r.run.name.c_str(), r.wall, r.steps, r.dt_max_share, r.acoustic_share, r.value[kAngle], r.value[kLayer],
            r.value[kIndex], r.value[kRing], r.value[kCore], r.value[kContrast], r.value[kAxis]);
        std::fflush(stdout);
    });
    std::printf("all runs: %.1f s wall\n\n", std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    const std::vector<DtEstimate> estimates = analyse_dt(results, o);
    write_dt_study(results, estimates, o);
    for (const DtEstimate& d : estimates)
        std::printf("%-11s %-10s n%-4d %-9s %-13s p %-6s f0 %-10s at the largest dt %-10s error %-10s bound %s\n",
                    part_name(d.feedback).c_str(), d.transport.c_str(), d.cells, fig7_quantities()[d.e.quantity].name,
                    convergence_name(d.e.g.condition).c_str(), fig7_number(d.e.g.p, 3).c_str(), fig7_number(d.e.g.f0).c_str(),
                    fig7_number(d.at_default).c_str(), fig7_number(d.error, 3).c_str(), fig7_number(d.bound, 3).c_str());
    std::printf("\n");
    const std::vector<DtCost> costs = dt_costs(results, estimates, o);
    write_dt_costs(costs, o);
    CheckTable table("bench_time_step: the full model's time error at the coupled drum's default step");
    for (const DtCost& c : costs) {
        if (!at_default_step(*c.run)) continue;
        const std::string series = c.run->run.transport + ", " + std::to_string(c.run->run.cells) + " cells: ";
        for (int q : {kAngle, kCore, kAxis})
            table.at_most(series + fig7_quantities()[q].name + " at the default step (mean " +
                              fig7_number(1e3 * c.run->dt_mean, 3) + " ms) from its limit",
                          c.bound[q], q == kAngle ? kAngleTarget : kShareTarget);
    }
    return table.finish();
}
