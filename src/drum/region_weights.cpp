#include "drum/region_weights.hpp"

#include "core/error.hpp"
#include "drum/plane_geometry.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace granseg {

double cell_area_in_disc(const Grid& grid, int i, int k, double R) {
    const double x0 = grid.origin[0] + i * grid.h[0], z0 = grid.origin[2] + k * grid.h[2];
    return rectangle_area_in_disc(x0, z0, x0 + grid.h[0], z0 + grid.h[2], Point2{0.0, 0.0}, R);
}

std::vector<double> disc_weights(const Grid& grid, double R) {
    if (!(R >= 0.0)) throw InputError("disc weights: the radius must be >= 0");
    std::vector<double> w(grid.cells(), 0.0);
    const double area = grid.h[0] * grid.h[2];
    for (int k = 0; k < grid.n[2]; ++k)
        for (int i = 0; i < grid.n[0]; ++i) {
            const double share = cell_area_in_disc(grid, i, k, R) / area;
            for (int j = 0; j < grid.n[1]; ++j) {
                const std::size_t c = grid.index(i, j, k);
                if (grid.is_inside(c)) w[c] = share;
            }
        }
    return w;
}

std::vector<double> region_weights(const Grid& grid, double r_inner, double r_outer) {
    if (!(r_inner >= 0.0 && r_outer >= r_inner)) throw InputError("region weights: need 0 <= r_inner <= r_outer");
    std::vector<double> w = disc_weights(grid, r_outer);
    const std::vector<double> inner = disc_weights(grid, r_inner);
    for (std::size_t c = 0; c < w.size(); ++c) w[c] = std::max(0.0, w[c] - inner[c]);
    return w;
}

double weighted_share(const std::vector<double>& phi, const std::vector<double>& Phi, const std::vector<double>& weights,
                      double bed_level) {
    if (phi.size() != Phi.size() || weights.size() != Phi.size())
        throw InputError("weighted share: phi, Phi and the weights need one value per cell");
    double small = 0.0, all = 0.0;
    for (std::size_t c = 0; c < Phi.size(); ++c)
        if (Phi[c] > bed_level && weights[c] > 0.0) small += weights[c] * phi[c], all += weights[c] * Phi[c];
    return all > 0.0 ? small / all : std::numeric_limits<double>::quiet_NaN();
}

}  // namespace granseg
