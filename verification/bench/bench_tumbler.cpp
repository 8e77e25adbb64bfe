// The acceptance run of the flow solver: the tumbler-flow scene (Sect. 4.2 without segregation,
// verification/scenes/tumbler_flow.toml: 100 cells per diameter, 25 s) run kRuns times on 2
// OpenMP threads. Reports the median wall time (with the load average before and after), the
// steps and mean time step, and the dynamic angle of repose; writes the last run's fields and
// history for figures/bench_tumbler.gp and its VTK files below DIR/tumbler_flow/vtk.
// Long (minutes per run): part of `make bench`, not of `make verify`.
//
// Run: build/bench/bench_tumbler [--data DIR]
#include "harness/program.hpp"
#include "scenes/scene_kind.hpp"

#include <omp.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

using namespace granseg;

namespace {

constexpr int kRuns = 3;
constexpr const char* kScene = "verification/scenes/tumbler_flow.toml";

std::string load_average() {
    std::ifstream in("/proc/loadavg");
    std::string a, b, c;
    in >> a >> b >> c;
    return a + " " + b + " " + c;
}

}  // namespace

int main(int argc, char** argv) {
    const auto options = verify::parse_program_options(argc, argv);
    omp_set_num_threads(2);
    std::vector<double> seconds;
    DataTable table({"run", "wall_seconds"});
    for (int run = 0; run < kRuns; ++run) {
        const std::string before = load_average();
        const auto t0 = std::chrono::steady_clock::now();
        run_scene_file(kScene, options.data_dir + "/tumbler_flow");
        seconds.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
        table.row({static_cast<double>(run), seconds.back()});
        std::printf("run %d: %.1f s wall on 2 threads (load average before: %s, after: %s)\n", run, seconds.back(),
                    before.c_str(), load_average().c_str());
        std::fflush(stdout);
    }
    std::vector<double> sorted = seconds;
    std::sort(sorted.begin(), sorted.end());
    table.comment("tumbler-flow, 100 cells per diameter, 25 s, 2 threads; median " + std::to_string(sorted[kRuns / 2]) + " s");
    verify::write_data(options, "bench_tumbler_times.dat", table);
    std::ifstream summary(options.data_dir + "/tumbler_flow/summary.dat");
    std::ostringstream text;
    text << summary.rdbuf();
    std::printf("median wall time %.1f s over %d runs\nlast run's summary:\n%s", sorted[kRuns / 2], kRuns, text.str().c_str());
    return 0;
}
