#include "coupled/material_points.hpp"

#include "core/threads.hpp"

#include <cmath>
#include <limits>

namespace granseg {

MaterialPoints::MaterialPoints(const Grid& grid, const std::vector<double>& Phi, double bed_level,
                               const std::function<double(double x, double z)>& mark)
    : grid_(grid) {
    for (int k = 0; k < grid.n[2]; ++k)
        for (int i = 0; i < grid.n[0]; ++i) {
            const std::size_t c = grid.index(i, 0, k);
            if (!grid.is_inside(c) || !(Phi[c] > bed_level)) continue;
            for (const double dx : {-0.25, 0.25})
                for (const double dz : {-0.25, 0.25}) {
                    const double x = grid.center(0, i) + dx * grid.h[0], z = grid.center(2, k) + dz * grid.h[2];
                    x_.push_back(x), z_.push_back(z), marked_.push_back(mark(x, z) >= 0.5);
                }
        }
}

double MaterialPoints::interpolate(const std::vector<double>& f, double x, double z) const {
    const double s = (x - grid_.origin[0]) / grid_.h[0] - 0.5, t = (z - grid_.origin[2]) / grid_.h[2] - 0.5;
    const int i0 = static_cast<int>(std::floor(s)), k0 = static_cast<int>(std::floor(t));
    const double fx = s - i0, fz = t - k0;
    double value = 0.0;
    for (int dk = 0; dk < 2; ++dk)
        for (int di = 0; di < 2; ++di) {
            const int i = i0 + di, k = k0 + dk;
            if (i < 0 || k < 0 || i >= grid_.n[0] || k >= grid_.n[2]) continue;
            const std::size_t c = grid_.index(i, 0, k);
            if (grid_.is_inside(c)) value += (di ? fx : 1.0 - fx) * (dk ? fz : 1.0 - fz) * f[c];
        }
    return value;
}

void MaterialPoints::advance(const std::vector<double>& ux, const std::vector<double>& uz, double dt) {
    // On the threads where the drum's grid runs on them (one rule for the whole run).
    parallel_for(threads_pay(grid_.cells()), x_.size(), [&](std::size_t p) {
        const double xm = x_[p] + 0.5 * dt * interpolate(ux, x_[p], z_[p]), zm = z_[p] + 0.5 * dt * interpolate(uz, x_[p], z_[p]);
        x_[p] += dt * interpolate(ux, xm, zm), z_[p] += dt * interpolate(uz, xm, zm);
    });
}

double MaterialPoints::marked_share_within(double r) const {
    long inside = 0, marked = 0;
    for (std::size_t p = 0; p < x_.size(); ++p)
        if (std::hypot(x_[p], z_[p]) < r) ++inside, marked += marked_[p];
    return inside > 0 ? static_cast<double>(marked) / inside : std::numeric_limits<double>::quiet_NaN();
}

}  // namespace granseg
