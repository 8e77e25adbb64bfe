// Starting a scene from another run's state (docs/scenes.md, "Starting from another run"): a
// tumbler whose flow is the flow of a tumbler-flow (or tumbler) run's checkpoint, with its own
// phi_hat on it, so that a drum's flow can be spun up once and segregation switched on after.
//
//   solves      nothing: finds and checks the source's flow state
//   inputs      the scene's [initial] flow (a checkpoint file), its [drum] keys and t_end
//   outputs     the path of the source; a StateIO at its flow solver's state (run/state_io.hpp)
//   invariants  the source is a whole checkpoint of a tumbler-flow or tumbler run of the same
//               drum (every [drum] key equal) at a time before t_end; else one line naming the key
#pragma once

#include "run/scene_file.hpp"
#include "run/state_io.hpp"

#include <string>

namespace granseg {

/// [initial] flow of a tumbler scene: "" if absent; else the checkpoint's path once it is a
/// checkpoint of a tumbler-flow or tumbler run of the scene's drum, at a time before t_end
/// (scene.fail otherwise). Call after the [drum] keys are read.
std::string read_flow_source(const SceneFile& scene, double t_end);

/// The flow solver's state in the checkpoint at `path` (a tumbler-flow's or a tumbler's): a
/// StateIO whose next member is FlowSolver::checkpoint's first (the rest is not read).
StateIO flow_state_of(const std::string& path);

}  // namespace granseg
