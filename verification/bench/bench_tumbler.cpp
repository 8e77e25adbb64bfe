// The acceptance run of the flow solver: the tumbler-flow scene (Sect. 4.2 without segregation,
// verification/scenes/tumbler_flow.toml: 100 cells per diameter, 25 s) in both time-stepping
// modes, kRuns times each on 2 OpenMP threads. Reports per mode the median wall time (with the
// load average before and after each run), the steps, the dynamic angle of repose and the
// flowing-layer thickness at 25 s (the depth, below the highest bed point along the surface
// normal, to which the bed within 0.4 R of the axis moves faster than 5 % of the wall speed
// relative to the drum), or the message a run stopped with; writes the explicit run's fields and
// history for figures/bench_tumbler.gp and its VTK files below DIR/tumbler_flow/vtk (the
// semi-implicit run's below DIR/tumbler_flow_semi_implicit).
// Long (minutes per run): part of `make bench`, not of `make verify`.
//
// Run: build/bench/bench_tumbler [--data DIR]
#include "core/error.hpp"
#include "core/output.hpp"
#include "flow/flow_settings.hpp"
#include "harness/program.hpp"
#include "scenes/scene_kind.hpp"

#include <omp.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

using namespace granseg;

namespace {

constexpr int kRuns = 3;
constexpr const char* kScene = "verification/scenes/tumbler_flow.toml";
constexpr double kRadius = 0.05, kOmega = 2.0 * M_PI * 0.1;

std::string load_average() {
    std::ifstream in("/proc/loadavg");
    std::string a, b, c;
    in >> a >> b >> c;
    return a + " " + b + " " + c;
}

/// The flowing-layer thickness (m) from fields_lab.dat (x z Phi u_x u_y u_z T p inside) and the
/// surface angle (deg): see the header comment.
double layer_thickness(const std::string& dir, double angle_deg) {
    const double angle = angle_deg * M_PI / 180.0, nx = -std::sin(angle), nz = std::cos(angle);
    const auto fields = verify::read_rows(dir + "/fields_lab.dat");
    double top = -INFINITY;
    for (const auto& r : fields)
        if (r[8] > 0.5 && r[2] > 0.3) top = std::max(top, r[0] * nx + r[1] * nz);
    double depth = 0.0;
    for (const auto& r : fields) {
        if (r[8] < 0.5 || r[2] < 0.3) continue;
        const double along = r[0] * nz - r[1] * nx;  // coordinate along the surface line
        const double speed = std::hypot(r[3] + kOmega * r[1], r[5] - kOmega * r[0]);
        if (std::fabs(along) < 0.4 * kRadius && speed > 0.05 * kOmega * kRadius)
            depth = std::max(depth, top - (r[0] * nx + r[1] * nz));
    }
    return depth;
}

/// The scene file with [flow] time_stepping set to `mode`.
std::string scene_in_mode(TimeStepping mode) {
    std::ifstream in(kScene);
    std::ostringstream text;
    for (std::string line; std::getline(in, line);) {
        text << line << "\n";
        if (line == "[flow]") text << "time_stepping = \"" << choice_name(kTimeSteppings, mode) << "\"\n";
    }
    return text.str();
}

}  // namespace

int main(int argc, char** argv) {
    const auto options = verify::parse_program_options(argc, argv);
    omp_set_num_threads(2);
    DataTable table({"semi_implicit", "run", "wall_seconds", "steps", "angle_mean_deg", "angle_std_deg", "layer_thickness_m"});
    table.comment("tumbler-flow, 100 cells per diameter, 25 s, 2 threads; a run that stopped has NaN angle and thickness");
    for (const TimeStepping mode : {TimeStepping::explicit_waves, TimeStepping::semi_implicit}) {
        const std::string name = choice_name(kTimeSteppings, mode);
        const bool semi = mode == TimeStepping::semi_implicit;
        const std::string dir = options.data_dir + (semi ? "/tumbler_flow_semi_implicit" : "/tumbler_flow");
        const std::string scene = dir + ".toml";
        write_file_atomically(scene, scene_in_mode(mode));
        std::vector<double> seconds;
        for (int run = 0; run < kRuns; ++run) {
            const std::string before = load_average();
            const auto t0 = std::chrono::steady_clock::now();
            std::string stopped;
            try {
                run_scene_file(scene, dir);
            } catch (const InvariantError& e) {
                stopped = e.what();
            }
            seconds.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
            double steps = NAN, angle = NAN, spread = NAN, thickness = NAN;
            if (stopped.empty()) {
                const auto summary = verify::read_rows(dir + "/summary.dat");  // t_end steps angle_mean angle_std samples mass_change
                steps = summary[0][1], angle = summary[0][2], spread = summary[0][3];
                thickness = layer_thickness(dir, verify::read_rows(dir + "/history.dat").back()[2]);
            }
            table.row({semi ? 1.0 : 0.0, static_cast<double>(run), seconds.back(), steps, angle, spread, thickness});
            std::printf("%s run %d: %.1f s wall on 2 threads (load average before: %s, after: %s): %s\n", name.c_str(), run,
                        seconds.back(), before.c_str(), load_average().c_str(),
                        stopped.empty() ? ("steps " + std::to_string(static_cast<long>(steps)) + ", angle of repose " +
                                           std::to_string(angle) + " +- " + std::to_string(spread) + " deg, layer " +
                                           std::to_string(1e3 * thickness) + " mm")
                                              .c_str()
                                        : ("stopped: " + stopped).c_str());
            std::fflush(stdout);
        }
        std::sort(seconds.begin(), seconds.end());
        std::printf("%s: median wall time %.1f s over %d runs\n", name.c_str(), seconds[kRuns / 2], kRuns);
    }
    verify::write_data(options, "bench_tumbler_times.dat", table);
    return 0;
}
