// The convective part of a step (eqs. 8, 9, 14 without viscosity, conduction and dissipation):
// the face fluxes of one axis by the HLLC flux with hydrostatic reconstruction (flow/faces/hllc.hpp;
// walls are mirror states), and the conservative update of (Phi, Phi u, Phi T) from the fluxes
// with the body forces the potential does not carry (Coriolis, gravity along inactive or
// periodic axes) and optional source terms. docs/flow_solver_choices.md, "The explicit step".
//
//   solves      the convective part of eqs. (8), (9), (14) over one step (forward Euler, unsplit)
//   inputs      FlowMesh; the state and closures at t^n, psi and the loads of an axis (fluxes);
//               the face fluxes, Frame, sources, t, dt (update)
//   outputs     AxisFaces of an axis; the state after the update (Phi, Phi u, Phi T, u, T)
//   invariants  mass, Phi T and tangential momentum fluxes are exactly 0 on walls; the update of
//               Phi is the coupling identity Phi_new = Phi - dt div M (flow/fields/face_balance.hpp)
#pragma once

#include "core/face_fields.hpp"
#include "flow/fields/flow_mesh.hpp"
#include "flow/fields/flow_settings.hpp"
#include "flow/fields/flow_state.hpp"
#include "flow/fields/frame.hpp"

#include <vector>

namespace granseg {

/// Mass, momentum and energy fluxes, face pressure p* and fastest wave speed on every face of
/// `axis` (HLLC between the hydrostatically reconstructed states of the two cells). On walls the
/// mass, energy and tangential momentum fluxes are exactly 0.
void hllc_face_fluxes(const FlowMesh& mesh, int axis, const FlowState& state, const CellClosures& closures, const Potential& psi,
                      const AxisLoads& loads, AxisFaces& faces);

/// Phi = Phi - dt sum_axis (M[upper] - M[lower])/h_axis (the coupling identity), the same for
/// Phi u and Phi T with their fluxes; then gravity on the Phi at the start along inactive or
/// periodic axes, the sources (if any) at time t, and Coriolis du/dt = 2 omega (u_z, -u_x) as a
/// rotation of (u_x, u_z) by -2 omega dt (exact); finally u and T of the new state (Phi u is left
/// unrotated: the implicit viscosity step rebuilds it from u).
void explicit_update(const FlowMesh& mesh, const FlowSettings& settings, const Frame& frame, const FlowSource& source, double t,
                     double dt, const FlowFaces& faces, FlowState& state);

/// The update of explicit_update() by the fluxes alone (no body force, source or rotation): the
/// semi-implicit step's transport, whose predictor already applied the forces.
void transport_update(const FlowMesh& mesh, const FlowSettings& settings, double dt, const FlowFaces& faces, FlowState& state);

/// Phi = Phi - dt div M in every inside cell (mass_balance, flow/fields/face_balance.hpp): what a consumer
/// of the flow's hand-over (flow/flow_solver.hpp) gets bit for bit as the flow's Phi after the step,
/// and the mass balance of kinematic set-ups without a flow solver. An empty M[axis] carries
/// nothing; non-periodic domain-boundary faces count (open boundaries).
void apply_mass_fluxes(const FlowMesh& mesh, const FaceFields& M, double dt, std::vector<double>& Phi);
/// The same on the grid's own FlowMesh, built for this one call.
void apply_mass_fluxes(const Grid& grid, const FaceFields& M, double dt, std::vector<double>& Phi);

}  // namespace granseg
