// Scene kind "tumbler": the whole model of Sect. 4.2, flow and segregation coupled in the drum
// (src/coupled/coupled_tumbler.hpp), Fig. 7a-d. Keys: docs/scenes.md; outputs: history.dat,
// summary.dat, initial_lab.dat, fields_lab.dat, frames/frame_NNN.dat, vtk/tumbler_NNNN.vtk
// (src/coupled/coupled_run.hpp).
#pragma once

#include "coupled/coupled_run.hpp"
#include "coupled/coupled_tumbler.hpp"
#include "scenes/scene_kind.hpp"

namespace granseg {

/// Everything a tumbler scene file says, validated (shared with verify_tumbler, which runs its
/// scenes through the same code path).
struct TumblerScene {
    CoupledTumblerSetup setup;
    CoupledRunOptions run;
    std::string flow_from;  // [initial] flow: a checkpoint whose flow the run starts from ("": the bed at rest)
};

/// Reads and validates every key of a tumbler scene (scene.fail on a bad value), including the
/// initial bed: phi_hat in [0, 1] wherever there is material and, with packing feedback, the bed
/// below Phi_rcp(phi_hat) in every cell.
TumblerScene read_tumbler(const SceneFile& scene);

/// Starts `tumbler` (built from scene.setup) from the flow of [initial] flow, if the scene has one
/// (CoupledTumbler::start_from).
void start(CoupledTumbler& tumbler, const TumblerScene& scene);

/// Smallest cells_per_diameter of a tumbler scene: the flowing layer, kLayerShare D thick at the
/// middle of the surface, must span two cells (assumption C4).
int min_tumbler_cells();

std::unique_ptr<SceneJob> prepare_tumbler(const SceneFile& scene);

}  // namespace granseg
