#include "drum/bed.hpp"

#include "closures/closures.hpp"
#include "core/error.hpp"

#include <algorithm>
#include <cmath>

namespace granseg {

Grid drum_grid(const DrumShape& shape, int n, int ny, double ly) {
    if (n < 4 || ny < 1 || !(ly > 0)) throw InputError("drum_grid: need n >= 4, ny >= 1, ly > 0");
    const double R = shape.radius();
    Grid g = Grid::plane_xz(n, n, -R, -R, 2 * R, 2 * R);
    if (shape.kind() != DrumShapeKind::circle) {
        const double h = 2 * R / n;
        // Whole cells over the extent (the 1e-9 keeps an extent of exactly m cells at m).
        const auto cells = [h](double length) { return std::max(1, static_cast<int>(std::ceil(length / h - 1e-9))); };
        const int nx = cells(2 * shape.half_width()), nz = cells(shape.highest() - shape.lowest());
        const double z_mid = 0.5 * (shape.lowest() + shape.highest());
        g = Grid::plane_xz(nx, nz, -0.5 * nx * h, z_mid - 0.5 * nz * h, nx * h, nz * h);
    }
    g.n[1] = ny;
    g.h[1] = ny > 1 ? ly / ny : 1.0;
    g.periodic[1] = ny > 1;
    g.inside.assign(g.cells(), 0);
    for (int k = 0; k < g.n[2]; ++k)
        for (int j = 0; j < ny; ++j)
            for (int i = 0; i < g.n[0]; ++i) g.inside[g.index(i, j, k)] = shape.inside(g.center(0, i), g.center(2, k)) ? 1 : 0;
    return g;
}

Grid drum_grid(int n, double R, int ny, double ly) {
    if (!(R > 0)) throw InputError("drum_grid: need n >= 4, ny >= 1, R > 0");
    return drum_grid(DrumShape::circle(R), n, ny, ly);
}

double volume_fraction_at_pressure(const Material& m, double p, double T, double Phi_rcp, double Phi_co) {
    if (!(p > 0.0)) return 0.0;
    double lo = 0.0, hi = Phi_rcp;  // p(lo) <= p < p(hi) = inf
    for (int it = 0; it < 200 && hi - lo > 4e-16 * hi; ++it) {
        const double mid = 0.5 * (lo + hi);
        (evaluate_closures_at(m, mid, T, Phi_rcp, Phi_co).p < p ? lo : hi) = mid;
    }
    return 0.5 * (lo + hi);
}

std::vector<double> lithostatic_bed(const Grid& grid, const Material& m, double z_surface, double gravity, double T,
                                    double Phi_rcp, double Phi_co) {
    std::vector<double> Phi(grid.cells(), 0.0);
    const double h = grid.h[2];
    const int sub = 16;
    // -dp/dz. Below p(Phi_co) the kinetic branch p = Phi g T holds a dilute layer only T/|g| thick
    // (1e-13 m at T = 1e-12 m^2/s^2): it is skipped, so the integration starts on the dense branch.
    const double p_co = evaluate_closures_at(m, Phi_co, T, Phi_rcp, Phi_co).p;
    auto rate = [&](double p) { return gravity * volume_fraction_at_pressure(m, std::max(p, p_co), T, Phi_rcp, Phi_co); };
    // p at each cell centre below the surface, integrated downwards from p(z_surface) = 0.
    std::vector<double> p_center(grid.n[2], 0.0);
    double p = 0.0, z = z_surface;
    for (int k = grid.n[2] - 1; k >= 0; --k) {
        const double zc = grid.center(2, k);
        if (zc >= z_surface) continue;
        const double dz = (z - zc) / sub;
        for (int s = 0; s < sub; ++s) {  // classical RK4 in the depth z_surface - z
            const double k1 = rate(p), k2 = rate(p + 0.5 * dz * k1), k3 = rate(p + 0.5 * dz * k2), k4 = rate(p + dz * k3);
            p += dz * (k1 + 2 * k2 + 2 * k3 + k4) / 6.0;
        }
        z = zc;
        p_center[k] = p;
    }
    for (int k = 0; k < grid.n[2]; ++k) {
        const double bottom = grid.origin[2] + k * h;
        const double filled = std::min(1.0, std::max(0.0, (z_surface - bottom) / h));
        if (filled <= 0.0) continue;
        // The surface cell: the material of its filled part at the pressure of its lower half.
        const double p_cell = filled < 1.0 ? 0.5 * filled * h * rate(0.0) : p_center[k];  // rate(0) = |g| Phi(p_co)
        const double value = filled * volume_fraction_at_pressure(m, p_cell, T, Phi_rcp, Phi_co);
        for (int j = 0; j < grid.n[1]; ++j)
            for (int i = 0; i < grid.n[0]; ++i) {
                const std::size_t c = grid.index(i, j, k);
                if (grid.is_inside(c)) Phi[c] = value;
            }
    }
    return Phi;
}

}  // namespace granseg
