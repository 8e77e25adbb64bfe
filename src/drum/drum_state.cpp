#include "drum/drum_state.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

namespace granseg {

DrumState drum_state(const FlowSolver& s, double Phi_level, double radius, double v_flow, const DrumShape* shape) {
    const Grid& g = s.grid();
    const Frame& f = s.frame();
    DrumState d{};
    // Crossings of Phi = Phi_level along x and z between neighbouring inside cells (slice j = 0).
    std::vector<std::array<double, 2>> points;
    for (int k = 0; k < g.n[2]; ++k)
        for (int i = 0; i < g.n[0]; ++i) {
            const std::size_t c = g.index(i, 0, k);
            if (!g.is_inside(c)) continue;
            for (int a : {0, 2}) {
                const int ni = a == 0 ? i + 1 : i, nk = a == 2 ? k + 1 : k;
                if (ni >= g.n[0] || nk >= g.n[2] || !g.is_inside(g.index(ni, 0, nk))) continue;
                const double p0 = s.Phi()[c], p1 = s.Phi()[g.index(ni, 0, nk)];
                if ((p0 - Phi_level) * (p1 - Phi_level) >= 0.0 || p0 == p1) continue;
                const double w = (Phi_level - p0) / (p1 - p0);
                const double x = g.center(0, i) + (a == 0 ? w * g.h[0] : 0.0), z = g.center(2, k) + (a == 2 ? w * g.h[2] : 0.0);
                const double r = shape ? shape->gauge(x - f.x_c, z - f.z_c) : std::hypot(x - f.x_c, z - f.z_c);
                if (r < radius) points.push_back({x, z});
            }
        }
    d.surface_points = static_cast<int>(points.size());
    d.surface_angle_deg = NAN;
    d.surface_distance = d.surface_offset = d.surface_direction = NAN;
    if (points.size() >= 2) {
        double mx = 0, mz = 0;
        for (const auto& p : points) mx += p[0], mz += p[1];
        mx /= points.size(), mz /= points.size();
        double sxx = 0, sxz = 0, szz = 0;
        for (const auto& p : points)
            sxx += (p[0] - mx) * (p[0] - mx), sxz += (p[0] - mx) * (p[1] - mz), szz += (p[1] - mz) * (p[1] - mz);
        const double theta = 0.5 * std::atan2(2 * sxz, sxx - szz);  // principal direction of the points
        d.surface_offset = -(mx - f.x_c) * std::sin(theta) + (mz - f.z_c) * std::cos(theta);
        d.surface_distance = std::fabs(d.surface_offset);
        d.surface_direction = theta;
        const Vec3 gv = f.gravity_at(s.time());
        const double horizontal = std::atan2(gv[0], -gv[2]);  // direction of g rotated by +90 degrees
        double angle = theta - horizontal;
        while (angle > M_PI / 2) angle -= M_PI;
        while (angle <= -M_PI / 2) angle += M_PI;
        // Measured counter-clockwise; a drum turning clockwise lifts the surface the other way.
        d.surface_angle_deg = (f.omega < 0.0 ? -1.0 : 1.0) * angle * 180.0 / M_PI;
    }
    double mass = 0.0, flowing = 0.0;
    const double cell_area = g.cell_volume() / (g.n[1] * g.h[1]);
    for (std::size_t c = 0; c < g.cells(); ++c) {
        if (!g.is_inside(c)) continue;
        const double speed = std::sqrt(s.u(0)[c] * s.u(0)[c] + s.u(1)[c] * s.u(1)[c] + s.u(2)[c] * s.u(2)[c]);
        mass += s.Phi()[c];
        if (speed > v_flow) flowing += s.Phi()[c];
        if (s.Phi()[c] > Phi_level) d.max_speed = std::max(d.max_speed, speed);
        if (s.Phi()[c] > Phi_level && speed > v_flow) d.flowing_area += cell_area;
        d.kinetic_energy += 0.5 * s.Phi()[c] * speed * speed * g.cell_volume();
    }
    d.flowing_fraction = mass > 0.0 ? flowing / mass : 0.0;
    if (!(v_flow > 0.0)) d.flowing_fraction = d.flowing_area = NAN;  // a drum at rest: no wall speed to measure by
    return d;
}

}  // namespace granseg
