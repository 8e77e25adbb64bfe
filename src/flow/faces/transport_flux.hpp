// The convective flux of eqs. (8), (9), (14) across one face when the face mass flux M is known
// (the semi-implicit step, flow/faces/semi_implicit_faces.hpp, where M comes from the implicit pressure
// equation): the donor cell, the one the mass leaves, carries its velocity (all three components)
// and temperature (first-order upwind, so T and u stay convex combinations of old values whenever
// no cell loses more than its mass), and the face pressure p* adds to the normal momentum flux.
//
//   solves      the convective flux across one face for a given mass flux M (donor cell)
//   inputs      the two face states, M, p*
//   outputs     FaceFlux
//   invariants  every flux is M times the donor's value (plus p* in the normal momentum)
//
// The normal momentum is carried with the donor's u_n, not with the face velocity U = M/Phi_d: a
// cell draining through a face whose U differs from its own u_n would otherwise keep the momentum
// difference M (u_n - U) dt/h in its remaining mass, a kick that grows without bound as the cell
// empties (dust of a collapsing heap once flew off that way: docs/history.md).
//
// Same orientation and result type as the HLLC flux of flow/faces/hllc.hpp: L is the cell below the
// face along the axis, R the cell above.
#pragma once

#include "flow/faces/hllc.hpp"

namespace granseg {

/// Fluxes of mass (M), normal momentum M u_n + p*, tangential momenta M u_t and Phi T u_n = M T,
/// with u_n, u_t, T of the donor (L for M >= 0, R otherwise), and p*.
inline __attribute__((always_inline)) FaceFlux transport_flux(const FaceState& L, const FaceState& R, double M, double p_star) {
    const FaceState& d = M >= 0.0 ? L : R;
    return {M, M * d.u_n + p_star, M * d.u_t1, M * d.u_t2, M * d.T, p_star};
}

}  // namespace granseg
