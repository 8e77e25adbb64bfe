// The coupled drum's own regions, for the Fig. 7 study (docs/sect4.2_fig7_study.md): where
// pattern_metrics.hpp takes the kinematic drum's regions (a layer kLayerShare D thick, cells counted
// by their centres) so that the two drums compare, these follow the coupled run itself:
//   core       r < d - delta:        material that never reaches the flowing layer, delta the run's
//                                     own measured thickness of the layer (a circle of solid-body
//                                     rotation with r < d - delta passes below the layer's bottom)
//   ring       d - delta <= r < d:   the circles that cross the layer but lie wholly in the bed
//   periphery  r >= 0.8 R:           next to the wall (as pattern_metrics.hpp, assumption T4)
//   axis       r < axis_radius:      the innermost part of the core
// with d the free surface's distance from the axis, and every bed cell (Phi > bed_level) counted by
// the exact share of its area inside the region (drum/region_weights.hpp), so that a region's
// area does not jump as its circle crosses cell centres and is the same on grids of either parity.
//
//   solves      nothing over time: shares of small particles in four regions
//   inputs      the grid (drum axis at the origin; a slab: its slice j = 0), phi and Phi, the radii
//   outputs     LayerRegionShares (NaN for a region without bed, e.g. a layer thicker than d)
//   invariants  weights in [0, 1]; a region's share in [0, 1] where 0 <= phi <= Phi
#pragma once

#include "core/grid.hpp"
#include "run/state_io.hpp"

#include <vector>

namespace granseg {

struct LayerRegionShares {
    double r_core = 0;                                   // m, d - delta
    double core = 0, ring = 0, periphery = 0, axis = 0;  // small-particle share of each region
    void checkpoint(StateIO& io) { io("r_core", r_core)("core", core)("ring", ring)("periphery", periphery)("axis", axis); }
};

/// The regions of a drum of radius R whose free surface passes at distance d from the axis; the
/// periphery's and the axis region's weights are computed once, the core's and the ring's for each
/// measured layer thickness.
class LayerRegions {
public:
    LayerRegions(const Grid& grid, double d, double R, double axis_radius);

    /// The shares of phi over the bed (Phi > bed_level) with a flowing layer `layer` thick (m).
    LayerRegionShares shares(const std::vector<double>& phi, const std::vector<double>& Phi, double layer,
                             double bed_level) const;

private:
    const Grid& grid_;
    double d_;
    std::vector<double> periphery_, axis_;
};

}  // namespace granseg
