// The face rules of the flow solver's diffusion operators, in one place for the viscosity (split
// line solves, flow/diffusion/viscosity.hpp, and coupled, flow/diffusion/coupled_viscosity.hpp), the temperature's
// conduction and viscous heating (flow/diffusion/temperature.hpp) and the velocity gradient
// (flow/velocity_gradient.hpp); docs/flow_solver.md Sect. 2, viscosity.
//
//   solves      nothing: the conductance of a face and the value a wall imposes
//   inputs      the cells' coefficient kappa (eta, lambda), the grid, the wall velocities
//   outputs     kappa_f per face (times r = dt/h^2 it is the face weight of an implicit system)
//   invariants  kappa_f >= 0 and symmetric in the two cells; a face between the bed and
//               near-empty air (kappa ~ 0) carries almost no stress or heat
//
// Interior face: kappa_f is the harmonic mean of the two cells' kappa. Wall: the wall lies at
// distance h/2 from the cell centre, so a no-slip (Dirichlet) wall has kappa_f = 2 kappa_c and
// imposes its own velocity, an adiabatic wall has kappa_f = 0. Only walls of the domain boundary
// move (with the WallVelocities of the scene); embedded walls (grid.inside) are at rest.
#pragma once

#include "core/grid.hpp"
#include "flow/fields/flow_settings.hpp"

#include <cstddef>

namespace granseg {

/// The harmonic mean 2ab/(a+b) of two coefficients (0 if both are 0).
inline double harmonic_mean(double a, double b) {
    const double s = a + b;
    return s > 0.0 ? 2.0 * a * b / s : 0.0;
}

/// kappa_f of a face of a cell with coefficient kappa_c: the harmonic mean with the neighbour's
/// kappa_nb across an interior face, 2 kappa_c at a no-slip wall, 0 at an adiabatic wall.
inline double face_conductance(bool interior, double kappa_c, double kappa_nb, bool no_slip) {
    return interior ? harmonic_mean(kappa_c, kappa_nb) : no_slip ? 2.0 * kappa_c : 0.0;
}

/// Whether face f of `axis` lies on the domain boundary (its first or last layer on a bounded
/// axis): a wall there may move; every other wall is embedded and at rest.
inline bool on_domain_boundary(const Grid& grid, int axis, std::size_t f) {
    if (grid.periodic[axis]) return false;
    const std::size_t nx = grid.n[0], ny = grid.n[1];
    const std::size_t layer = axis == 0 ? f % (nx + 1) : axis == 1 ? f / nx % (ny + 1) : f / (nx * ny);
    return layer == 0 || layer == static_cast<std::size_t>(grid.n[axis]);
}

/// Component b of the velocity of the wall face f on `side` (0 lower, 1 upper) of `axis`:
/// walls[axis][side][b] on the domain boundary, 0 on an embedded wall.
inline double wall_velocity(const Grid& grid, const WallVelocities& walls, int axis, int side, std::size_t f, int b) {
    return on_domain_boundary(grid, axis, f) ? walls[axis][side][b] : 0.0;
}

}  // namespace granseg
