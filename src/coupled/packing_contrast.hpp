// The claim of Fig. 7d as a number (verify_tumbler): in the resting bed, at equal depth below
// the free surface, how much denser the mixed material packs than nearly pure material.
//
// With packing feedback Phi_rcp(phi_hat) and Phi_co(phi_hat) peak near phi_hat = 0.4 (assumptions
// A3, A4), so a mixed cell carries its load at a higher Phi than a pure one under the same
// pressure; without feedback every cell has the initial mixture's packing law and the contrast
// must vanish within the spread of Phi among cells of one kind at one depth.
//
// Cells: bed cells (Phi > bed_level) at rest relative to the drum (speed <= v_flow; in the flowing
// layer Phi is set by the shear rate, not by the packing law), lab frame. Depth: distance below
// the free surface along its normal n = (-sin a, cos a) (a the fitted surface angle), measured
// from the highest bed cell. Bins of depth of width `bin`; in each bin with cells of both kinds:
// the mean Phi of the mixed cells (mixed_lo < phi_hat < mixed_hi) minus that of the pure cells
// (phi_hat < pure or phi_hat > 1 - pure). contrast: the mean of the bin differences weighted by
// min(n_mixed, n_pure); spread: the square root of the pooled variance of Phi within the kinds and
// bins (the "noise" the contrast is compared with).
#pragma once

#include "coupled/coupled_tumbler.hpp"
#include "run/state_io.hpp"

namespace granseg {

struct PackingContrastOptions {
    double bed_level = 0.3;                             // a bed cell has Phi > bed_level
    double v_flow = 0.0;                                // m/s, at rest: speed relative to the drum <= v_flow
    double bin = 0.005;                                 // m, width of a depth bin
    double mixed_lo = 0.3, mixed_hi = 0.7, pure = 0.1;  // phi_hat classes (docs/assumptions.md)
};

struct PackingContrast {
    double contrast = 0;       // weighted mean of the bins' (mean Phi mixed - mean Phi pure)
    double spread = 0;         // pooled standard deviation of Phi within a kind and a bin
    int bins = 0;              // bins with both kinds
    long mixed = 0, pure = 0;  // cells of each kind in those bins
    void checkpoint(StateIO& io) { io("contrast", contrast)("spread", spread)("bins", bins)("mixed", mixed)("pure", pure); }
};

/// The contrast of the tumbler's current state; surface_angle_deg: the fitted free-surface angle
/// (drum/drum_state.hpp) against the horizontal.
PackingContrast packing_contrast(const CoupledTumbler& tumbler, double surface_angle_deg, const PackingContrastOptions& options);

}  // namespace granseg
