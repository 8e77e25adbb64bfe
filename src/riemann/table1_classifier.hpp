// The ten cases of Table 1 (regions A-J of Fig. 4): which wave pattern the Riemann problem (52)
// between Q_L and Q_R has. The paper states the conditions for T_L = T_R in terms of Phi (e.g.
// "Phi_R > Phi_L", "Phi_R < Phi~"); with a = S sqrt(T) differing between the sides they become
// conditions on the flux values f_L(phi_L), f_R(phi_R), f_L^min = -a_L Phi_L/4 (= f(Q*)) and
// f_R^min = -a_R Phi_R/4, which is how they are evaluated here (docs/assumptions.md S2):
//
//   solves      which of the ten cases of Table 1 (regions A-J of Fig. 4) the problem (52), (60) is
//   inputs      Q_L, Q_R = (phi, Phi, a)
//   outputs     Table1Case: number 1-10 (0 for a_L a_R <= 0), region, mirrored (a_L, a_R < 0)
//   invariants  agrees with the wave pattern of the exact solution; on a boundary between two
//               regions both give the same flux (verify_table1_sweep)
//
//   Q_L left of Gamma (phi_L <= Phi_L/2)       Q_L right of Gamma (phi_L > Phi_L/2)
//   3 C  f_R(phi_R) < f_L^min                   8 H   f_R(phi_R) < f_L(phi_L)
//   1 A  phi_R < Phi_R/2, f_R > f_L(phi_L)      7 G   phi_R < Phi_R/2 (and f_R >= f_L)
//   2 B  phi_R < Phi_R/2, f_R <= f_L(phi_L)     9 I   phi_R >= Phi_R/2, f_R^min < f_L(phi_L)
//   4 D  phi_R >= Phi_R/2, f_R^min <= f_L^min   10 J  phi_R >= Phi_R/2, f_R^min >= f_L(phi_L)
//   5 E  ..., f_L^min < f_R^min < f_L(phi_L)
//   6 F  ..., f_R^min >= f_L(phi_L)
// (each row applies only if the rows above it in its column do not; on a boundary between two
// regions both give the same interface flux). With f_R^min = -a Phi_R/4 and equal a, "f_R^min <=
// f_L^min" is Phi_R >= Phi_L and "f_R^min >= f_L(phi_L)" is Phi_R <= Phi~ of Table 1.
//
// For a_L, a_R < 0 the case is the one of the mirror problem (Q_R, -a_R | Q_L, -a_L), flagged
// `mirrored`; for a_L a_R <= 0 there is no Table 1 case (number 0, region '-'): the flux is 0.
#pragma once

#include "riemann/segregation_flux.hpp"

namespace granseg {

struct Table1Case {
    int number = 0;         // 1..10, or 0 when a_L a_R <= 0
    char region = '-';      // 'A'..'J' (Fig. 4), or '-'
    bool mirrored = false;  // a_L, a_R < 0: the case of the mirror image
};

/// Classifies the Riemann problem between L and R (0 <= phi <= Phi, Phi > 0, any signs of a).
Table1Case classify_table1(const FluxSide& L, const FluxSide& R);

}  // namespace granseg
