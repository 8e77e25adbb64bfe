// Scene kinds of the granular flow solver (Sect. 2.1; keys in docs/scenes.md):
//   bed-at-rest     a bed settling under gravity in a box (or a column)
//   simple-shear    homogeneous simple shear between moving walls (eq. 45)
//   inclined-plane  a layer on a rough inclined plane, periodic along the slope
//   tumbler-flow    the rotating drum of Sect. 4.2 without segregation
// Each reads [material] (closures) and [flow] (solver settings).
#pragma once

#include "drum/drum.hpp"
#include "flow/flow_solver.hpp"
#include "scenes/scene_kind.hpp"

namespace granseg {

/// Reads the optional [flow] section: time_stepping, viscosity, cfl, T_floor, Phi_vacuum, dt_min, dt_max and, if `mixture`,
/// phi_hat (a scene whose mixture comes from elsewhere leaves it out, so the key is rejected); a key
/// the scene leaves out keeps its value in `defaults` (the coupled drum's dt_max is its own).
FlowSettings read_flow_settings(const SceneFile& scene, bool mixture = true, const FlowSettings& defaults = FlowSettings{});

/// The [drum] keys of tumbler-flow and tumbler (docs/scenes.md).
DrumSpec read_drum(const SceneFile& scene);

/// The [run] keys of tumbler-flow and tumbler.
DrumRun read_drum_run(const SceneFile& scene);

std::unique_ptr<SceneJob> prepare_bed_at_rest(const SceneFile& scene);
std::unique_ptr<SceneJob> prepare_simple_shear(const SceneFile& scene);
std::unique_ptr<SceneJob> prepare_inclined_plane(const SceneFile& scene);
std::unique_ptr<SceneJob> prepare_tumbler_flow(const SceneFile& scene);

}  // namespace granseg
