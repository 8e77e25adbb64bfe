// Exact Riemann solver of the resonant system (52), extended by the flux coefficient a:
//   d_t phi + d_z f(phi; Phi, a) = 0,   d_t Phi = 0,   d_t a = 0,
//   f(phi; Phi, a) = a phi (phi - Phi)/Phi,  a = S sqrt(T)  (eqs. 49, 52, 66),
// with Q = (phi, Phi, a) = Q_L for z < 0 and Q_R for z > 0 (eq. 60). The solution is self-similar,
// phi(z, t) = phi(xi), xi = z/t, and made of at most three waves (Sect. 3.2):
//   - a wave of the left flux curve f_L = f(.; Phi_L, a_L) with speeds <= 0 (shock or rarefaction
//     along Phi = const, characteristic speed lambda_1 = a (2 phi/Phi - 1), eq. 55),
//   - a standing wave at xi = 0 along f = const (lambda_0 = 0): f_L(phi_minus) = f_R(phi_plus),
//     condition (51), present whenever (Phi, a) jumps,
//   - a wave of the right flux curve f_R with speeds >= 0.
// Shocks satisfy the Lax condition lambda_1(left) >= s >= lambda_1(right); the standing wave must
// not cross the transition curve Gamma (Isaacson-Temple entropy condition): phi_minus and
// phi_plus lie on the same side of Gamma, or one of them on Gamma.
//
//   solves      the Riemann problem (60) of the resonant system (52) exactly
//   inputs      Q_L, Q_R = (phi, Phi, a) with 0 <= phi <= Phi, 0 < Phi, a of any sign
//   outputs     RiemannSolution: the waves (kind, end states, speeds), the traces phi_minus,
//               phi_plus at z = 0 and the interface flux F = f_L(phi_minus) = f_R(phi_plus)
//   invariants  Lax condition and Rankine-Hugoniot on every shock, condition (51) on the standing
//               wave, which does not cross Gamma; F equals eq. (63) (verify_table1, _oracle, _sweep)
//
// Signs of a (docs/assumptions.md S1, S3):
//   a_L, a_R > 0  convex fluxes: the construction of Table 1 (see riemann_solver.cpp);
//   a_L, a_R < 0  concave fluxes: the mirror image z -> -z of the convex problem with
//                 Q_L' = (phi_R, Phi_R, -a_R), Q_R' = (phi_L, Phi_L, -a_L);
//   a_L a_R <= 0  the interface flux is 0, the only value both curves share; a side whose flux
//                 points away from z = 0 empties (trace phi = 0), a side whose flux points
//                 towards it fills (trace phi = Phi), through one shock; a side with a = 0 is still.
#pragma once

#include "riemann/segregation_flux.hpp"

#include <vector>

namespace granseg {

enum class WaveKind { shock, rarefaction, standing };

/// One wave of the solution: the states on its two sides and its speeds. A shock has
/// speed_left = speed_right = s (Rankine-Hugoniot); a rarefaction fans out from lambda_1(left) to
/// lambda_1(right); the standing wave has speed 0 and joins (phi_minus, Phi_L, a_L) to
/// (phi_plus, Phi_R, a_R).
struct Wave {
    WaveKind kind;
    FluxSide left, right;
    double speed_left, speed_right;
};

/// The exact solution of one Riemann problem.
struct RiemannSolution {
    FluxSide L, R;
    std::vector<Wave> waves;  // left to right, by speed
    double phi_minus = 0.0;   // trace at z = 0- (left end of the standing wave)
    double phi_plus = 0.0;    // trace at z = 0+ (right end)
    double flux = 0.0;        // interface flux F = f_L(phi_minus) = f_R(phi_plus)
};

/// Solves the Riemann problem (52), (60) exactly for states with 0 <= phi <= Phi, Phi > 0, and
/// coefficients a of any sign. Throws InputError for states outside that set.
RiemannSolution solve_riemann(const FluxSide& L, const FluxSide& R);

/// "shock", "rarefaction" or "standing".
const char* wave_kind_name(WaveKind kind);

}  // namespace granseg
