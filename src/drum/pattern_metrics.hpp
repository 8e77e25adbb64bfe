// Measures of the segregation pattern in the drum (docs/sect4.2_tumbler_kinematic.md, section 3).
//
// Bed cells: inside cells with Phi > bed_level (the kinematic drum's grid holds only bed cells, so
// 0 there; in the coupled drum the level of the free surface, Phi_co/2, leaves out the air).
// Regions, by the distance r of a bed-cell centre from the drum centre (inertial frame):
//   core       r < r_core:              solid-body streamlines that never reach the flowing layer
//   ring       r_core <= r < r_ring:    the streamlines just below the layer's deepest point
//   periphery  g >= r_periphery:        next to the drum wall, g the cell centre's gauge in the drum's
//                                       shape (DrumShape::gauge; for a circle g = r)
// Each region's small-particle fraction is sum(phi)/sum(Phi) over its bed cells (the mass-weighted
// phi_hat). The segregation index is the standard deviation of phi_hat over the bed (cell
// weighted) divided by sqrt(m (1 - m)), m the mean: 0 for any uniform mixture, 1 for a bed split
// into pure small and pure large cells (Danckwerts' intensity of segregation).
#pragma once

#include "core/grid.hpp"
#include "drum/drum_shape.hpp"
#include "run/state_io.hpp"

#include <vector>

namespace granseg {

struct PatternRegions {
    double r_core = 0, r_ring = 0, r_periphery = 0;  // m
    double bed_level = 0;                            // a bed cell has Phi > bed_level
    DrumShape shape = DrumShape::circle(1.0);        // whose gauge places the periphery (a circle: r, any radius)
};

/// The regions of a drum of radius R whose free surface passes at distance d from the centre, on
/// a flowing layer of thickness delta0 at the middle of the surface: r_core = d - delta0 (the
/// layer bottom's closest approach to the centre), r_ring = d (circles below r = d lie wholly in
/// the bed), r_periphery = 0.8 R (docs/sect4.2_tumbler_kinematic.md, section 3; assumption T4).
PatternRegions drum_regions(double d, double delta0, double R);

struct PatternMetrics {
    double core = 0, ring = 0, periphery = 0;  // small-particle fraction of each region (NaN if empty)
    double mean = 0;                           // mass-weighted phi_hat of the whole bed
    double index = 0;                          // segregation index (see above)
    double core_deviation = 0;                 // max |phi_hat - phi_hat_initial| over the core cells
    void checkpoint(StateIO& io) {
        io("core", core)("ring", ring)("periphery", periphery)("mean", mean)("index", index)("core_deviation", core_deviation);
    }
};

/// The metrics of phi on the bed cells of `grid` (drum centre at the origin; a slab: its slice
/// j = 0). phi_hat_initial: per cell, for core_deviation.
PatternMetrics pattern_metrics(const Grid& grid, const std::vector<double>& phi, const std::vector<double>& Phi,
                               const PatternRegions& regions, const std::vector<double>& phi_hat_initial);

/// Mass-weighted phi_hat, sum(phi)/sum(Phi), of the bed cells (Phi > bed_level) whose centres lie
/// within `radius` of the drum centre (NaN if there are none).
double disc_share(const Grid& grid, const std::vector<double>& phi, const std::vector<double>& Phi, double radius,
                  double bed_level);

/// phi_hat averaged (mass-weighted) over the bed cells in each of `shells` equal radial shells of
/// [0, radius]; the mean radius of the cells of each shell in `r` (NaN where a shell is empty).
struct ShellProfile {
    std::vector<double> r, phi_hat;
    std::vector<long> cells;
};
ShellProfile shell_profile(const Grid& grid, const std::vector<double>& phi, const std::vector<double>& Phi, double radius,
                           int shells, double bed_level = 0.0);

}  // namespace granseg
