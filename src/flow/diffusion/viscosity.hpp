// Implicit viscosity split by axes (eqs. 9-11; docs/flow_solver_choices.md, "The explicit step"), the explicit
// step's default.
//
//   solves      Phi (u_new - u)/dt = div(eta grad u_new), one axis after the other, by
//               tridiagonal line solves
//   inputs      Phi, u, eta per cell, dt, the velocities of the domain-boundary walls
//   outputs     u and Phi u
//   invariants  empty cells at rest; the line systems are M-matrices
//
// With the asymmetric stress eta grad u every velocity component obeys
//     Phi (u_new - u)/dt = sum_axis d/dx_a (eta d u_new/dx_a),
// which has no mixed derivatives; the axes are taken one after the other (Lie/ADI splitting),
// each as tridiagonal line solves (flow/diffusion/diffusion_lines.hpp). No-slip walls, moving walls of the
// domain boundary with their tangential velocity; eta from the start of the step (linearly
// implicit, at the effective pressure). Then Phi u = Phi u_new.
#pragma once

#include "flow/diffusion/diffusion_lines.hpp"
#include "flow/fields/flow_mesh.hpp"
#include "flow/fields/flow_settings.hpp"
#include "flow/fields/flow_state.hpp"

#include <vector>

namespace granseg {

/// Updates u and Phi u of `state` (reads Phi, u); `work` holds one value per cell.
void implicit_viscosity(const FlowMesh& mesh, const FlowSettings& settings, const WallVelocities& walls, double dt,
                        const std::vector<double>& eta, DiffusionLines& lines, std::vector<double>& work, FlowState& state);

}  // namespace granseg
