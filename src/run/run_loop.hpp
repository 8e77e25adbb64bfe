// The one time loop: every scene kind that steps in time (the flow-alone runs, the coupled drum,
// the kinematic drum, the 1-D segregation column) runs through run_loop, configured by what it
// steps, what it records and what it checks (docs/checkpoints.md for the checkpoints).
//
//   solves      nothing: advances a model's steps to t_end
//   inputs      RunLoop: the model's time, steps and one step; observers called after each step
//               (history rows, frames, snapshots, invariant checks); the checkpoints and the
//               state they hold
//   outputs     the run's cost (RunTime, with the seconds before a resume); progress on stderr
//   invariants  those the observers check (they throw InvariantError); a checkpointed run
//               computes the same bits as one without (run/run_checkpoints.hpp)
//
// The choreography, the same for every kind:
//     resume from the checkpoint, or start (a fresh run's first records)
//     while not done: keep the state before a step that may end the run; step; observers;
//                     progress; a checkpoint when due
//     the final checkpoint; the cost
#pragma once

#include "run/progress.hpp"
#include "run/run_checkpoints.hpp"

#include <functional>
#include <string>
#include <vector>

namespace granseg {

struct RunLoop {
    std::string label;  // progress lines ("tumbler: 42% ...")
    double t_end = 0.0;
    std::function<double()> time;  // the model's time
    std::function<long()> steps;   // its steps so far
    std::function<void()> step;    // one step towards t_end, never beyond it
    /// Whether the run has reached its end; empty: time() >= t_end.
    std::function<bool()> done;
    /// The longest step the model may take next: a checkpoint keeps the state before a step that
    /// may end the run (RunCheckpoints::before_step); 0 for a model whose steps land on their
    /// sample times, whose state at t_end is on the path of a longer run.
    std::function<double()> longest_step;
    /// Called after every step, in order: records (history rows, frames, snapshots) and checks.
    std::vector<std::function<void()>> observers;
    /// Called once before the first step: with false for a fresh run (its first records), with
    /// true after a resume (to check that the checkpoint continues this run).
    std::function<void(bool resumed)> begin;
    RunCheckpoints* checkpoints = nullptr;  // none if null
    RunState state;                         // what a checkpoint holds (run/state_io.hpp)
    int threads = 1;                        // the threads the run uses, for its cost
};

/// Runs `loop` to its end (above) and returns the run's cost.
RunTime run_loop(const RunLoop& loop);

}  // namespace granseg
