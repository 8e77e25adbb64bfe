#include "segregation/invariants.hpp"

#include "core/error.hpp"
#include "core/format.hpp"

#include <cmath>

namespace granseg {

double total_amount(const Grid& grid, const std::vector<double>& u) {
    double sum = 0.0, carry = 0.0;  // Neumaier's compensated summation
    for (std::size_t c = 0; c < u.size(); ++c) {
        if (!grid.is_inside(c)) continue;
        const double t = sum + u[c];
        carry += std::fabs(sum) >= std::fabs(u[c]) ? (sum - t) + u[c] : (u[c] - t) + sum;
        sum = t;
    }
    return (sum + carry) * grid.cell_volume();
}

void BoundsMonitor::observe(const Grid& grid, const std::vector<double>& phi, const std::vector<double>& Phi) {
    for (std::size_t c = 0; c < phi.size(); ++c) {
        if (!grid.is_inside(c)) continue;
        if (!std::isfinite(phi[c])) {
            ++nonfinite;
            continue;
        }
        if (phi[c] - Phi[c] > max_excess) max_excess = phi[c] - Phi[c], where_excess = c;
        if (phi[c] < min_phi) min_phi = phi[c], where_min = c;
    }
}

void check_segregation_invariants(const std::string& context, const BoundsMonitor& bounds, double correction, double mass_start,
                                  double mass_now, double mass_scale, double mass_tolerance, bool check_bounds, double Phi_max) {
    if (bounds.nonfinite > 0)
        throw InvariantError(context + ": " + std::to_string(bounds.nonfinite) + " non-finite values of phi");
    const double drift = std::fabs(mass_now - mass_start) / (mass_scale > 0.0 ? mass_scale : 1.0);
    if (!(drift <= mass_tolerance))
        throw InvariantError(context + ": amount of small particles changed by " + format_number(drift, 3) +
                             " (relative; allowed " + format_number(mass_tolerance, 3) + ")");
    if (check_bounds && !(correction <= kBoundRoundOff * Phi_max))
        throw InvariantError(context + ": the scheme left 0 <= phi <= Phi by " + format_number(correction, 3) +
                             ", more than round-off (" + format_number(kBoundRoundOff * Phi_max, 3) + ")");
}

}  // namespace granseg
