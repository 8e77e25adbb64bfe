#include "run/run_loop.hpp"

namespace granseg {

RunTime run_loop(const RunLoop& loop) {
    RunCheckpoints& saves = checkpoints_or_none(loop.checkpoints);
    const bool resumed = saves.resume(loop.t_end, loop.state);
    if (loop.begin) loop.begin(resumed);
    const auto done = [&] { return loop.done ? loop.done() : loop.time() >= loop.t_end; };
    Progress progress(loop.label, loop.t_end, loop.time());
    while (!done()) {
        if (loop.longest_step) saves.before_step(loop.time(), loop.t_end, loop.longest_step(), loop.state);
        loop.step();
        for (const auto& observe : loop.observers) observe();
        progress.update(loop.time());
        saves.after_step(loop.time(), loop.steps(), loop.state);
    }
    saves.finish(loop.time(), loop.steps(), loop.state);
    return progress.finish(loop.threads) + saves.earlier();
}

}  // namespace granseg
