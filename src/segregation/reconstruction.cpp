#include "segregation/reconstruction.hpp"

#include "segregation/flux_difference.hpp"

#include <algorithm>
#include <cmath>

namespace granseg {

void reconstruct_faces(const Grid& grid, int axis, const std::vector<double>& phi, const std::vector<double>& Phi,
                       Limiter limiter, std::vector<double>& at_lower, std::vector<double>& at_upper) {
    at_lower = phi;
    at_upper = phi;
    std::vector<double> phi_hat(phi.size());
    for (std::size_t c = 0; c < phi.size(); ++c) phi_hat[c] = composition(phi[c], Phi[c]);
    // A cell reconstructs only if it and both neighbours hold material inside the domain.
    const auto usable = [&](std::size_t c) { return grid.is_inside(c) && Phi[c] > 0.0; };
    const std::size_t n = static_cast<std::size_t>(grid.n[axis]), stride = grid.stride(axis);
    const bool periodic = grid.periodic[axis];
    for_each_line(grid, axis, [&](std::size_t cell0, std::size_t) {
        for (std::size_t l = 0; l < n; ++l) {
            if (!periodic && (l == 0 || l == n - 1)) continue;  // next to a domain wall: first order
            const std::size_t i = cell0 + l * stride;
            const std::size_t lo = l > 0 ? i - stride : i + (n - 1) * stride;
            const std::size_t hi = l + 1 < n ? i + stride : cell0;
            if (!usable(i) || !usable(lo) || !usable(hi)) continue;
            const double h_lo = phi_hat[lo], h_i = phi_hat[i], h_hi = phi_hat[hi];
            const double half = 0.5 * limited_slope(h_i - h_lo, h_hi - h_i, limiter);
            const double lowest = std::min({h_lo, h_i, h_hi}), highest = std::max({h_lo, h_i, h_hi});
            at_lower[i] = Phi[i] * std::clamp(h_i - half, lowest, highest);
            at_upper[i] = Phi[i] * std::clamp(h_i + half, lowest, highest);
        }
    });
}

}  // namespace granseg
