// The drum's dynamic angle of repose against resolution, in both time-stepping modes (issue 12):
// the tumbler-flow drum of verification/scenes/tumbler_flow.toml (25 s, angle averaged from 10 s)
// at kRuns' cells per diameter, modes and dt_max, one after another on OMP_NUM_THREADS threads
// (default 1). Per run: steps, wall time, the angle's mean and standard deviation over
// t >= angle_from, the kinetic energy (relative to the drum) over t >= angle_from as min/mean and
// max/mean (a rolling drum keeps both near 1; a slumping one falls by orders of magnitude between
// avalanches), and the friction angle atan(mu) of the scene's material (Material::shear_friction,
// eq. 45 balance; docs/flow_solver.md Sect. 1); at the end the least-squares line angle = a + b h
// through each mode's runs at dt_max 1 ms (a first-order scheme's error; a is a reading of its
// h -> 0 limit).
// The one check: mass to round-off in every run. The angles are reported, never asserted: this
// study measures what the drum's angle is at the resolutions we can afford (docs/flow_solver.md
// Sect. 11, "The angle against the cell size").
// Writes DIR/drum_angle/<run>/ (each run's scene and files) and bench_drum_angle.dat for
// figures/full_drum_angle.gp.
//
// Run: build/bench/bench_drum_angle [--data DIR]   (long: 41 minutes on one thread of the shared
// machine on 2 December 2026, 18 of them the 100-cell explicit run)
#include "closures/packing.hpp"
#include "harness/check_table.hpp"
#include "harness/program.hpp"
#include "scenes/material_section.hpp"
#include "scenes/scene_kind.hpp"

#include <omp.h>
#include <toml++/toml.h>

#include <algorithm>
#include <cfloat>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <string>
#include <vector>

using namespace granseg;
using granseg::verify::CheckTable;

namespace {

constexpr const char* kScene = "verification/scenes/tumbler_flow.toml";

struct Run {
    int cells;          // cells per diameter
    const char* mode;   // [flow] time_stepping
    double dt_max;      // s, [flow] dt_max (1e-3 is the default; binds only the semi-implicit step)
};
// Explicit up to 100 cells (the resolution of the target); semi-implicit up to 64 at the
// default dt_max, and at 32 and 64 cells with a tenth of it, to separate the time step's share.
constexpr Run kRuns[] = {
    {32, "explicit", 1e-3},      {50, "explicit", 1e-3},      {64, "explicit", 1e-3},
    {100, "explicit", 1e-3},     {32, "semi-implicit", 1e-3}, {50, "semi-implicit", 1e-3},
    {64, "semi-implicit", 1e-3}, {100, "semi-implicit", 1e-3}, {32, "semi-implicit", 1e-4},
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
    if (!std::getenv("OMP_NUM_THREADS")) omp_set_num_threads(1);
    const int threads = omp_get_max_threads();
    const toml::table base = toml::parse_file(kScene);
    const double angle_from = base["run"]["angle_from"].value<double>().value();
    const double diameter = base["drum"]["diameter"].value<double>().value();

    DataTable table({"cells", "semi_implicit", "dt_max", "h_mm", "steps", "wall_s", "angle_mean_deg", "angle_std_deg",
                     "ke_min_over_mean", "ke_max_over_mean", "friction_deg"});
    table.comment("tumbler-flow drum of " + std::string(kScene) + ", 25 s; angle and kinetic energy over t >= " +
                  verify::format(angle_from) + " s; " + std::to_string(threads) + " OpenMP thread(s); load average at start " +
                  verify::load_average());
    table.comment("semi_implicit: 0 explicit, 1 semi-implicit; h = D / cells");
    std::vector<double> h[2], angle[2];  // per mode, dt_max 1 ms: for the first-order extrapolation h -> 0
    double friction = NAN;
    CheckTable checks("Drum angle of repose against resolution, both time-stepping modes (tumbler_flow.toml, 25 s)");
    for (const Run& r : kRuns) {
        const std::string tag = std::string(r.mode) + "_" + std::to_string(r.cells) + "_dt" + verify::format(r.dt_max);
        const std::string dir = options.data_dir + "/drum_angle/" + tag;
        write_file_atomically(dir + ".toml", scene_text(base, r));
        const auto t0 = std::chrono::steady_clock::now();
        run_scene_file(dir + ".toml", dir);
        const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();

        const Material m = read_material(SceneFile::load(dir + ".toml"));
        friction = std::atan(m.shear_friction()) * 180.0 / M_PI;
        const auto s = verify::read_rows(dir + "/summary.dat")[0];  // t_end steps angle_mean angle_std samples mass_change
        const auto history = history_range(verify::read_rows(dir + "/history.dat"), angle_from);
        const bool is_explicit = std::string(r.mode) == "explicit";
        const double h_mm = 1e3 * diameter / r.cells;
        table.row({double(r.cells), is_explicit ? 0.0 : 1.0, r.dt_max, h_mm, s[1], wall, s[2], s[3], history.ke_min,
                   history.ke_max, friction});
        verify::write_data(options, "bench_drum_angle.dat", table);  // after every run: a long study keeps what it has
        checks.note(tag + ": " + verify::format(s[1]) + " steps, " + verify::format(wall) + " s wall; angle " +
                    verify::format(s[2]) + " +- " + verify::format(s[3]) + " deg (friction angle " + verify::format(friction) +
                    "); kinetic energy min/mean " + verify::format(history.ke_min) + ", max/mean " + verify::format(history.ke_max));
        // Mass is conserved to round-off: at most one unit of round-off per step (as verify_flow_tumbler).
        checks.at_most(tag + ": relative mass change", history.mass_change, s[1] * DBL_EPSILON);
        if (r.dt_max == 1e-3) h[is_explicit ? 0 : 1].push_back(h_mm), angle[is_explicit ? 0 : 1].push_back(s[2]);
        std::fflush(stdout);
    }
    // A first-order scheme's error is a + b h for small h: the line through each mode's runs and
    // its value at h = 0 are a reading of the continuum angle, not a measurement of it.
    for (int mode = 0; mode < 2; ++mode) {
        const Polynomial line = fit_polynomial(h[mode], angle[mode], 1);
        const double a = line.c[0], b = line.c[1];
        const std::string fit = std::string(mode == 0 ? "explicit" : "semi-implicit (dt_max 1 ms)") +
                                " runs, least-squares line angle = " + verify::format(a) + " + " + verify::format(b) +
                                " deg/mm h: at h = 0 " + verify::format(a) + " deg, " + verify::format(a - friction) +
                                " deg above the friction angle";
        table.comment(fit);
        checks.note(fit);
    }
    verify::write_data(options, "bench_drum_angle.dat", table);
    return checks.finish();
}
