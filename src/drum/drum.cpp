#include "drum/drum.hpp"

#include "closures/closures.hpp"
#include "drum/bed.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace granseg {

Frame DrumSpec::frame() const {
    Frame f;
    f.gravity = gravity;
    f.omega = 2.0 * M_PI * rps;
    return f;
}

DrumShape DrumSpec::cross_section() const {
    return shape == DrumShapeKind::circle ? DrumShape::circle(radius())
                                          : DrumShape::polygon(sides, radius(), orientation * M_PI / 180.0);
}

Grid DrumSpec::grid() const { return drum_grid(cross_section(), cells_per_diameter, axial_cells, axial_length); }

double closest_surface_distance(const DrumSpec& drum) {
    const DrumShape shape = drum.cross_section();
    if (shape.kind() == DrumShapeKind::circle) return drum.surface_height();
    const double bed = shape.area_below(drum.surface_height(), 0.0);
    double closest = INFINITY;
    for (int step = 0; step < 720; ++step) closest = std::min(closest, shape.surface_offset(bed, step * M_PI / 360.0));
    return closest;
}

std::vector<double> drum_bed_at_rest(const DrumSpec& drum, const Grid& grid, const Material& material, double phi_hat, double T) {
    return lithostatic_bed(grid, material, drum.surface_height(), drum.gravity, T, material.packing.Phi_rcp(phi_hat),
                           material.packing.Phi_co(phi_hat));
}

std::vector<double> drum_bed_at_rest(const DrumSpec& drum, const Grid& grid, const Material& material,
                                     const std::vector<double>& phi_hat, double mixture, double T) {
    std::vector<double> Phi = drum_bed_at_rest(drum, grid, material, mixture, T);
    const std::vector<double> fill = drum_fill_fraction(drum, grid);
    const PackingFit& packing = material.packing;
    for (std::size_t c = 0; c < grid.cells(); ++c) {
        if (!(Phi[c] > 0.0) || phi_hat[c] == mixture) continue;
        const double p = evaluate_closures_at(material, Phi[c] / fill[c], T, packing.Phi_rcp(mixture), packing.Phi_co(mixture)).p;
        Phi[c] = fill[c] * volume_fraction_at_pressure(material, p, T, packing.Phi_rcp(phi_hat[c]), packing.Phi_co(phi_hat[c]));
    }
    return Phi;
}

std::vector<double> drum_fill_fraction(const DrumSpec& drum, const Grid& grid) {
    std::vector<double> fill(grid.cells(), 0.0);
    const double z_surface = drum.surface_height(), h = grid.h[2];
    for (int k = 0; k < grid.n[2]; ++k)
        for (int j = 0; j < grid.n[1]; ++j)
            for (int i = 0; i < grid.n[0]; ++i) {
                const std::size_t c = grid.index(i, j, k);
                const double bottom = grid.center(2, k) - 0.5 * h;
                if (grid.is_inside(c)) fill[c] = std::clamp((z_surface - bottom) / h, 0.0, 1.0);
            }
    return fill;
}

void TimeAverage::add(double t, double value) {
    if (!std::isfinite(value)) return;  // NaN: no surface crossing within 0.8 R
    t_.push_back(t), value_.push_back(value);
}

std::array<double, 3> TimeAverage::sums() const {
    std::array<double, 3> s{};
    for (std::size_t i = 0; i < t_.size(); ++i)
        if (t_[i] >= from_) s[0] += value_[i], s[1] += value_[i] * value_[i], s[2] += 1.0;
    return s;
}

long TimeAverage::samples() const { return static_cast<long>(sums()[2]); }

double TimeAverage::mean() const {
    const auto [sum, sum2, n] = sums();
    return n > 0 ? sum / n : std::numeric_limits<double>::quiet_NaN();
}

double TimeAverage::std_dev() const {
    const auto [sum, sum2, n] = sums();
    if (n == 0) return std::numeric_limits<double>::quiet_NaN();
    if (n == 1) return 0.0;
    const double m = sum / n;
    return std::sqrt(std::max(0.0, sum2 / n - m * m));
}

}  // namespace granseg
