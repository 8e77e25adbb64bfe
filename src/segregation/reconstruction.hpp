// Limited linear reconstruction of the composition phi_hat = phi/Phi for the second-order
// segregation scheme (modified-godunov-2, beyond the paper).
//
//   solves      nothing over time: the face states of eq. (63) at second order
//   inputs      phi and Phi per cell, the limiter
//   outputs     phi at the lower and at the upper face of every cell along one axis
//   invariants  face values in [0, Phi_i]; the two of a cell average to phi_i
//
// Reconstructing phi itself would let a face value exceed Phi_i where Phi varies; reconstructing
// phi_hat and multiplying by the cell's own Phi_i gives face states in [0, Phi_i], the states the
// modified flux (eqs. 61-63) expects. The slope s_i of phi_hat is limited (minmod or monotonized
// central) so that phi_hat_i +- s_i/2 lies between the neighbouring values; the face values are
// also clipped to that range, so the property holds in floating point too. The two face values
// of a cell average to phi_i, which makes the scheme a convex combination of first-order updates
// (docs/sect2.2_segregation.md, "Second order").
#pragma once

#include "core/grid.hpp"
#include "segregation/scheme.hpp"

#include <algorithm>
#include <vector>

namespace granseg {

/// phi_hat = phi/Phi clipped to [0, 1], or 0 where there is no material (Phi <= 0). The clip
/// matters only where Phi is tiny: the rounding of a coupled step (Phi_new from the flow, phi_new
/// from the bulk transport) can leave phi a few ulps above such a Phi, i.e. phi_hat well above 1,
/// which a reconstruction would spread to the neighbours.
inline double composition(double phi, double Phi) { return Phi > 0.0 ? std::clamp(phi / Phi, 0.0, 1.0) : 0.0; }

/// For every inside cell, phi at its lower face (at_lower) and at its upper face (at_upper) along
/// `axis`: Phi_i (phi_hat_i -+ s_i/2) with the limited slope s_i; s_i = 0 next to a wall or a
/// cell without material. Outside cells get phi_i on both faces.
void reconstruct_faces(const Grid& grid, int axis, const std::vector<double>& phi, const std::vector<double>& Phi,
                       Limiter limiter, std::vector<double>& at_lower, std::vector<double>& at_upper);

}  // namespace granseg
