#include "flow/flow_loop.hpp"

#include "core/error.hpp"
#include "core/format.hpp"
#include "core/threads.hpp"

#include <cmath>

namespace granseg {

RunTime run_flow(FlowSolver& solver, double t_end, const std::string& label, const std::function<void()>& record,
                 RunCheckpoints* checkpoints, const RunState& state) {
    double mass0 = 0.0, t0 = 0.0;  // at the start of this process's part of the run
    RunLoop loop;
    loop.label = label, loop.t_end = t_end, loop.checkpoints = checkpoints, loop.state = state;
    loop.time = [&] { return solver.time(); };
    loop.steps = [&] { return solver.steps(); };
    loop.step = [&] { solver.step(t_end); };
    loop.longest_step = [&] { return solver.settings().dt_max; };
    loop.begin = [&](bool resumed) {
        if (!resumed && record) record();
        mass0 = solver.mass(), t0 = solver.time();
    };
    if (record) loop.observers.push_back(record);
    loop.observers.push_back([&] {
        const double drift = std::fabs(solver.mass() - mass0) / mass0;
        if (!(drift <= kMassDriftLimit))
            throw InvariantError(label + ": mass changed by " + format_number(drift) +
                                 " (relative) between t = " + format_number(t0) + " and " + format_number(solver.time()) + " s");
    });
    loop.threads = run_threads(solver.grid().cells());
    return run_loop(loop);
}

}  // namespace granseg
