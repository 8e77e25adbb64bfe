// Regions of a drum cross-section weighed by exact areas: the share of each grid cell's area that
// lies inside a disc or an annulus about the drum axis (drum/plane_geometry.hpp), and the
// small-particle fraction of a region with each cell counted by that share. A cell cut by the
// region's circle counts with the part of its area inside, where pattern_metrics.hpp counts the
// whole cell by its centre; on a refined grid both tend to the same region, the weighted one
// without the staircase's jumps as the radius moves across cell centres.
//
//   solves      nothing over time: areas of cells inside discs and annuli
//   inputs      an x-z grid (its slice j = 0; every j alike in a slab), radii about the origin
//   outputs     per-cell weights in [0, 1]; mass-weighted phi_hat of a weighted region
//   invariants  weights of the annuli [0, r1), [r1, r2), [r2, inf) sum to 1 in every inside cell
#pragma once

#include "core/grid.hpp"

#include <vector>

namespace granseg {

/// Area of the x-z face of cell (i, k) inside the disc of radius R about the drum axis (the origin), m^2.
double cell_area_in_disc(const Grid& grid, int i, int k, double R);

/// Per cell (every j alike), the share of the cell's x-z area inside the disc of radius R about
/// the origin: 1 inside, 0 outside, the exact share for a cell the circle cuts; 0 in wall cells.
/// R = +inf gives 1 in every inside cell.
std::vector<double> disc_weights(const Grid& grid, double R);

/// Per cell, the share of its area in the annulus r_inner <= r < r_outer about the origin
/// (0 <= r_inner <= r_outer, r_outer may be +inf): disc_weights(r_outer) - disc_weights(r_inner).
std::vector<double> region_weights(const Grid& grid, double r_inner, double r_outer);

/// sum(w phi) / sum(w Phi) over the cells with Phi > bed_level: the mass-weighted phi_hat of the
/// weighted region (NaN if it holds no bed).
double weighted_share(const std::vector<double>& phi, const std::vector<double>& Phi, const std::vector<double>& weights,
                      double bed_level);

}  // namespace granseg
