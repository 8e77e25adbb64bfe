// The cell velocity gradient handed to the segregation solver (docs/flow_solver.md Sect. 2, "Hand-over to the segregation
// solver").
//
//   solves      nothing: d u_b/d x_a by central differences in every inside cell
//   inputs      Phi, u per cell, the velocities of the domain-boundary walls
//   outputs     the nine components per cell
//   invariants  walls and empty neighbours by the rules of flow/diffusion/diffusion_faces.hpp
//
// d u_b/d x_a by central differences; a wall contributes the no-slip ghost 2 U_wall - u (U_wall
// the domain-boundary wall's velocity, 0 on embedded walls), an empty neighbour (free surface)
// the cell's own value, an inactive axis 0.
#pragma once

#include "flow/fields/flow_mesh.hpp"
#include "flow/fields/flow_settings.hpp"

#include <array>
#include <vector>

namespace granseg {

/// grad[3 b + a][c] = d u_b / d x_a in every inside cell c.
void velocity_gradient(const FlowMesh& mesh, const FlowSettings& settings, const WallVelocities& walls,
                       const std::vector<double>& Phi, const std::array<std::vector<double>, 3>& u,
                       std::array<std::vector<double>, 9>& grad);

}  // namespace granseg
