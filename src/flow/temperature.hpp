// The temperature equation (14) without convection (docs/flow_solver.md Sect. 4):
//   1. heating (3/2) eta kappa:kappa against dissipation eps Phi T, linearly implicit:
//          Phi (T - T*)/dt = (3/2) H - eps Phi T_new,
//      with H the dissipation of the discrete viscous operator (half of eta_f ((u_nb - u)/h)^2 of
//      each interior face, all of 2 eta ((U_wall - u)/h)^2 of a wall face) and eps from the start
//      of the step. As (3/2) eta/(eps Phi) = (3/2) eta0/eps0, T relaxes towards eq. (45)'s value
//      and never overshoots it, for any dt;
//   2. conduction (3/2) div(lambda grad T), adiabatic walls, line solves one axis after the other;
//   3. the floor T >= T_floor (assumption F2), and Phi T = Phi T_new.
#pragma once

#include "flow/diffusion_lines.hpp"
#include "flow/flow_mesh.hpp"
#include "flow/flow_settings.hpp"
#include "flow/flow_state.hpp"

#include <vector>

namespace granseg {

/// Updates T and Phi T of `state` (reads Phi, u, T) with eta, eps Phi, lambda of `closures`;
/// `heat` and `work` hold one value per cell.
void implicit_temperature(const FlowMesh& mesh, const FlowSettings& settings, const WallVelocities& walls, double dt,
                          const CellClosures& closures, DiffusionLines& lines, std::vector<double>& heat,
                          std::vector<double>& work, FlowState& state);

}  // namespace granseg
