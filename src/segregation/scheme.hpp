// The selectable schemes of the segregation sub-step and their names in scene files.
//
//   modified-godunov    eqs. (61)-(63) with each cell's own flux function (default; first order)
//   modified-godunov-2  the same flux on limited reconstructions of phi_hat = phi/Phi, with the
//                       SSP-RK(3,2) method (second order where the solution is smooth; beyond
//                       the paper)
//   classic-upwind      one flux function per face with interface values Phi_face, a_face (the
//   classic-godunov     paper's comparisons in Fig. 6); they ignore condition (51) and overshoot
#pragma once

#include <string>
#include <vector>

namespace granseg {

enum class SegregationScheme { modified_godunov, modified_godunov_2, classic_upwind, classic_godunov };

/// Slope limiter of the second-order reconstruction of phi_hat.
enum class Limiter { minmod, mc };

/// Bulk transport of a scene without a flow solver: the coupling contract's donor cell, or
/// flux-corrected transport (bulk_transport_fct.hpp).
enum class BulkScheme { donor_cell, fct };

/// Scene-file names, in the order listed in messages ("modified-godunov", ...).
const std::vector<std::string>& scheme_names();
const std::vector<std::string>& limiter_names();
const std::vector<std::string>& bulk_scheme_names();  // "donor-cell", "fct"

/// Name <-> value; the parsers throw std::invalid_argument for an unknown name.
SegregationScheme parse_scheme(const std::string& name);
std::string scheme_name(SegregationScheme scheme);
Limiter parse_limiter(const std::string& name);
std::string limiter_name(Limiter limiter);
BulkScheme parse_bulk_scheme(const std::string& name);

/// True for the schemes that keep 0 <= phi <= Phi (the modified ones).
inline bool preserves_bounds(SegregationScheme s) {
    return s == SegregationScheme::modified_godunov || s == SegregationScheme::modified_godunov_2;
}

/// True for the schemes that read interface values Phi_face, a_face (the classic ones).
inline bool uses_interface_values(SegregationScheme s) { return !preserves_bounds(s); }

/// Spatial and temporal order on smooth solutions: 2 for modified-godunov-2, else 1.
inline int scheme_order(SegregationScheme s) { return s == SegregationScheme::modified_godunov_2 ? 2 : 1; }

}  // namespace granseg
