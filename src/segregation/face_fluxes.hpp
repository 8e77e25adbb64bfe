// The segregation flux on every face of one axis, for any scheme of the table, plus the
// remixing flux.
//
//   solves      the face fluxes F of eq. (64) along one axis for any row of the scheme table, plus
//               the remixing flux (assumption G3)
//   inputs      grid, axis, FrozenFields, scheme, phi (cell averages), each cell's state at its
//               lower and upper face
//   outputs     F on every face normal to the axis
//   invariants  F = 0 on every wall face
//
// The face between a lower cell L and an upper cell U sees the state L presents at its upper
// face and the state U presents at its lower face (the cell averages for first order, the
// reconstructed values for order 2), each with its own cell's Phi and a, and, for the schemes
// that read them, the interface values Phi_face, a_face (given, or the means, assumption G2):
//   F = scheme.row().flux({{phi_L, Phi_L, a_L}, {phi_U, Phi_U, a_U}, Phi_face, a_face})
// (eq. 63 for the modified schemes) and F = 0 on walls (zero-flux ends, embedded walls,
// non-periodic domain boundaries).
#pragma once

#include "segregation/frozen_fields.hpp"
#include "segregation/scheme.hpp"

#include <vector>

namespace granseg {

/// F on every face normal to `axis` (resized to grid.faces(axis)). at_upper[c], at_lower[c]: the
/// state of cell c at its upper and lower face; phi: cell averages (for the remixing flux).
void segregation_face_fluxes(const Grid& grid, int axis, const FrozenFields& fields, SegregationScheme scheme,
                             const std::vector<double>& phi, const std::vector<double>& at_lower,
                             const std::vector<double>& at_upper, std::vector<double>& F);

/// Largest |a| over the inside cells with material, and over the interface values the scheme
/// reads, along `axis` (0 if the axis has no coefficients).
double max_coefficient(const Grid& grid, int axis, const FrozenFields& fields, SegregationScheme scheme);

}  // namespace granseg
