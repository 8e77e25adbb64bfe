// Geometry of the segregation flux f(phi; Phi, a) = a phi (phi - Phi)/Phi in the state space
// (phi, Phi) of the resonant system (52): the transition curve Gamma (eq. 59), the extreme value
// of f on it, and the two inverse branches of f at fixed Phi (the standing-wave curves f = const).
//
//   solves      f(phi; Phi, a) = F for phi on either side of Gamma (eqs. 55, 58, 59)
//   inputs      F between 0 and f_min = -a Phi/4, Phi > 0, a != 0
//   outputs     the root left of Gamma (phi <= Phi/2) or right of it (phi >= Phi/2)
//   invariants  each root lies on its side of Gamma and in [0, Phi]; F a few ulps outside is clamped
//
// Gamma = {(phi, Phi) : Phi = 2 phi} is where lambda_1 = a (2 phi/Phi - 1) vanishes (eqs. 55, 58).
// "Left of Gamma" means phi <= Phi/2 (lambda_1 has the sign of -a there), "right" phi >= Phi/2.
// On each side f is monotone, so f = F has one root per side for F between 0 and -a Phi/4.
// This file is the only place where f is inverted; the case logic of the Riemann solver and of the
// Table 1 classifier never solves an equation itself.
#pragma once

namespace granseg {

/// phi on the transition curve Gamma at this Phi: Phi/2 (eq. 59), where f(.; Phi, a) is extreme.
inline double gamma_phi(double Phi) { return 0.5 * Phi; }

/// The extreme value of f(.; Phi, a): f(Phi/2) = -a Phi/4 (f_min for a > 0, f_max for a < 0).
inline double flux_extremum(double Phi, double a) { return -0.25 * a * Phi; }

/// The phi in [0, Phi/2] (left of Gamma) with f(phi; Phi, a) = F; F must lie between 0 and
/// -a Phi/4 (a few ulps outside are clamped; further outside throws InputError).
/// Evaluated without cancellation near phi = 0: phi = -2F / (a (1 + sqrt(1 + 4F/(a Phi)))).
double phi_left_of_gamma(double F, double Phi, double a);

/// The phi in [Phi/2, Phi] (right of Gamma) with f(phi; Phi, a) = F (same conditions):
/// Phi minus the left root, since f is symmetric about Phi/2.
double phi_right_of_gamma(double F, double Phi, double a);

}  // namespace granseg
