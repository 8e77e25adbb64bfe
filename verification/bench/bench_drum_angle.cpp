// The drum's dynamic angle of repose against resolution, in both time-stepping modes (docs/sect4.2_tumbler.md):
// the tumbler-flow drum of verification/scenes/tumbler_flow.toml (25 s, angle averaged from 10 s)
// at kRuns' cells per diameter, modes and dt_max: side by side, one per core, on one thread each
// (the default), or one after another on OMP_NUM_THREADS threads when that is set above 1. Per run: steps, wall time, the angle's
// mean and standard deviation over t >= angle_from, the flowing layer's mean thickness, the steps repeated with half the dt, the
// kinetic energy (relative to the drum) over t >= angle_from as min/mean and
// max/mean (a rolling drum keeps both near 1; a slumping one falls by orders of magnitude between
// avalanches), and the friction angle atan(mu) of the scene's material (Material::shear_friction,
// eq. 45 balance; docs/flow_solver.md Sect. 1). At the end, from each mode's runs at dt_max 1 ms:
// the gap between the modes at equal h as a power law C h^p (log-log least squares: if both modes
// discretise the same equations the gap vanishes with h, p > 0 is its observed order), and each
// mode's angle as a + b h^p with that p (a: a reading of the h -> 0 limit, for both modes the same
// if the gap's power law holds). Writes the gaps to bench_drum_angle_gap.dat.
// The one check: mass to round-off in every run. The angles are reported, never asserted: this
// study measures what the drum's angle is at the resolutions we can afford (docs/sect4.2_tumbler.md
// and docs/history.md, flow solver).
// Writes DIR/drum_angle/<run>/ (each run's scene and files) and bench_drum_angle.dat for
// figures/full_drum_angle.gp.
//
// Run: build/bench/bench_drum_angle [--data DIR]   (long: over an hour on one thread, most of it
// the 100-cell explicit run, whose steps follow the sound speed)
#include "closures/packing.hpp"
#include "core/threads.hpp"
#include "flow/time_step.hpp"
#include "harness/check_table.hpp"
#include "harness/program.hpp"
#include "harness/side_by_side.hpp"
#include "scenes/material_section.hpp"
#include "scenes/scene_kind.hpp"

#include <toml++/toml.h>

#include <algorithm>
#include <cfloat>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <iterator>
#include <sstream>
#include <string>
#include <vector>

using namespace granseg;
using granseg::verify::CheckTable;

namespace {

constexpr const char* kScene = "verification/scenes/tumbler_flow.toml";

struct Run {
    int cells;         // cells per diameter
    const char* mode;  // [flow] time_stepping
    double dt_max;     // s, [flow] dt_max (1e-3 is the default; binds only the semi-implicit step)
};
// Explicit up to 100 cells (the paper's resolution); semi-implicit up to 100 at the
// default dt_max, at 32 cells with a tenth of it, and at 50 and 100 cells from 0.25 to 4 ms: what a
// longer (cheaper) step costs in angle and layer thickness.
constexpr Run kRuns[] = {
    {32, "explicit", 1e-3},      {50, "explicit", 1e-3},        {64, "explicit", 1e-3},       {100, "explicit", 1e-3},
    {32, "semi-implicit", 1e-3}, {50, "semi-implicit", 1e-3},   {64, "semi-implicit", 1e-3},  {100, "semi-implicit", 1e-3},
    {32, "semi-implicit", 1e-4}, {50, "semi-implicit", 2.5e-4}, {50, "semi-implicit", 5e-4},  {50, "semi-implicit", 2e-3},
    {50, "semi-implicit", 4e-3}, {100, "semi-implicit", 2e-3},  {100, "semi-implicit", 4e-3},
};

/// The scene `base` with the run's resolution, mode and dt_max, without VTK output, as TOML text.
std::string scene_text(toml::table scene, const Run& r) {
    scene["drum"].as_table()->insert_or_assign("cells_per_diameter", r.cells);
    scene["run"].as_table()->insert_or_assign("vtk", false);
    if (!scene["flow"]) scene.insert("flow", toml::table{});
    scene["flow"].as_table()->insert_or_assign("time_stepping", r.mode);
    scene["flow"].as_table()->insert_or_assign("dt_max", r.dt_max);
    std::ostringstream out;
    out << scene << "\n";
    return out.str();
}

/// From history.dat (t steps angle points flowing max_speed ke mass mass_change dt): the kinetic
/// energy over t >= t0 as min/mean and max/mean, and the largest relative mass change of the run.
struct HistoryRange {
    double ke_min, ke_max, mass_change;
};
HistoryRange history_range(const std::vector<std::vector<double>>& history, double t0) {
    double lo = INFINITY, hi = 0.0, sum = 0.0, mass_change = 0.0;
    int n = 0;
    for (const auto& r : history) {
        mass_change = std::max(mass_change, std::fabs(r[8]));
        if (r[0] < t0) continue;
        lo = std::min(lo, r[6]), hi = std::max(hi, r[6]), sum += r[6], ++n;
    }
    const double mean = sum / n;
    return {lo / mean, hi / mean, mass_change};
}

}  // namespace

int main(int argc, char** argv) {
    const auto options = verify::parse_program_options(argc, argv);
    const ThreadScope scope(std::getenv("OMP_NUM_THREADS") ? 0 : 1);
    const int threads = max_threads();
    // One thread per run: the runs side by side, one per core (the slowest, the 100-cell explicit
    // run, then sets the study's time); more threads per run: one run after another.
    const int lanes = threads == 1 ? verify::machine_cores() : 1;
    const toml::table base = toml::parse_file(kScene);
    const double angle_from = base["run"]["angle_from"].value<double>().value();
    const double diameter = base["drum"]["diameter"].value<double>().value();

    DataTable table;
    table.comment("tumbler-flow drum of " + std::string(kScene) + ", 25 s; angle and kinetic energy over t >= " +
                  verify::format(angle_from) + " s; " + std::to_string(threads) + " OpenMP thread(s) per run, " +
                  std::to_string(lanes) + " run(s) side by side; load average at start " + verify::load_average());
    table.comment("semi_implicit: 0 explicit, 1 semi-implicit; h = D / cells");
    std::vector<double> h[2], angle[2];  // per mode, dt_max 1 ms: for the first-order extrapolation h -> 0
    double friction = NAN;
    CheckTable checks("Drum angle of repose against resolution, both time-stepping modes (tumbler_flow.toml, 25 s)");
    auto run_dir = [&](const Run& r) {
        return options.data_dir + "/drum_angle/" + std::string(r.mode) + "_" + std::to_string(r.cells) + "_dt" +
               verify::format(r.dt_max);
    };
    constexpr int kJobs = static_cast<int>(std::size(kRuns));
    double walls[kJobs];
    const auto start = std::chrono::steady_clock::now();
    verify::run_side_by_side(kJobs, lanes, [&](int j) {
        const std::string dir = run_dir(kRuns[j]);
        write_file_atomically(dir + ".toml", scene_text(base, kRuns[j]));
        // A run that finished is only written out again, an interrupted one resumes (docs/checkpoints.md); its wall time covers
        // all its parts.
        run_scene_file(dir + ".toml", dir, Resume::if_compatible);
        walls[j] = verify::last_row(dir + "/summary.dat").at("wall_seconds");
        std::fprintf(stderr, "bench_drum_angle: %s done in %.0f s\n", dir.c_str(), walls[j]);
    });
    checks.note("all runs: " + verify::format(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count()) +
                " s wall");
    for (int j = 0; j < kJobs; ++j) {
        const Run& r = kRuns[j];
        const std::string dir = run_dir(r), tag = dir.substr(dir.rfind('/') + 1);
        const double wall = walls[j];

        const Material m = read_material(SceneFile::load(dir + ".toml"));
        friction = std::atan(m.shear_friction()) * 180.0 / M_PI;
        // t_end steps angle_mean angle_std samples mass_change layer_mean layer_std steps_X (6 bounds) ...
        const auto s = verify::read_rows(dir + "/summary.dat")[0];
        const auto history = history_range(verify::read_rows(dir + "/history.dat"), angle_from);
        const bool is_explicit = std::string(r.mode) == "explicit";
        const double h_mm = 1e3 * diameter / r.cells;
        table.row({{"cells", double(r.cells)},
                   {"semi_implicit", is_explicit ? 0.0 : 1.0},
                   {"dt_max", r.dt_max},
                   {"h_mm", h_mm},
                   {"steps", s[1]},
                   {"wall_s", wall},
                   {"angle_mean_deg", s[2]},
                   {"angle_std_deg", s[3]},
                   {"ke_min_over_mean", history.ke_min},
                   {"ke_max_over_mean", history.ke_max},
                   {"friction_deg", friction},
                   {"layer_mm", 1e3 * s[6]},
                   {"steps_halved", s[8 + static_cast<int>(StepBound::halved)]}});
        checks.note(tag + ": " + verify::format(s[1]) + " steps, " + verify::format(wall) + " s wall; angle " +
                    verify::format(s[2]) + " +- " + verify::format(s[3]) + " deg (friction angle " + verify::format(friction) +
                    "); layer " + verify::format(1e3 * s[6]) + " mm; kinetic energy min/mean " + verify::format(history.ke_min) +
                    ", max/mean " + verify::format(history.ke_max));
        // Mass is conserved to round-off: at most one unit of round-off per step (as verify_flow_tumbler).
        checks.at_most(tag + ": relative mass change", history.mass_change, s[1] * DBL_EPSILON);
        if (r.dt_max == 1e-3) h[is_explicit ? 0 : 1].push_back(h_mm), angle[is_explicit ? 0 : 1].push_back(s[2]);
        std::fflush(stdout);
    }
    // The gap between the modes at the resolutions both ran, and its power law C h^p.
    DataTable gaps;
    std::vector<double> log_h, log_gap;
    for (std::size_t i = 0; i < h[0].size(); ++i)
        for (std::size_t j = 0; j < h[1].size(); ++j)
            if (h[0][i] == h[1][j]) {
                const double gap = angle[0][i] - angle[1][j];
                gaps.row(
                    {{"h_mm", h[0][i]}, {"explicit_deg", angle[0][i]}, {"semi_implicit_deg", angle[1][j]}, {"gap_deg", gap}});
                if (gap > 0.0) log_h.push_back(std::log(h[0][i])), log_gap.push_back(std::log(gap));
            }
    if (log_h.size() < 2) return checks.finish();  // no power law through fewer than two positive gaps
    const Polynomial power = fit_polynomial(log_h, log_gap, 1);
    const double p = power.c[1];
    const std::string law = "gap explicit - semi-implicit = " + verify::format(std::exp(power.c[0])) + " deg h^" +
                            verify::format(p) + " (h in mm; log-log least squares over " + std::to_string(log_h.size()) +
                            " resolutions)";
    gaps.comment(law);
    table.comment(law);
    checks.note(law);
    // Each mode as a + b h^p with the gap's order: a is a reading of the continuum angle.
    for (int mode = 0; mode < 2; ++mode) {
        std::vector<double> hp;
        for (double x : h[mode]) hp.push_back(std::pow(x, p));
        const Polynomial fit = fit_polynomial(hp, angle[mode], 1);
        const double a = fit.c[0], b = fit.c[1];
        const std::string text = std::string(mode == 0 ? "explicit" : "semi-implicit (dt_max 1 ms)") +
                                 " runs, least squares angle = " + verify::format(a) + " + " + verify::format(b) + " deg h^" +
                                 verify::format(p) + ": at h = 0 " + verify::format(a) + " deg, " + verify::format(a - friction) +
                                 " deg above the friction angle";
        table.comment(text);
        checks.note(text);
    }
    verify::write_data(options, "bench_drum_angle_gap.dat", gaps);
    verify::write_data(options, "bench_drum_angle.dat", table);
    return checks.finish();
}
