// The acceptance runs of Sect. 4.2 at full resolution (100 cells per diameter, 25 s, 2 OpenMP
// threads, or OMP_NUM_THREADS if set: on a busy machine two threads stall each other): the flow
// alone in both time-stepping modes (tumbler-flow, verification/scenes/tumbler_flow.toml with the
// default semi-implicit step, and the same scene with [flow] time_stepping = "explicit", written to
// DIR/tumbler_flow_explicit.toml so that both run the same drum) and the whole model (tumbler,
// verification/scenes/tumbler.toml), alternately kRuns times each, so all see the same load.
// Reports the median wall times; for both flow modes steps, angle of repose and flowing-layer
// thickness and their wall-time ratio; the ratio coupled / flow (the coupling
// may cost at most a fifth of the flow, ratio <= 1.2), the cost of the coupling per cell and flow
// step from the coupled run's own timers, and then, once, the coupled drum without packing feedback
// (tumbler_no_feedback.toml) and the kinematic drum (figures/tumbler_kinematic.toml) to check:
//   d. the pattern after 25 s against bounds stated before the first full run (below);
//   e. the Fig. 7d contrast with packing feedback on and off (as verify_tumbler, on the real pattern).
// Writes DIR/tumbler_flow, DIR/tumbler_flow_explicit, DIR/tumbler (Fig. 7 at full resolution is
// drawn from a run of its own: make fig7), DIR/tumbler_no_feedback, DIR/tumbler_kinematic,
// bench_tumbler_times.dat, bench_tumbler_modes.dat and bench_tumbler_pattern.dat. Long (over an
// hour, most of it the three explicit runs): `make bench`.
//
// Run: build/bench/bench_tumbler [--data DIR]
#include "core/threads.hpp"
#include "flow/flow_solver.hpp"
#include "harness/check_table.hpp"
#include "harness/program.hpp"
#include "harness/tolerances.hpp"
#include "run/output.hpp"
#include "scenes/scene_kind.hpp"

#include <toml++/toml.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

using namespace granseg;
using granseg::verify::CheckTable;
using granseg::verify::kContrastSpreads;

namespace {

constexpr int kRuns = 3;
constexpr const char* kFlowScene = "verification/scenes/tumbler_flow.toml";  // semi-implicit (the default)
constexpr const char* kCoupledScene = "verification/scenes/tumbler.toml";
constexpr const char* kNoFeedbackScene = "verification/scenes/tumbler_no_feedback.toml";
constexpr const char* kKinematicScene = "figures/tumbler_kinematic.toml";

// The segregation part may cost at most a fifth of the flow's (docs/sect4.2_tumbler.md).
constexpr double kRatio = 1.2;
// d. The pattern after 25 s, stated before the first full-resolution run (docs/sect4.2_tumbler.md,
// "Results"). The flow is the same as verify_tumbler's up to resolution; at 100 cells per diameter
// the donor-cell bulk transport smears the sorted bands with a third of the numerical diffusion
// (h |u|/2) of the 32-cell run, while the segregation flux does not depend on h, so the pattern is
// at least as strong as verify_tumbler's at 32 cells (ring 0.58, periphery 0.38, index 0.22): small
// particles in excess in the ring where the layer feeds the bed, large ones at the periphery.
// The margins allow the bands to move by part of a ring width between the two resolutions.
constexpr double kRingAtLeast = 0.55;
constexpr double kPeripheryAtMost = 0.45;
constexpr double kIndexAtLeast = 0.2;
// e. As verify_tumbler: on, the contrast exceeds kContrastSpreads (harness/tolerances.hpp) times
// the spread of Phi within a kind and a bin; off, it stays within that spread.

double run_timed(const std::string& scene, const std::string& dir) {
    const auto t0 = std::chrono::steady_clock::now();
    run_scene_file(scene, dir);
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

/// The scene `path` with [flow] time_stepping = "explicit", written next to `dir` as dir.toml;
/// returns that path.
std::string explicit_scene(const std::string& path, const std::string& dir) {
    toml::table scene = toml::parse_file(path);
    if (!scene["flow"]) scene.insert("flow", toml::table{});
    scene["flow"].as_table()->insert_or_assign("time_stepping", "explicit");
    std::ostringstream text;
    text << scene << "\n";
    write_file_atomically(dir + ".toml", text.str());
    return dir + ".toml";
}

/// The flow alone in both modes (0 explicit, 1 semi-implicit): wall times over the runs, and from
/// the last run's summary (the runs are deterministic) steps, angle and layer thickness, the cost
/// per cell and step, the solver's work per step and the shares of the step's stages (FlowStage);
/// printed and written to bench_tumbler_modes.dat.
void write_modes(const verify::ProgramOptions& options, const std::vector<std::pair<std::vector<double>, std::string>>& modes) {
    DataTable table;
    table.comment(
        "tumbler-flow, 100 cells per diameter, 25 s: 0 explicit, 1 semi-implicit; angle and flowing-layer "
        "thickness (area of the flowing bed over the surface chord) averaged over t >= angle_from; ns per "
        "cell and step from the median wall time; shares of the timed stages");
    for (std::size_t m = 0; m < modes.size(); ++m) {
        const auto& [walls, dir] = modes[m];
        const auto s = verify::last_row(dir + "/summary.dat");
        const double steps = s.at("steps"), solves = std::max(1.0, s.at("pressure_solves"));
        double staged = 0.0;
        for (int k = 0; k < kFlowStages; ++k)
            staged += s.at(std::string("seconds_") + flow_stage_name(static_cast<FlowStage>(k)));
        const double ns = 1e9 * verify::median(walls) / (steps * s.at("inside_cells")),
                     per_step = s.at("pressure_solves") / steps, newton = s.at("newton") / solves,
                     krylov = s.at("krylov") / std::max(1.0, s.at("newton")),
                     temperature = s.at("temperature_iterations") / steps;
        TableRow row{{"semi_implicit", static_cast<double>(m)},
                     {"wall_median_s", verify::median(walls)},
                     {"wall_min_s", *std::min_element(walls.begin(), walls.end())},
                     {"wall_max_s", *std::max_element(walls.begin(), walls.end())},
                     {"steps", steps},
                     {"angle_mean_deg", s.at("angle_mean_deg")},
                     {"angle_std_deg", s.at("angle_std_deg")},
                     {"layer_mean_mm", 1e3 * s.at("layer_mean")},
                     {"layer_std_mm", 1e3 * s.at("layer_std")},
                     {"ns_per_cell_step", ns},
                     {"solves_per_step", per_step},
                     {"newton_per_solve", newton},
                     {"krylov_per_newton", krylov},
                     {"temperature_cg_per_step", temperature}};
        std::string shares;
        for (int k = 0; k < kFlowStages; ++k) {
            const std::string name = flow_stage_name(static_cast<FlowStage>(k));
            const double share = s.at("seconds_" + name) / staged;
            row.add("share_" + name, share);
            shares += " " + name + " " + verify::format(100.0 * share) + "%";
        }
        table.row(row);
        std::printf(
            "%s: wall median %.1f s, %.0f steps, angle %.2f +- %.2f deg, layer %.2f +- %.2f mm, %.0f ns per cell "
            "and step; per step %.2f solves, %.2f Newton per solve, %.2f CG per Newton, %.1f temperature CG; "
            "shares:%s\n",
            m == 0 ? "explicit" : "semi-implicit", verify::median(walls), steps, s.at("angle_mean_deg"), s.at("angle_std_deg"),
            1e3 * s.at("layer_mean"), 1e3 * s.at("layer_std"), ns, per_step, newton, krylov, temperature, shares.c_str());
    }
    std::printf("wall ratio explicit / semi-implicit (medians): %.2f\n",
                verify::median(modes[0].first) / verify::median(modes[1].first));
    verify::write_data(options, "bench_tumbler_modes.dat", table);
}

}  // namespace

int main(int argc, char** argv) {
    const auto options = verify::parse_program_options(argc, argv);
    const int threads = std::getenv("OMP_NUM_THREADS") ? max_threads() : 2;
    const ThreadScope scope(threads);
    const std::string dir = options.data_dir;
    std::vector<double> flow, flow_explicit, coupled;
    DataTable times;
    const std::string explicit_flow = explicit_scene(kFlowScene, dir + "/tumbler_flow_explicit");
    for (int run = 0; run < kRuns; ++run) {
        const std::string before = verify::load_average();
        flow.push_back(run_timed(kFlowScene, dir + "/tumbler_flow"));
        flow_explicit.push_back(run_timed(explicit_flow, dir + "/tumbler_flow_explicit"));
        coupled.push_back(run_timed(kCoupledScene, dir + "/tumbler"));
        times.row({{"run", static_cast<double>(run)},
                   {"flow_seconds", flow.back()},
                   {"coupled_seconds", coupled.back()},
                   {"flow_explicit_seconds", flow_explicit.back()}});
        std::printf(
            "run %d: tumbler-flow %.1f s (explicit %.1f s), tumbler %.1f s wall on %d threads (load average before: %s, after: "
            "%s)\n",
            run, flow.back(), flow_explicit.back(), coupled.back(), threads, before.c_str(), verify::load_average().c_str());
        std::fflush(stdout);
    }
    times.comment("100 cells per diameter, 25 s, " + std::to_string(threads) + " threads; medians: tumbler-flow " +
                  verify::format(verify::median(flow)) + " s (explicit " + verify::format(verify::median(flow_explicit)) +
                  " s), tumbler " + verify::format(verify::median(coupled)) + " s");
    verify::write_data(options, "bench_tumbler_times.dat", times);
    write_modes(options, {{flow_explicit, dir + "/tumbler_flow_explicit"}, {flow, dir + "/tumbler_flow"}});
    // Not timed: a run that finished is only written out again, an interrupted one resumes.
    run_scene_file(kNoFeedbackScene, dir + "/tumbler_no_feedback", Resume::if_compatible);
    run_scene_file(kKinematicScene, dir + "/tumbler_kinematic", Resume::if_compatible);

    CheckTable t("Sect. 4.2 at 100 cells per diameter, 25 s: cost of the coupling, pattern, Fig. 7d");
    const double ratio = verify::median(coupled) / verify::median(flow);
    t.note("median wall time of " + std::to_string(kRuns) + " runs: tumbler-flow " + verify::format(verify::median(flow)) +
           " s, tumbler " + verify::format(verify::median(coupled)) + " s");
    t.at_most("wall time tumbler / tumbler-flow (medians)", ratio, kRatio);
    const auto on = verify::last_row(dir + "/tumbler/summary.dat"),
               off = verify::last_row(dir + "/tumbler_no_feedback/summary.dat");
    const double cell_steps = on.at("steps") * on.at("inside_cells");
    t.note("coupling cost in the last coupled run: bulk transport " + verify::format(1e9 * on.at("seconds_bulk") / cell_steps) +
           " ns, segregation sub-steps " + verify::format(1e9 * on.at("seconds_segregation") / cell_steps) +
           " ns, closures from phi_hat " + verify::format(1e9 * on.at("seconds_feedback") / cell_steps) +
           " ns per cell and flow step (flow step " + verify::format(1e9 * on.at("seconds_flow") / cell_steps) + " ns); " +
           verify::format(on.at("substeps")) + " segregation sub-steps of " +
           verify::format(1e9 * on.at("seconds_segregation") / (on.at("substeps") * on.at("inside_cells"))) + " ns per cell");

    const auto kinematic = verify::last_row(dir + "/tumbler_kinematic/tumbler_metrics.dat");
    DataTable pattern;
    pattern.comment(
        "pattern metrics after 25 s (pattern_metrics.hpp): drum 0 = coupled (tumbler), 1 = coupled without "
        "packing feedback, 2 = kinematic (tumbler-kinematic)");
    pattern.row({{"drum", 0},
                 {"segregation_index", on.at("segregation_index")},
                 {"ring", on.at("ring")},
                 {"periphery", on.at("periphery")},
                 {"core", on.at("core")}});
    pattern.row({{"drum", 1},
                 {"segregation_index", off.at("segregation_index")},
                 {"ring", off.at("ring")},
                 {"periphery", off.at("periphery")},
                 {"core", off.at("core")}});
    pattern.row({{"drum", 2},
                 {"segregation_index", kinematic.at("index")},
                 {"ring", kinematic.at("ring")},
                 {"periphery", kinematic.at("periphery")},
                 {"core", kinematic.at("core")}});
    verify::write_data(options, "bench_tumbler_pattern.dat", pattern);
    for (const auto& [label, m] : {std::pair{"coupled", on}, std::pair{"coupled, no packing feedback", off}})
        t.note("d. " + std::string(label) + ": index " + verify::format(m.at("segregation_index")) + ", ring " +
               verify::format(m.at("ring")) + ", periphery " + verify::format(m.at("periphery")) + ", core " +
               verify::format(m.at("core")));
    t.note("d. kinematic drum: index " + verify::format(kinematic.at("index")) + ", ring " +
           verify::format(kinematic.at("ring")) + ", periphery " + verify::format(kinematic.at("periphery")) + ", core " +
           verify::format(kinematic.at("core")));
    t.at_least("d. small-particle fraction of the ring", on.at("ring"), kRingAtLeast);
    t.at_most("d. small-particle fraction of the periphery", on.at("periphery"), kPeripheryAtMost);
    t.at_least("d. segregation index", on.at("segregation_index"), kIndexAtLeast);

    t.note("e. packing contrast (mixed - pure at equal depth): on " + verify::format(on.at("packing_contrast")) + " (spread " +
           verify::format(on.at("packing_spread")) + ", " + verify::format(on.at("contrast_bins")) + " bins), off " +
           verify::format(off.at("packing_contrast")) + " (spread " + verify::format(off.at("packing_spread")) + ", " +
           verify::format(off.at("contrast_bins")) + " bins)");
    t.at_least("e. on: contrast / spread", on.at("packing_contrast") / on.at("packing_spread"), kContrastSpreads);
    t.at_most("e. off: |contrast| / spread", std::fabs(off.at("packing_contrast")) / off.at("packing_spread"), 1.0);
    return t.finish();
}
