// Benchmark of the flow solver on the tumbler-flow drum (Sect. 4.2 set-up), both time-stepping
// modes: for 50, 100 and 200 cells per diameter and 1 and 2 OpenMP threads, a window of steps from
// the initial state (a bed at rest in the turning drum, before the first avalanche): the time
// step, steps and wall time per second of drum time, ns per cell and step, the shares of the
// phases, and for the semi-implicit mode the Newton steps per pressure solve and the
// conjugate-gradient iterations per Newton step; and the ratio of the modes' wall time per drum
// second. Medians of kRuns runs; reports, never asserts. The explicit step is set by the sound
// speed of the resting bed, which the window already has; the semi-implicit step reaches dt_max
// after its start-up (docs/flow_solver_choices.md, "Cost of a step").
// Writes bench_flow.dat for figures/bench_flow.gp.
//
// Run: build/bench/bench_flow [--data DIR]   (a few minutes; timings are noisy on a shared machine)
#include "closures/closures.hpp"
#include "core/threads.hpp"
#include "drum/bed.hpp"
#include "flow/flow_solver.hpp"
#include "harness/program.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <string>
#include <vector>

using namespace granseg;

namespace {

constexpr int kRuns = 5;
constexpr double kRadius = 0.05, kFillHeight = 0.075, kRunLength = 25.0;
constexpr int kWarmUp = 20;  // steps before the window: caches, the semi-implicit start-up of dt

struct Sample {
    double seconds, drum_seconds, share[kFlowStages], solves, newton, krylov, temperature;
    std::size_t cells;
    long steps;
};

Sample window(TimeStepping mode, int n, int steps) {
    const Material m = Material::glass_substitute();
    const Grid g = drum_grid(n, kRadius);
    FlowSettings s;
    s.time_stepping = mode;
    Frame f;
    f.omega = 2.0 * M_PI * 0.1;
    FlowSolver solver(g, m, s, f);
    const std::vector<double> Phi = lithostatic_bed(g, m, -kRadius + kFillHeight, f.gravity, s.T_floor,
                                                    m.packing.Phi_rcp(s.phi_hat), m.packing.Phi_co(s.phi_hat));
    const std::vector<double> zero(g.cells(), 0.0), T(g.cells(), s.T_floor);
    solver.set_state(Phi, {zero, zero, zero}, T);
    for (int i = 0; i < kWarmUp; ++i) solver.step();
    const FlowTimers before = solver.timers();
    const FlowCounters counted = solver.counters();
    const double t0 = solver.time();
    const auto start = std::chrono::steady_clock::now();
    for (int i = 0; i < steps; ++i) solver.step();
    Sample r{};
    r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    r.drum_seconds = solver.time() - t0;
    const FlowTimers& after = solver.timers();
    const double total = after.total() - before.total();
    for (int k = 0; k < kFlowStages; ++k) r.share[k] = (after.seconds[k] - before.seconds[k]) / total;
    const FlowCounters& c = solver.counters();
    const double solves = static_cast<double>(c.pressure_solves - counted.pressure_solves);
    r.solves = solves / steps;
    r.newton = solves > 0 ? (c.newton - counted.newton) / solves : 0.0;
    r.krylov = c.newton > counted.newton ? static_cast<double>(c.krylov - counted.krylov) / (c.newton - counted.newton) : 0.0;
    r.temperature = static_cast<double>(c.temperature_iterations - counted.temperature_iterations) / steps;
    r.cells = 0;
    for (std::size_t q = 0; q < g.cells(); ++q) r.cells += g.is_inside(q) ? 1 : 0;
    r.steps = steps;
    return r;
}

}  // namespace

int main(int argc, char** argv) {
    const auto options = verify::parse_program_options(argc, argv);
    DataTable table;
    table.comment(
        "tumbler-flow drum (D = 0.1 m, 75 % fill, 0.1 rps) from its initial state (bed at rest, before the first "
        "avalanche); medians of " +
        std::to_string(kRuns) +
        " windows; ratio: explicit wall per drum second over "
        "this row's (semi-implicit rows)");
    std::printf("%-14s %-6s %-7s %-8s %-9s %-9s %-10s %-10s %-9s %-7s %-7s %-6s\n", "mode", "cells", "threads", "inside",
                "ns/cell", "dt (s)", "steps/s", "wall/s", "25 s (s)", "newton", "krylov", "ratio");
    for (int n : {50, 100, 200}) {
        const int steps = n == 200 ? 100 : 300;
        for (int threads : {1, 2}) {
            const ThreadScope scope(threads);
            double explicit_wall = 0.0;
            for (const TimeStepping mode : {TimeStepping::explicit_waves, TimeStepping::semi_implicit}) {
                std::vector<double> ns, dt, share[kFlowStages], solves, newton, krylov, temperature;
                Sample last{};
                for (int run = 0; run < kRuns; ++run) {
                    last = window(mode, n, steps);
                    ns.push_back(1e9 * last.seconds / (static_cast<double>(last.cells) * last.steps));
                    dt.push_back(last.drum_seconds / last.steps);
                    for (int k = 0; k < kFlowStages; ++k) share[k].push_back(last.share[k]);
                    solves.push_back(last.solves), newton.push_back(last.newton), krylov.push_back(last.krylov);
                    temperature.push_back(last.temperature);
                }
                const double step = verify::median(dt), cost = verify::median(ns) * 1e-9 * last.cells;  // s per step
                const double wall = cost / step, semi = mode == TimeStepping::semi_implicit;
                if (!semi) explicit_wall = wall;
                const double ratio = semi ? explicit_wall / wall : 1.0;
                TableRow row{{"semi_implicit", semi},
                             {"cells_per_diameter", static_cast<double>(n)},
                             {"threads", static_cast<double>(threads)},
                             {"inside_cells", static_cast<double>(last.cells)},
                             {"ns_per_cell_step", verify::median(ns)},
                             {"dt", step},
                             {"steps_per_drum_second", 1.0 / step},
                             {"wall_per_drum_second", wall},
                             {"seconds_for_25s", kRunLength * wall},
                             {"solves_per_step", verify::median(solves)},
                             {"newton_per_solve", verify::median(newton)},
                             {"krylov_per_newton", verify::median(krylov)},
                             {"temperature_cg_per_step", verify::median(temperature)}};
                for (int k = 0; k < kFlowStages; ++k)
                    row.add(std::string("share_") + flow_stage_name(static_cast<FlowStage>(k)), verify::median(share[k]));
                row.add("ratio_explicit_to_semi", ratio);
                table.row(row);
                std::printf("%-14s %-6d %-7d %-8zu %-9.0f %-9.3g %-10.4g %-10.3g %-9.3g %-7.2f %-7.1f %-6.2f\n",
                            choice_name(kTimeSteppings, mode).c_str(), n, threads, last.cells, verify::median(ns), step,
                            1.0 / step, wall, kRunLength * wall, verify::median(newton), verify::median(krylov), ratio);
                std::fflush(stdout);
            }
        }
    }
    verify::write_data(options, "bench_flow.dat", table);
    return 0;
}
