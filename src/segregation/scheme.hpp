// The numerical choices of the segregation sub-step, each in one table: the interface fluxes
// (one row per scheme), the slope limiters and the bulk transport schemes. Scene files, error
// messages, `granseg run --help`, the solver and the verification programs all read these
// tables, so a new scheme is one row below and one flux function in
// src/riemann/segregation_flux.{hpp,cpp} (docs/tutorial.md, exercise 1).
#pragma once

#include "core/choice.hpp"
#include "riemann/segregation_flux.hpp"
#include "transport/limiter.hpp"

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace granseg {

/// A row of the scheme table.
struct SchemeRow {
    std::string_view name;     // value of [segregation] scheme
    InterfaceFlux flux;        // F at a face from the states either side (riemann/segregation_flux.hpp)
    int order;                 // 1: cell averages, one forward-Euler stage per axis; 2: limited
                               //    reconstruction of phi_hat (reconstruction.hpp) and SSP-RK(3,2)
    bool bounded;              // keeps 0 <= phi <= Phi for cfl <= 1 (then the solver clips round-off, G5)
    bool interface_values;     // reads Phi_face, a_face (one flux function per face)
    std::string_view summary;  // one line for `granseg run --help`
};

/// The segregation schemes. `bounded` is a claim that verify_overshoot and verify_table1_sweep
/// check for every row (kept if true, broken somewhere if false), `order` one that
/// verify_segregation_extensions checks on a smooth solution.
inline constexpr SchemeRow kSegregationSchemes[] = {
    // name               flux                   order bounded interface values
    {"modified-godunov", modified_godunov_flux, 1, true, false, "eqs. (61)-(63) with each cell's own flux function (default)"},
    {"modified-godunov-2", modified_godunov_flux, 2, true, false,
     "eq. (63) on limited reconstructions of phi_hat, SSP-RK(3,2) (beyond the paper)"},
    {"classic-upwind", classic_upwind_flux, 1, false, true,
     "Murman-Roe upwind flux of one flux function per face (Fig. 6 comparison)"},
    {"classic-godunov", classic_godunov_flux, 1, false, true, "Godunov flux of one flux function per face (Fig. 6 comparison)"},
    {"rusanov", rusanov_flux, 1, false, false, "local Lax-Friedrichs with each cell's own flux function (teaching example)"},
};

/// A segregation scheme: a row of kSegregationSchemes, held by its position.
class SegregationScheme {
public:
    /// The rows the code refers to by name (found by name at compile time).
    static const SegregationScheme modified_godunov, modified_godunov_2, classic_upwind, classic_godunov;

    /// The scheme called `name`; a compile-time error in a constant expression, InvariantError
    /// otherwise (scene files go through parse_scheme, which throws InputError).
    static constexpr SegregationScheme named(std::string_view name) {
        for (std::size_t i = 0; i < std::size(kSegregationSchemes); ++i)
            if (kSegregationSchemes[i].name == name) return SegregationScheme(i);
        throw InvariantError("no segregation scheme \"" + std::string(name) + "\"");
    }
    /// Every scheme, in the order of the table.
    static std::vector<SegregationScheme> all() {
        std::vector<SegregationScheme> schemes;
        for (std::size_t i = 0; i < std::size(kSegregationSchemes); ++i) schemes.push_back(SegregationScheme(i));
        return schemes;
    }

    constexpr const SchemeRow& row() const { return kSegregationSchemes[position_]; }
    constexpr bool operator==(SegregationScheme other) const { return position_ == other.position_; }
    constexpr bool operator!=(SegregationScheme other) const { return position_ != other.position_; }

private:
    constexpr explicit SegregationScheme(std::size_t position) : position_(position) {}
    std::size_t position_;
};

inline constexpr SegregationScheme SegregationScheme::modified_godunov = SegregationScheme::named("modified-godunov");
inline constexpr SegregationScheme SegregationScheme::modified_godunov_2 = SegregationScheme::named("modified-godunov-2");
inline constexpr SegregationScheme SegregationScheme::classic_upwind = SegregationScheme::named("classic-upwind");
inline constexpr SegregationScheme SegregationScheme::classic_godunov = SegregationScheme::named("classic-godunov");

/// Scene-file names of the schemes, in table order; the scheme of a name (InputError if unknown).
inline std::vector<std::string> scheme_names() { return choice_names(kSegregationSchemes); }
SegregationScheme parse_scheme(const std::string& name);
inline std::string scheme_name(SegregationScheme s) { return std::string(s.row().name); }
/// Names of the rows with bounded = true ("modified-godunov, modified-godunov-2").
std::string bounded_scheme_names();

/// Row fields, for readability at the call site.
inline bool preserves_bounds(SegregationScheme s) { return s.row().bounded; }
inline bool uses_interface_values(SegregationScheme s) { return s.row().interface_values; }
inline int scheme_order(SegregationScheme s) { return s.row().order; }

/// Bulk transport of a scene without a flow solver: the coupling contract's donor cell, or
/// flux-corrected transport (bulk_transport_fct.hpp).
enum class BulkScheme { donor_cell, fct };
inline constexpr Choice<BulkScheme> kBulkSchemes[] = {
    {BulkScheme::donor_cell, "donor-cell", "first-order donor cell in phi_hat (the coupling contract, eq. 65)"},
    {BulkScheme::fct, "fct", "flux-corrected transport (Zalesak), assumption T5 (tumbler-kinematic default)"},
};

inline std::vector<std::string> bulk_scheme_names() { return choice_names(kBulkSchemes); }
inline BulkScheme parse_bulk_scheme(const std::string& name) { return parse_choice(kBulkSchemes, name, "bulk scheme"); }
inline std::string bulk_scheme_name(BulkScheme b) { return choice_name(kBulkSchemes, b); }

}  // namespace granseg
