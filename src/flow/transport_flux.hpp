// The convective flux of eqs. (8), (9), (14) across one face when the face mass flux M is known
// (the semi-implicit step, flow/semi_implicit.hpp, where M comes from the implicit pressure
// equation): the donor cell, the one the mass leaves, carries its velocity and temperature
// (first-order upwind, so T and u_t stay convex combinations of old values whenever no cell
// loses more than its mass), and the face pressure p* adds to the normal momentum flux.
// Same orientation and result type as the HLLC flux of flow/hllc.hpp: L is the cell below the
// face along the axis, R the cell above.
#pragma once

#include "flow/hllc.hpp"

namespace granseg {

/// Fluxes of mass (M), normal momentum M U + p* (U the face velocity, as the contact speed S* in
/// HLLC), tangential momenta and Phi T u_n = M T with u_t, T of the donor (L for M >= 0, R
/// otherwise), and p*.
inline __attribute__((always_inline)) FaceFlux transport_flux(const FaceState& L, const FaceState& R, double M,
                                                            double U, double p_star) {
    const bool left = M >= 0.0;
    const double t1 = left ? L.u_t1 : R.u_t1, t2 = left ? L.u_t2 : R.u_t2, T = left ? L.T : R.T;
    return {M, M * U + p_star, M * t1, M * t2, M * T, p_star};
}

}  // namespace granseg
