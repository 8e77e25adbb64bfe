#include "segregation/reconstruction.hpp"

#include <algorithm>
#include <cmath>

namespace granseg {

double limited_slope(double below, double above, Limiter limiter) {
    if (below * above <= 0.0) return 0.0;  // extremum or flat side: first order
    const double sign = below > 0.0 ? 1.0 : -1.0;
    const double a = std::fabs(below), b = std::fabs(above);
    if (limiter == Limiter::minmod) return sign * std::min(a, b);
    return sign * std::min({2.0 * a, 2.0 * b, 0.5 * (a + b)});  // monotonized central
}

void reconstruct_faces(const Grid& grid, int axis, const std::vector<double>& phi, const std::vector<double>& Phi,
                       Limiter limiter, std::vector<double>& at_lower, std::vector<double>& at_upper) {
    at_lower.resize(phi.size());
    at_upper.resize(phi.size());
    const int n = grid.n[axis];
    const std::size_t stride = grid.stride(axis);
    std::array<int, 3> c{0, 0, 0};
    for (c[2] = 0; c[2] < grid.n[2]; ++c[2])
        for (c[1] = 0; c[1] < grid.n[1]; ++c[1])
            for (c[0] = 0; c[0] < grid.n[0]; ++c[0]) {
                const std::size_t i = grid.index(c[0], c[1], c[2]);
                at_lower[i] = at_upper[i] = phi[i];
                if (!grid.is_inside(i) || !(Phi[i] > 0.0)) continue;
                const int layer = c[axis];
                const bool wrap = grid.periodic[axis];
                if (!wrap && (layer == 0 || layer == n - 1)) continue;  // domain wall: first order
                const std::size_t lo = layer > 0 ? i - stride : i + (n - 1) * stride;
                const std::size_t hi = layer < n - 1 ? i + stride : i - (n - 1) * stride;
                if (!grid.is_inside(lo) || !grid.is_inside(hi) || !(Phi[lo] > 0.0) || !(Phi[hi] > 0.0)) continue;
                const double h_lo = composition(phi[lo], Phi[lo]);
                const double h_i = composition(phi[i], Phi[i]);
                const double h_hi = composition(phi[hi], Phi[hi]);
                const double half = 0.5 * limited_slope(h_i - h_lo, h_hi - h_i, limiter);
                const double lowest = std::min({h_lo, h_i, h_hi}), highest = std::max({h_lo, h_i, h_hi});
                at_lower[i] = Phi[i] * std::clamp(h_i - half, lowest, highest);
                at_upper[i] = Phi[i] * std::clamp(h_i + half, lowest, highest);
            }
}

}  // namespace granseg
