// The segregation flux of Sect. 3 and the interface fluxes built from it.
//
//   solves      the interface flux F of eq. (64) for d_t phi + d_z f(phi; Phi, a) = 0 (eqs. 49, 66;
//               one axis of eq. 47): eqs. (61)-(63) and the fluxes it is compared with
//   inputs      InterfaceStates: (phi, Phi, a) either side of the face; Phi_face, a_face for the
//               fluxes of one flux function per face
//   outputs     F, the flux of small particles through the face along the axis
//   invariants  F(u, u) = f(u); F(L, R) = -F(R', L') with a -> -a; the modified flux keeps
//               0 <= phi <= Phi under eq. (64) for dt max|a|/h <= 1 (verify_table1_sweep)
//
// Per direction the flux of small particles is f(phi; Phi, a) = a phi (phi - Phi)/Phi
// (eqs. 49 and 66 with a = S sqrt(T); in more dimensions a = (S^sl)_k, eq. 47 moved to the
// left-hand side). For a > 0 it is convex with its minimum a(-Phi/4) at phi = Phi/2, the
// transition curve Gamma (eq. 59); for a < 0 it is concave. f vanishes at phi = 0 and phi = Phi.
//
// The interface flux between a left cell (phi_L, Phi_L, a_L) and a right cell (phi_R, Phi_R, a_R):
//   a_L, a_R >= 0: F = max(f_L(max(phi_L, Phi_L/2)), f_R(min(phi_R, Phi_R/2)))  eqs. (61)-(63)
//   a_L, a_R <= 0: F = min(f_L(min(phi_L, Phi_L/2)), f_R(max(phi_R, Phi_R/2)))  concave mirror
//   a_L a_R < 0:   F = 0, the only value both flux curves share on [0, Phi]
// (docs/assumptions.md S1; the concave form is not minus eq. (63): left and right swap roles).
// The classic fluxes the paper compares with use ONE flux function, with interface values
// Phi_face and a_face, and so ignore condition (51).
//
// Every interface flux has the same signature, double F(const InterfaceStates&), so that the
// scheme table (src/segregation/scheme.hpp) can hold any of them; a new flux is one function
// here and one row there.
#pragma once

#include <limits>

namespace granseg {

/// f(phi; Phi, a) = a phi (phi - Phi)/Phi (eqs. 49, 66); 0 where there is no material (Phi <= 0).
inline double segregation_flux(double phi, double Phi, double a) { return Phi > 0.0 ? a * phi * (phi - Phi) / Phi : 0.0; }

/// df/dphi = a (2 phi/Phi - 1), the eigenvalue lambda_1 of eq. (55).
inline double segregation_speed(double phi, double Phi, double a) { return Phi > 0.0 ? a * (2.0 * phi / Phi - 1.0) : 0.0; }

/// One side of a cell interface: small-particle fraction, granular fraction, flux coefficient.
struct FluxSide {
    double phi, Phi, a;
};

/// What an interface flux sees: the state either side of the face, each with its own cell's
/// Phi and a, and the interface values Phi_face, a_face read by the fluxes that use one flux
/// function per face (NaN unless given; the fluxes of each cell's own flux function ignore them).
struct InterfaceStates {
    FluxSide L, R;
    double Phi_face = std::numeric_limits<double>::quiet_NaN();
    double a_face = std::numeric_limits<double>::quiet_NaN();
};

/// The signature of every interface flux.
using InterfaceFlux = double (*)(const InterfaceStates& q);

/// The interface values of rule "mean" (docs/assumptions.md G2): Phi_face, a_face the means of
/// the two cells' values.
InterfaceStates mean_interface(const FluxSide& L, const FluxSide& R);

/// Modified Godunov flux, eqs. (61)-(63), extended to coefficients of any sign (see above);
/// reads L and R, not the interface values.
double modified_godunov_flux(const InterfaceStates& q);

/// Classic upwind (Murman-Roe) flux of the single function f(.; Phi_face, a_face): f(phi_L) if
/// the Rankine-Hugoniot speed of (phi_L, phi_R) is >= 0, else f(phi_R). Reads L.phi, R.phi and
/// the interface values.
double classic_upwind_flux(const InterfaceStates& q);

/// Classic Godunov flux of the single function f(.; Phi_face, a_face): the minimum of f over
/// [phi_L, phi_R] if phi_L <= phi_R, else its maximum over [phi_R, phi_L]. Reads L.phi, R.phi
/// and the interface values.
double classic_godunov_flux(const InterfaceStates& q);

/// Local Lax-Friedrichs (Rusanov) flux with each cell's own flux function, a teaching row of the
/// scheme table (beyond the paper):
///     F = (f_L(phi_L) + f_R(phi_R))/2 - alpha (phi_R - phi_L)/2,
///     alpha = max(|f_L'(phi_L)|, |f_R'(phi_R)|)   (eq. 55 on each side).
/// Consistent and conservative; its dissipation acts on phi, not on phi_hat = phi/Phi, so where
/// Phi jumps it moves small particles into a full cell (docs/sect4.1_overshoot.md, the flux table).
double rusanov_flux(const InterfaceStates& q);

}  // namespace granseg
