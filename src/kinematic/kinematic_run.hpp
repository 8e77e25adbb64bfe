// The kinematic drum's run, shared by the tumbler-kinematic scene and verify_tumbler_kinematic:
// run/run_loop.hpp configured with steps of KinematicTumbler::time_step() (shortened to land on
// the sample times) until t_end, the pattern metrics at every sample time, snapshots of phi_hat, and
// the invariants checked while it runs (InvariantError, exit 3):
//   - the amount of small particles (sum of phi over the bed) stays within 1e-12 relative of
//     its start: the mass fluxes are divergence-free and every wall face carries zero flux;
//   - 0 <= phi <= Phi after the bulk step and after the segregation sub-step, up to the
//     round-off allowance kBoundRoundOff Phi (before the solver's guard clips; see invariants.hpp);
//   - every phi finite.
//
//   solves      nothing new: runs KinematicTumbler in time
//   inputs      the tumbler, t_end, the sample and frame counts, the pattern regions
//   outputs     KinematicRunResult: the metrics at every sample time, snapshots of phi_hat, amounts
//   invariants  the list above, checked while it runs
#pragma once

#include "drum/pattern_metrics.hpp"
#include "kinematic/kinematic_tumbler.hpp"
#include "run/run_loop.hpp"
#include "segregation/invariants.hpp"

#include <functional>
#include <vector>

namespace granseg {

struct KinematicRunOptions {
    double t_end = 25.0;  // s
    int samples = 100;    // metric records after t = 0 (every t_end/samples)
    int frames = 0;       // snapshots of phi_hat after t = 0 (every t_end/frames); 0: none
    PatternRegions regions;
};

struct KinematicSample {
    double t = 0;
    PatternMetrics metrics;
    void checkpoint(StateIO& io) { io("t", t)("metrics", metrics); }
};

struct KinematicFrame {
    double t = 0;
    std::vector<double> phi_hat;
    void checkpoint(StateIO& io) { io("t", t)("phi_hat", phi_hat); }
};

struct KinematicRunResult {
    std::vector<KinematicSample> history;  // t = 0 and every sample time
    std::vector<KinematicFrame> frames;    // every frame time (empty if frames = 0)
    std::vector<double> phi_hat_initial;
    double mass_start = 0, mass_end = 0;  // sum of phi h^2 over the bed
    BoundsMonitor after_bulk;             // extremes of phi - Phi and phi after every bulk step
    BoundsMonitor after_segregation;      // the same at the sample times (after the full step)
    void checkpoint(StateIO& io) {
        io("history", history)("frames", frames)("phi_hat_initial", phi_hat_initial)("mass_start", mass_start);
        io("mass_end", mass_end)("after_bulk", after_bulk)("after_segregation", after_segregation);
    }
};

/// Observer called after every step (for checks beyond the built-in invariants); may be empty.
/// It sees the extremes of phi after this step's bulk transport and phi at that point.
using KinematicStepObserver = std::function<void(const KinematicTumbler& tumbler, const BoundsMonitor& after_bulk_step,
                                                 const std::vector<double>& phi_after_bulk)>;

/// Runs `tumbler` from its current state to options.t_end (see above); with `checkpoints`, writes
/// and resumes checkpoints of the tumbler and of the result so far (run/run_checkpoints.hpp).
KinematicRunResult run_kinematic_tumbler(KinematicTumbler& tumbler, const KinematicRunOptions& options,
                                         const KinematicStepObserver& observer = {}, RunCheckpoints* checkpoints = nullptr);

/// The regions of the pattern metrics for `flow` (docs/sect4.2_tumbler_kinematic.md, section 3).
PatternRegions default_regions(const RollingDrumFlow& flow);

}  // namespace granseg
