// The invariants a segregation run checks while it runs: the amount of small particles (sum of
// phi; conserved with zero-flux walls), the bounds 0 <= phi <= Phi (kept by the modified schemes,
// broken by the classic ones, Sect. 4.1) and finite values.
//
//   solves      nothing: measures a run against its invariants
//   inputs      the grid, phi, Phi, the amounts at the start and now, the solver's largest clip
//   outputs     total_amount, BoundsMonitor; InvariantError when an invariant is broken
//   invariants  sum of phi (zero-flux walls), 0 <= phi <= Phi (bounded schemes), finite phi
#pragma once

#include "core/grid.hpp"
#include "run/state_io.hpp"

#include <cstddef>
#include <limits>
#include <string>
#include <vector>

namespace granseg {

/// Sum of u over the inside cells times the cell volume, with Neumaier compensation so that the
/// measurement itself adds no round-off at the 1e-15 level.
double total_amount(const Grid& grid, const std::vector<double>& u);

/// Relative change of the amount of small particles (or of large ones) a run may show: eq. (64)
/// with zero-flux walls conserves it to round-off (the telescoping sums of ~1e4 steps round to
/// ~1e-14; verify_overshoot measures ~1e-16 in the column); 1e-12 flags a real leak. The 1-D
/// column, the kinematic and the coupled drum check against it.
constexpr double kAmountTolerance = 1e-12;

/// Running extremes of phi against its bounds over a run.
struct BoundsMonitor {
    double max_excess = -std::numeric_limits<double>::infinity();  // max of phi - Phi
    double min_phi = std::numeric_limits<double>::infinity();      // min of phi
    std::size_t where_excess = 0, where_min = 0;                   // cell index of each extreme
    long nonfinite = 0;                                            // non-finite values seen

    /// Updates the extremes with the inside cells of phi.
    void observe(const Grid& grid, const std::vector<double>& phi, const std::vector<double>& Phi);
    void checkpoint(StateIO& io) {
        io("max_excess", max_excess)("min_phi", min_phi)("where_excess", where_excess)("where_min", where_min)("nonfinite",
                                                                                                               nonfinite);
    }
};

/// Round-off allowance of the bounds: a scheme that keeps 0 <= phi <= Phi in real arithmetic
/// may leave [0, Phi] by rounding only. One update (u + g_low) - g_up rounds twice, each time by
/// <= DBL_EPSILON/2 of a value below 1.25 Phi; 8 DBL_EPSILON of Phi_max covers that with room.
constexpr double kBoundRoundOff = 8 * std::numeric_limits<double>::epsilon();

/// Throws InvariantError (one line, naming `context`) for a non-finite value, for a change of the
/// amount, |mass_now - mass_start| / mass_scale (absolute if mass_scale is 0), above
/// `mass_tolerance`, and, if `check_bounds`, if the scheme left
/// [0, Phi] by more than kBoundRoundOff * Phi_max before its round-off guard clipped it
/// (`correction`, SegregationSolver::largest_correction).
void check_segregation_invariants(const std::string& context, const BoundsMonitor& bounds, double correction, double mass_start,
                                  double mass_now, double mass_scale, double mass_tolerance, bool check_bounds, double Phi_max);

}  // namespace granseg
