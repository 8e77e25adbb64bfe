// Benchmark of the flow solver on the tumbler-flow drum (Sect. 4.2 set-up): for 50, 100 and 200
// cells per diameter and 1 and 2 OpenMP threads, the cost of a window of steps from the initial
// state (the time step is set by the sound speed of the static bed, which the window already has):
// cell updates per second (inside cells times steps per second), the time step, the steps a
// 25 s run needs at that step, and the shares of closures, convection (fluxes, update, time step),
// implicit viscosity and temperature. Medians of kRuns runs; reports, never asserts.
// Writes bench_flow.dat for figures/bench_flow.gp.
//
// Run: build/bench/bench_flow [--data DIR]   (about a minute; timings are noisy on a shared machine)
#include "closures/closures.hpp"
#include "flow/bed.hpp"
#include "flow/flow_solver.hpp"
#include "harness/program.hpp"

#include <omp.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <vector>

using namespace granseg;

namespace {

constexpr int kRuns = 5;
constexpr double kRadius = 0.05, kFillHeight = 0.075, kRunLength = 25.0;

struct Sample {
    double seconds, dt, closures, convection, viscosity, temperature;
    std::size_t cells;
    long steps;
};

Sample window(int n, int steps) {
    const Material m = Material::glass_substitute();
    const Grid g = drum_grid(n, kRadius);
    FlowSettings s;
    Frame f;
    f.omega = 2.0 * M_PI * 0.1;
    FlowSolver solver(g, m, s, f);
    const std::vector<double> Phi = lithostatic_bed(g, m, -kRadius + kFillHeight, f.gravity, s.T_floor,
                                                    m.packing.Phi_rcp(s.phi_hat), m.packing.Phi_co(s.phi_hat));
    const std::vector<double> zero(g.cells(), 0.0), T(g.cells(), s.T_floor);
    solver.set_state(Phi, {zero, zero, zero}, T);
    for (int i = 0; i < 5; ++i) solver.step();  // warm-up: caches, page faults, thread pool
    const FlowTimers before = solver.timers();
    const auto t0 = std::chrono::steady_clock::now();
    for (int i = 0; i < steps; ++i) solver.step();
    Sample r;
    r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    const FlowTimers& after = solver.timers();
    r.closures = after.closures - before.closures, r.convection = after.convection - before.convection;
    r.viscosity = after.viscosity - before.viscosity, r.temperature = after.temperature - before.temperature;
    r.dt = solver.last_dt();
    r.cells = 0;
    for (std::size_t c = 0; c < g.cells(); ++c) r.cells += g.is_inside(c) ? 1 : 0;
    r.steps = steps;
    return r;
}

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v[v.size() / 2];
}

}  // namespace

int main(int argc, char** argv) {
    const auto options = verify::parse_program_options(argc, argv);
    DataTable table({"cells_per_diameter", "threads", "inside_cells", "Mcell_updates_per_s", "dt", "steps_for_25s",
                     "seconds_for_25s", "share_closures", "share_convection", "share_viscosity", "share_temperature"});
    table.comment("tumbler-flow drum (D = 0.1 m, 75 % fill, 0.1 rps) from its initial state; medians of " +
                  std::to_string(kRuns) + " runs; seconds_for_25s = steps_for_25s / (steps per second)");
    std::printf("%-6s %-7s %-8s %-12s %-10s %-10s %-11s %-8s %-8s %-8s %-8s\n", "cells", "threads", "inside",
                "Mcell-upd/s", "dt (s)", "steps 25s", "est. 25s (s)", "closure", "convect", "viscous", "temper");
    for (int n : {50, 100, 200}) {
        const int steps = n == 200 ? 100 : 400;
        for (int threads : {1, 2}) {
            omp_set_num_threads(threads);
            std::vector<double> rate, share[4];
            Sample last{};
            for (int run = 0; run < kRuns; ++run) {
                last = window(n, steps);
                rate.push_back(last.cells * static_cast<double>(last.steps) / last.seconds / 1e6);
                const double total = last.closures + last.convection + last.viscosity + last.temperature;
                share[0].push_back(last.closures / total), share[1].push_back(last.convection / total);
                share[2].push_back(last.viscosity / total), share[3].push_back(last.temperature / total);
            }
            const double r = median(rate), steps25 = kRunLength / last.dt;
            const double seconds25 = steps25 * last.cells / (r * 1e6);
            table.row({static_cast<double>(n), static_cast<double>(threads), static_cast<double>(last.cells), r, last.dt,
                       steps25, seconds25, median(share[0]), median(share[1]), median(share[2]), median(share[3])});
            std::printf("%-6d %-7d %-8zu %-12.3g %-10.3g %-10.3g %-11.3g %-8.2f %-8.2f %-8.2f %-8.2f\n", n, threads,
                        last.cells, r, last.dt, steps25, seconds25, median(share[0]), median(share[1]), median(share[2]),
                        median(share[3]));
        }
    }
    verify::write_data(options, "bench_flow.dat", table);
    return 0;
}
