// The invariants a segregation run checks while it runs: the amount of small particles (sum of
// phi; conserved with zero-flux walls), the bounds 0 <= phi <= Phi (kept by the modified schemes,
// broken by the classic ones, Sect. 4.1) and finite values.
#pragma once

#include "core/grid.hpp"

#include <cstddef>
#include <limits>
#include <string>
#include <vector>

namespace granseg {

/// Sum of u over the inside cells times the cell volume, with Neumaier compensation so that the
/// measurement itself adds no round-off at the 1e-15 level.
double total_amount(const Grid& grid, const std::vector<double>& u);

/// Running extremes of phi against its bounds over a run.
struct BoundsMonitor {
    double max_excess = -std::numeric_limits<double>::infinity();  // max of phi - Phi
    double min_phi = std::numeric_limits<double>::infinity();      // min of phi
    std::size_t where_excess = 0, where_min = 0;                   // cell index of each extreme
    long nonfinite = 0;                                            // non-finite values seen

    /// Updates the extremes with the inside cells of phi.
    void observe(const Grid& grid, const std::vector<double>& phi, const std::vector<double>& Phi);
};

/// Round-off allowance of the bounds: |violation| <= kBoundRoundOff * Phi_max counts as kept.
/// One update phi - (dt/h)(F_up - F_low) rounds four times, each by <= DBL_EPSILON/2 of a value
/// <= Phi; 8 DBL_EPSILON covers that with room (docs/sect2.2_segregation.md, "Bounds").
constexpr double kBoundRoundOff = 8 * std::numeric_limits<double>::epsilon();

/// Throws InvariantError (one line, naming `context`) for a non-finite value, for a relative
/// change of the amount above `mass_tolerance`, and, if `check_bounds`, for phi outside
/// [0, Phi] by more than kBoundRoundOff * Phi_max.
void check_segregation_invariants(const std::string& context, const BoundsMonitor& bounds, double mass_start,
                                  double mass_now, double mass_tolerance, bool check_bounds, double Phi_max);

}  // namespace granseg
