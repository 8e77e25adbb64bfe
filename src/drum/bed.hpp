// Geometry and initial states of granular beds for the flow scenes: a drum (the circle of
// Sect. 4.2, or any drum/drum_shape.hpp cross-section) as embedded walls, and a bed at rest in the static (lithostatic) balance
// dp/dz = -Phi |g| with p = p(Phi, T) from eqs. (15)-(19) (docs/assumptions.md F6).
//
//   solves      the lithostatic balance dp/dz = -Phi(p) |g| column by column (RK4), and p(Phi) = p
//   inputs      drum: its shape, cells across its diameter; bed: Grid, Material, surface height, |g|, T, Phi_rcp, Phi_co
//   outputs     the drum's Grid (inside flags); Phi per cell of the bed at rest
//   invariants  0 <= Phi < Phi_rcp; cells above the surface are empty
#pragma once

#include "closures/material.hpp"
#include "core/grid.hpp"
#include "drum/drum_shape.hpp"

#include <vector>

namespace granseg {

/// The drum `shape` (axis at the origin) on square cells of side 2R/n, R = shape.radius() (times
/// ny periodic cells along y of length ly; ny = 1: the x-z plane): cells whose centre lies inside
/// the shape are inside, the rest are walls (a staircase shape). A circle gets the n x n cells of
/// [-R, R]^2; another shape the whole cells that cover its extent, placed symmetrically about
/// x = 0 (a shape symmetric under x -> -x gets a mirror-symmetric grid).
Grid drum_grid(const DrumShape& shape, int n, int ny = 1, double ly = 1.0);

/// The circular drum of radius R: drum_grid(DrumShape::circle(R), n, ny, ly).
Grid drum_grid(int n, double R, int ny = 1, double ly = 1.0);

/// Volume fraction at pressure p >= 0 and temperature T: the inverse of p(Phi) of eqs. (15)-(19)
/// on [0, Phi_rcp) (p is increasing in Phi), by bisection to round-off.
double volume_fraction_at_pressure(const Material& m, double p, double T, double Phi_rcp, double Phi_co);

/// Phi per cell of a bed at rest filling every inside cell below the horizontal surface
/// z = z_surface under gravity |g| along -z, at temperature T: the lithostatic pressure
/// p(z) from dp/dz = -Phi(p) |g|, p(z_surface) = 0, integrated column by column (RK4, 16 steps per
/// cell), Phi = Phi(p) at the cell centre; the cell holding the surface gets the filled fraction
/// of its height times that value. Cells above the surface are empty.
std::vector<double> lithostatic_bed(const Grid& grid, const Material& m, double z_surface, double gravity, double T,
                                    double Phi_rcp, double Phi_co);

}  // namespace granseg
