// The time loop of a flow-alone run (the scene kinds bed-at-rest, simple-shear, inclined-plane,
// tumbler-flow, and the verification programs): run/run_loop.hpp configured with the flow
// solver's step and its mass invariant.
//
//   solves      nothing new: steps a FlowSolver to t_end
//   inputs      the solver, t_end, what to record after each step, the checkpoints
//   outputs     the run's cost (RunTime)
//   invariants  the total mass drifts by less than kMassDriftLimit (InvariantError otherwise)
#pragma once

#include "flow/flow_solver.hpp"
#include "run/run_loop.hpp"

#include <functional>
#include <string>

namespace granseg {

/// Relative change of the total mass that breaks the mass invariant: each step rounds every
/// cell's update once (relative error <= 2^-53 of Phi), so after n steps the drift is below
/// n * 2^-53 * (cells * max Phi / mass); runs of up to 10^7 steps stay far below 1e-8.
constexpr double kMassDriftLimit = 1e-8;

/// Steps `solver` to t_end (run_loop, progress labelled `label`), calling `record` (if given) at
/// a fresh start and after every step, and throwing InvariantError if the mass drifts by more
/// than kMassDriftLimit. With `checkpoints`, resumes `state` (the solver and what `record` keeps)
/// and writes its checkpoints. Returns the run's wall and CPU seconds (with those before a
/// resume) and its threads.
RunTime run_flow(FlowSolver& solver, double t_end, const std::string& label, const std::function<void()>& record = {},
                 RunCheckpoints* checkpoints = nullptr, const RunState& state = {});

}  // namespace granseg
