#include "study/fig7_study.hpp"

#include "core/error.hpp"
#include "core/threads.hpp"
#include "drum/drum.hpp"
#include "harness/named_table.hpp"
#include "harness/program.hpp"
#include "harness/table_provenance.hpp"
#include "harness/time_series.hpp"
#include "run/output.hpp"
#include "scenes/scene_kind.hpp"

#include <toml++/toml.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <sstream>
#include <tuple>
#include <utility>

namespace granseg::verify {

namespace {

constexpr const char* kScene = "verification/scenes/tumbler.toml";

std::string file_text(const std::string& path) {
    std::ifstream in(path);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

bool is_tracer(Fig7Kind k) { return k == Fig7Kind::tracer || k == Fig7Kind::floor; }

/// NAME_nCELLS, a run's name.
std::string cell_name(const char* prefix, int cells) { return std::string(prefix) + "_n" + std::to_string(cells); }

/// The scene text of `run`: the paper's scene with the run's keys changed.
std::string scene_text(const Fig7Run& run, const Fig7Options& o) {
    toml::table scene = toml::parse_file(kScene);
    const auto section = [&](const char* name) -> toml::table& {
        if (!scene.contains(name)) scene.insert(name, toml::table{});
        return *scene[name].as_table();
    };
    section("drum").insert_or_assign("cells_per_diameter", run.cells);
    toml::table& r = section("run");
    r.insert_or_assign("t_end", o.t_end), r.insert_or_assign("angle_from", o.average_from);
    r.insert_or_assign("frames", 0), r.insert_or_assign("vtk", false);
    toml::table& flow = section("flow");
    if (run.explicit_steps)
        flow.insert_or_assign("time_stepping", "explicit");
    else
        flow.insert_or_assign("transport", run.transport);
    flow.insert_or_assign("dt_max", run.dt_max);
    if (!std::isnan(run.acoustic_courant_max)) flow.insert_or_assign("acoustic_courant_max", run.acoustic_courant_max);
    if (run.kind == Fig7Kind::floor) flow.insert_or_assign("T_floor", o.T_floor_low);
    if (!run.packing_feedback) section("coupling").insert_or_assign("packing_feedback", false);
    if (!std::isnan(run.S)) section("segregation").insert_or_assign("S", run.S);
    if (run.min_shear_rate > 0) section("segregation").insert_or_assign("diagnostic_min_shear_rate", run.min_shear_rate);
    if (is_tracer(run.kind)) {
        // The tracer fills the drum's own core at that grid: r < d - layer, the layer measured by
        // the reference transport's grid run of the same cells (run before the tracer runs).
        const std::string grid_run = o.data_dir + "/" + o.study_dir + "/" + cell_name(o.transports.front().c_str(), run.cells);
        const NamedTable grid_summary = read_named(grid_run + "/summary.dat");
        const double r_core = grid_summary.at(grid_summary.last(), "r_core_layer");
        char expression[96];
        std::snprintf(expression, sizeof expression, "sqrt(x^2 + z^2) < %.17g ? 1 : 0", r_core);
        section("initial").insert_or_assign("tracer", std::string(expression));
    }
    std::ostringstream text;
    text << "# " << o.program << ": " << kScene << " as run " << run.name << "\n" << scene << "\n";
    return text.str();
}

/// A dt factor in a run's name: 0.5 -> "0.5", 0.25 -> "0.25".
std::string fig7_factor(double f) {
    char s[32];
    std::snprintf(s, sizeof s, "%g", f);
    return s;
}

}  // namespace

const std::array<Fig7Quantity, kFig7Quantities>& fig7_quantities() {
    // Ranges: an angle of repose between 0 and 90 deg, a thickness >= 0, the index (a standard
    // deviation over its largest value) and the shares in [0, 1], a contrast of two Phi in [-1, 1].
    constexpr double kInf = std::numeric_limits<double>::infinity();
    static const std::array<Fig7Quantity, kFig7Quantities> q{{
        {"angle", "dynamic angle of repose", "deg", true, "angle_mean_deg", "surface_angle_deg", 1.0, 0.0, 90.0},
        {"layer", "flowing-layer thickness", "mm", true, "layer_mean", "layer_thickness", 1e3, 0.0, kInf},
        {"index", "segregation index", "-", false, "segregation_index", "segregation_index", 1.0, 0.0, 1.0},
        {"ring", "ring (d - layer <= r < d), small-particle share", "-", false, "ring_layer", "ring_layer", 1.0, 0.0, 1.0},
        {"periphery", "periphery (r >= 0.8 R), small-particle share", "-", false, "periphery_layer", "periphery_layer", 1.0, 0.0,
         1.0},
        {"core", "core (r < d - layer), small-particle share", "-", false, "core_layer", "core_layer", 1.0, 0.0, 1.0},
        {"contrast", "Fig. 7d contrast (Phi mixed - pure)", "-", false, "packing_contrast", "packing_contrast", 1.0, -1.0, 1.0},
        {"axis", "small-particle share within 0.05 D of the axis", "-", false, "axis_layer", "axis_layer", 1.0, 0.0, 1.0},
    }};
    return q;
}

double fig7_scene_number(const char* section, const char* key, double fallback) {
    return toml::parse_file(kScene)[section][key].value_or(fallback);
}

std::vector<Fig7Run> plan_fig7_runs(const Fig7Options& o) {
    std::vector<Fig7Run> runs;
    const std::string& first = o.transports.front();
    const auto add = [&](const std::string& name, Fig7Kind kind, bool explicit_steps, int n, double factor,
                         const std::string& transport) {
        runs.push_back({name, kind, explicit_steps, n, factor, transport, o.dt_max(n, factor)});
    };
    for (const std::string& t : o.transports)
        for (int n : o.cells) add(cell_name(t.c_str(), n), Fig7Kind::grid, false, n, 1.0, t);
    for (int n : o.explicit_cells) add(cell_name("explicit", n), Fig7Kind::grid, true, n, 1.0, "");
    const int coarsest = o.cells.front(), finest = o.cells.back();
    if (o.dt_study) {
        for (double f : o.dt_coarse)
            add(cell_name(first.c_str(), coarsest) + "_dt" + fig7_factor(f), Fig7Kind::dt, false, coarsest, f, first);
        for (double f : o.dt_fine)
            add(cell_name(first.c_str(), finest) + "_dt" + fig7_factor(f), Fig7Kind::dt, false, finest, f, first);
    }
    if (o.core_study) {
        for (int n : o.cells) add(cell_name("tracer", n), Fig7Kind::tracer, false, n, 1.0, first);
        // At the second-finest grid: the floor's part is a difference of two runs at one grid, and
        // the finest grid would double the study's cost.
        const int n = o.cells[o.cells.size() - 2];
        add(cell_name("floor", n), Fig7Kind::floor, false, n, 1.0, first);
    }
    return runs;
}

Fig7Result run_fig7(const Fig7Run& run, const Fig7Options& o) {
    namespace fs = std::filesystem;
    const std::string dir = o.data_dir + "/" + o.study_dir + "/" + run.name, scene_path = dir + ".toml";
    const std::string text = scene_text(run, o);
    // A run is reused only if this build's physics made it: its tables' provenance records say so
    // (harness/table_provenance.hpp).
    const std::string physics_path = dir + "/physics.txt", physics = this_build_physics_line();
    const bool reuse = o.reuse && fs::exists(scene_path) && file_text(scene_path) == text && fs::exists(dir + "/summary.dat") &&
                       fs::exists(physics_path) && file_text(physics_path) == physics;
    if (!reuse) {
        write_file_atomically(scene_path, text);
        const ThreadScope threads(o.threads);
        // A finished run of this scene and build is only written out again, an interrupted one
        // continues from its checkpoint, any other runs from t = 0 (docs/checkpoints.md): a killed study loses at most a
        // checkpoint interval per run.
        run_scene_file(scene_path, dir, Resume::if_compatible);
        write_file_atomically(physics_path, physics);
    }
    Fig7Result r;
    r.run = run;
    const NamedTable summary = read_named(dir + "/summary.dat"), history = read_named(dir + "/history.dat");
    const std::vector<double>& s = summary.last();
    // The run's wall and CPU seconds over all its parts (on one thread its thread's alone: other runs
    // share the process; run/progress.hpp run_cpu_seconds).
    r.wall = summary.at(s, "wall_seconds"), r.cpu = summary.at(s, "cpu_seconds");
    r.steps = summary.at(s, "steps");
    r.dt_max_share = summary.at(s, "steps_dt_max") / r.steps;
    r.acoustic_share = summary.at(s, "steps_acoustic") / r.steps;
    r.dt_mean = summary.at(s, "t_end") / r.steps;
    r.h = fig7_scene_number("drum", "diameter", DrumSpec{}.diameter) / run.cells;
    r.initial_mixture = summary.at(s, "initial_mixture"), r.packing_spread = summary.at(s, "packing_spread");
    const double t_end = summary.at(s, "t_end");
    // A value and its sampling error: the standard error of its time average over t >= average_from,
    // or its jitter over the last jitter_window before t_end.
    const auto read = [&](const char* summary_column, const char* history_column, double scale, bool time_average) {
        std::vector<double> t, v;
        for (const std::vector<double>& row : history.rows) {
            const double ti = history.at(row, "t"), vi = history.at(row, history_column);
            const bool in_window = time_average ? ti >= o.average_from - 1e-9 : ti >= t_end - o.jitter_window - 1e-9;
            if (in_window && std::isfinite(vi)) t.push_back(ti), v.push_back(vi);
        }
        return std::pair{scale * summary.at(s, summary_column),
                         scale * (time_average ? batch_mean_error(v) : detrended_spread(t, v))};
    };
    for (int i = 0; i < kFig7Quantities; ++i) {
        const Fig7Quantity& q = fig7_quantities()[i];
        std::tie(r.value[i], r.sampling[i]) = read(q.summary_column, q.history_column, q.scale, q.time_average);
    }
    if (is_tracer(run.kind)) {
        std::tie(r.tracer, r.tracer_sampling) = read("tracer_core_layer", "tracer_core_layer", 1.0, false);
        std::tie(r.points, r.points_sampling) = read("points_core_layer", "points_core_layer", 1.0, false);
    }
    // A tracer run repeats its grid run: its core column carries the tracer's retained share.
    if (run.kind == Fig7Kind::tracer) r.value[kCore] = r.tracer, r.sampling[kCore] = r.tracer_sampling;
    return r;
}

}  // namespace granseg::verify
