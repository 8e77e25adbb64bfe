#include "drum/layer_regions.hpp"

#include "drum/region_weights.hpp"

#include <algorithm>
#include <limits>

namespace granseg {

LayerRegions::LayerRegions(const Grid& grid, double d, double R, double axis_radius)
    : grid_(grid),
      d_(d),
      periphery_(region_weights(grid, 0.8 * R, std::numeric_limits<double>::infinity())),
      axis_(disc_weights(grid, axis_radius)) {}

LayerRegionShares LayerRegions::shares(const std::vector<double>& phi, const std::vector<double>& Phi, double layer,
                                       double bed_level) const {
    LayerRegionShares s;
    s.r_core = d_ - layer;
    const double r_core = std::clamp(s.r_core, 0.0, std::max(d_, 0.0));
    s.core = weighted_share(phi, Phi, disc_weights(grid_, r_core), bed_level);
    s.ring = weighted_share(phi, Phi, region_weights(grid_, r_core, std::max(d_, 0.0)), bed_level);
    s.periphery = weighted_share(phi, Phi, periphery_, bed_level);
    s.axis = weighted_share(phi, Phi, axis_, bed_level);
    return s;
}

}  // namespace granseg
