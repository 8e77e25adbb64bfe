// Per cell, at the start of a step: the primitives u = Phi u/Phi, T = Phi T/Phi and the closures
// of eqs. (15)-(20) (p, the sound speed c with c^2 = dp/dPhi at fixed T, eta, lambda, eps Phi)
// at the cell's packing limits Phi_rcp(phi_hat), Phi_co(phi_hat); and the effective pressure
// that scales eta, lambda and eps Phi in partly filled surface cells (assumption F7).
//
//   solves      nothing over time: primitives and closures (eqs. 15-20) at t^n
//   inputs      FlowMesh, Material, FlowSettings, phi_hat, Phi, Phi u, Phi T; the face pressures
//   outputs     u, T and CellClosures; eta, lambda, eps Phi at the effective pressure
//   invariants  Phi < Phi_rcp in every inside cell (InvariantError otherwise); empty cells have
//               u = 0, T = T_floor and no transport coefficients
#pragma once

#include "closures/material.hpp"
#include "flow/fields/flow_mesh.hpp"
#include "flow/fields/flow_settings.hpp"
#include "flow/fields/flow_state.hpp"

#include <vector>

namespace granseg {

/// u and T of `state` and every closure of inside cells. phi_hat: per-cell small-particle share,
/// or empty for settings.phi_hat everywhere. Empty cells (Phi <= Phi_vacuum) get u = 0,
/// T = T_floor and no transport coefficients. Throws InvariantError (naming the cell and t) if a
/// cell has Phi >= Phi_rcp.
void compute_primitives(const FlowMesh& mesh, const Material& material, const FlowSettings& settings,
                        const std::vector<double>& phi_hat, double t, FlowState& state, CellClosures& closures);

/// Scales eta, lambda and eps Phi (proportional to p at fixed T, eqs. 16-20) by p_eff/p, p_eff the
/// larger of the cell's own p and, per axis, the mean of its two faces' pressures `faces[a].p`
/// (a cell holding the free surface rests on the face below with its full weight although its
/// own p(Phi) is nearly 0; docs/flow_solver.md Sect. 2, forces).
void effective_pressure(const FlowMesh& mesh, const FlowFaces& faces, CellClosures& closures);

}  // namespace granseg
