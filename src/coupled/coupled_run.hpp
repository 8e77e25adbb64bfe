// The coupled drum's run, shared by the scene kind "tumbler" and verify_tumbler, and the files it
// writes (docs/scenes.md): run/run_loop.hpp configured with the coupled step and what it records.
// The flow is stepped exactly as tumbler-flow steps it (its own dt, up to t_end), so with S = 0 the
// two runs take the same steps (verify_tumbler). Every step takes its segregation sub-step
// (coupled_tumbler.hpp); every kDrumHistoryInterval of time a history row is recorded and the
// invariants are checked (InvariantError, exit 3):
//   - the amount of each phase, sum of phi and sum of Phi - phi over the drum, stays within
//     kAmountTolerance of the whole amount at the start, sum of Phi (both move only by face
//     fluxes that telescope; measured against the whole, since a phase may start empty);
//   - 0 <= phi <= Phi: the bulk step (CoupledTumbler) and the segregation sub-step
//     (SegregationSolver) may clip only round-off, kBoundRoundOff Phi, checked at every step.
//
//   solves      nothing new: runs CoupledTumbler in time and writes its files
//   inputs      the tumbler, CoupledRunOptions (t_end, snapshots, frames, the pattern regions)
//   outputs     the OutputSet of the scene (history, summary, fields, frames)
//   invariants  the list above, checked while it runs
#pragma once

#include "coupled/coupled_tumbler.hpp"
#include "drum/pattern_metrics.hpp"
#include "run/output.hpp"
#include "run/run_checkpoints.hpp"

#include <functional>

namespace granseg {

struct CoupledRunOptions {
    DrumRun run;             // t_end, VTK snapshots, angle of repose
    int frames = 50;         // phi_hat frames of the animation after t = 0 (0: none)
    PatternRegions regions;  // with bed_level: the free surface's level
};

/// The regions of the pattern metrics for `drum` with the material's surface level: those of the
/// kinematic drum (drum_regions with delta0 = kLayerShare D), so the two drums compare directly.
PatternRegions coupled_regions(const DrumSpec& drum, double bed_level);

/// Share of the diameter taken as the flowing layer's thickness at the middle of the surface:
/// 8 mm in the Sect. 4.2 drum, the kinematic drum's delta0 (assumption K2; C4).
constexpr double kLayerShare = 0.08;

/// Radius, as a share of the diameter, of the region around the axis whose small-particle share
/// (mass-weighted phi_hat of its bed cells) history.dat and summary.dat report as `axis`: the
/// innermost part of the core, which the core metric averages with the rest of it.
constexpr double kAxisShare = 0.05;

/// Observer called after every coupled step (for checks beyond the built-in invariants).
using CoupledStepObserver = std::function<void(const CoupledTumbler& tumbler)>;

/// Runs `tumbler` from t = 0 to options.run.t_end and returns its files: history.dat, summary.dat
/// (the angle and the flowing layer's thickness averaged over t >= angle_from, the pattern metrics,
/// axis share, the drum's own regions (layer_regions.hpp) and Fig. 7d contrast at t_end),
/// initial_lab.dat and fields_lab.dat (coupled_field_table at t = 0 and t_end), frames/frame_NNN.dat,
/// vtk/tumbler_NNNN.vtk.
/// With `checkpoints`, the run writes and resumes checkpoints of the tumbler and of what it has
/// recorded (run/run_checkpoints.hpp).
OutputSet run_coupled_tumbler(CoupledTumbler& tumbler, const CoupledRunOptions& options, const CoupledStepObserver& observer = {},
                              RunCheckpoints* checkpoints = nullptr);

}  // namespace granseg
