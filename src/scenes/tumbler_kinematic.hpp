// Scene kind "tumbler-kinematic": segregation in the drum of Sect. 4.2 on the prescribed
// rolling-regime flow (src/kinematic/kinematic_tumbler.hpp), skipping the flow solver; Fig. 7a-c.
// Keys: docs/scenes.md. Outputs (inertial frame): tumbler_initial.dat, tumbler_final.dat
// (x z phi_hat), tumbler_flow.dat (u, d_s, T, a per bed cell), tumbler_outline.dat,
// tumbler_metrics.dat (pattern metrics over time), tumbler_shells.dat (radial profile) and
// frame_NNN.dat snapshots if [output] frames > 0.
#pragma once

#include "kinematic/kinematic_run.hpp"
#include "kinematic/kinematic_tumbler.hpp"
#include "scenes/scene_kind.hpp"

namespace granseg {

/// Radial shells of tumbler_shells.dat.
constexpr int kTumblerShells = 25;

/// Everything a tumbler-kinematic scene file says, validated (shared with verify_tumbler_kinematic,
/// which runs the scene file of the figures through the same code path).
struct TumblerKinematicScene {
    KinematicTumblerSetup setup;
    KinematicRunOptions run;
};

/// Reads and validates every key of a tumbler-kinematic scene (scene.fail on a bad value).
TumblerKinematicScene read_tumbler_kinematic(const SceneFile& scene);

/// The output files of a finished run.
OutputSet tumbler_kinematic_outputs(const KinematicTumbler& tumbler, const KinematicRunResult& result,
                                    const KinematicRunOptions& run);

std::unique_ptr<SceneJob> prepare_tumbler_kinematic(const SceneFile& scene);

}  // namespace granseg
