// The 1-D column of Sect. 4.1: eq. (66), d_t phi + d_z(S sqrt(T) phi (phi - Phi)/Phi) = 0 on
// [0, length] with zero-flux ends, z up and gravity down, given profiles Phi(z) and T(z), plus
// optional remixing D (beyond the paper). Shared by the segregation1d scene, the verification
// programs and the benchmark, so they all run exactly the same discretisation.
//
//   solves      nothing over time: sets up eq. (66) on a column for SegregationSolver
//   inputs      ColumnSetup: cells, length, S, D, the profiles Phi(z), T(z), the interface rule
//   outputs     Column: the grid and FrozenFields (Phi and a_z = S sqrt(T) at centres and faces)
//   invariants  0 < Phi < 1 and T >= 0 wherever they are read (InputError otherwise)
#pragma once

#include "core/choice.hpp"
#include "segregation/frozen_fields.hpp"

#include <functional>
#include <string>
#include <vector>

namespace granseg {

/// Where the schemes with interface values take Phi and T at a face (docs/assumptions.md G2).
enum class InterfaceRule { exact, mean };
inline constexpr Choice<InterfaceRule> kInterfaceRules[] = {
    {InterfaceRule::exact, "exact", "Phi(z), T(z) evaluated at the face, \"the exact value\" of Sect. 4.1 (default)"},
    {InterfaceRule::mean, "mean", "the arithmetic mean of the two neighbouring cells"},
};
inline std::vector<std::string> interface_rule_names() { return choice_names(kInterfaceRules); }
inline InterfaceRule parse_interface_rule(const std::string& name) {
    return parse_choice(kInterfaceRules, name, "interface rule");  // InputError for an unknown name
}

struct ColumnSetup {
    int cells = 50;
    double length = 1.0;
    double S = 1.0;  // segregation rate: a = S sqrt(T) (eq. 66)
    double D = 0.0;  // remixing diffusivity
    std::function<double(double z)> Phi, T;
    InterfaceRule interface = InterfaceRule::exact;
};

struct Column {
    Grid grid;
    FrozenFields fields;       // Phi and a_z at the centres, Phi and a_z at the faces
    std::vector<double> z, T;  // cell centres and T there (for output)
};

/// The grid and the frozen fields of a column (Phi, T evaluated at the centres; at the faces as
/// the interface rule says). Throws InputError if a value is out of range.
Column make_column(const ColumnSetup& setup);

/// phi0 evaluated at the cell centres.
std::vector<double> column_profile(const Column& column, const std::function<double(double z)>& phi0);

}  // namespace granseg
