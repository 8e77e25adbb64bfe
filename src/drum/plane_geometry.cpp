#include "drum/plane_geometry.hpp"

#include <algorithm>
#include <cmath>

namespace granseg {

namespace {

double cross(Point2 a, Point2 b) { return a.x * b.z - a.z * b.x; }
double dot(Point2 a, Point2 b) { return a.x * b.x + a.z * b.z; }

/// Signed area of the sector of radius R between the directions of u and v (the shorter way round).
double sector(Point2 u, Point2 v, double R) { return 0.5 * R * R * std::atan2(cross(u, v), dot(u, v)); }

/// Signed area of the part of the triangle (0, a, b) inside the disc of radius R about 0.
double triangle_in_disc(Point2 a, Point2 b, double R) {
    const double R2 = R * R;
    if (dot(a, a) <= R2 && dot(b, b) <= R2) return 0.5 * cross(a, b);
    // The segment p(t) = a + t (b - a), t in [0, 1], meets the circle where |p(t)|^2 = R^2.
    const Point2 d{b.x - a.x, b.z - a.z};
    const double A = dot(d, d), B = dot(a, d), C = dot(a, a) - R2;
    if (A == 0.0) return 0.0;
    const double discriminant = B * B - A * C;
    if (discriminant <= 0.0) return sector(a, b, R);  // the line misses the open disc
    const double s = std::sqrt(discriminant), t1 = (-B - s) / A, t2 = (-B + s) / A;
    if (t2 <= 0.0 || t1 >= 1.0) return sector(a, b, R);  // the segment misses it
    const double u1 = std::max(t1, 0.0), u2 = std::min(t2, 1.0);
    const Point2 p1{a.x + u1 * d.x, a.z + u1 * d.z}, p2{a.x + u2 * d.x, a.z + u2 * d.z};
    // From a along the arc to p1 (none if a is inside), the chord's triangle, the arc from p2 to b.
    return (u1 > 0.0 ? sector(a, p1, R) : 0.0) + 0.5 * cross(p1, p2) + (u2 < 1.0 ? sector(p2, b, R) : 0.0);
}

}  // namespace

Polygon rectangle(double x0, double z0, double x1, double z1) { return {{x0, z0}, {x1, z0}, {x1, z1}, {x0, z1}}; }

double polygon_area(const Polygon& polygon) {
    double twice = 0.0;
    for (std::size_t v = 0; v < polygon.size(); ++v) twice += cross(polygon[v], polygon[(v + 1) % polygon.size()]);
    return 0.5 * twice;
}

Polygon clip_half_plane(const Polygon& polygon, Point2 normal, double offset) {
    Polygon out;
    for (std::size_t v = 0; v < polygon.size(); ++v) {
        const Point2 a = polygon[v], b = polygon[(v + 1) % polygon.size()];
        const double fa = dot(normal, a) - offset, fb = dot(normal, b) - offset;
        if (fa <= 0.0) out.push_back(a);
        if ((fa < 0.0 && fb > 0.0) || (fa > 0.0 && fb < 0.0)) {
            const double t = fa / (fa - fb);
            out.push_back({a.x + t * (b.x - a.x), a.z + t * (b.z - a.z)});
        }
    }
    return out;
}

Polygon clip_convex(const Polygon& polygon, const Polygon& convex) {
    Polygon out = polygon;
    for (std::size_t v = 0; v < convex.size() && !out.empty(); ++v) {
        const Point2 a = convex[v], b = convex[(v + 1) % convex.size()];
        const Point2 outward{b.z - a.z, a.x - b.x};  // the interior lies to the left of a -> b
        out = clip_half_plane(out, outward, dot(outward, a));
    }
    return out;
}

double area_in_disc(const Polygon& polygon, Point2 centre, double R) {
    double area = 0.0;
    for (std::size_t v = 0; v < polygon.size(); ++v) {
        const Point2 a = polygon[v], b = polygon[(v + 1) % polygon.size()];
        area += triangle_in_disc({a.x - centre.x, a.z - centre.z}, {b.x - centre.x, b.z - centre.z}, R);
    }
    return area;
}

double rectangle_area_in_disc(double x0, double z0, double x1, double z1, Point2 centre, double R) {
    // Nearest and farthest point of the rectangle from the centre.
    const double nx = std::clamp(centre.x, x0, x1) - centre.x, nz = std::clamp(centre.z, z0, z1) - centre.z;
    if (nx * nx + nz * nz >= R * R) return 0.0;
    const double fx = std::max(centre.x - x0, x1 - centre.x), fz = std::max(centre.z - z0, z1 - centre.z);
    if (fx * fx + fz * fz <= R * R) return (x1 - x0) * (z1 - z0);
    return std::clamp(area_in_disc(rectangle(x0, z0, x1, z1), centre, R), 0.0, (x1 - x0) * (z1 - z0));
}

double rectangle_area_in_convex(double x0, double z0, double x1, double z1, const Polygon& convex) {
    bool all_inside = true;
    for (std::size_t v = 0; v < convex.size(); ++v) {
        const Point2 a = convex[v], b = convex[(v + 1) % convex.size()];
        const Point2 outward{b.z - a.z, a.x - b.x};
        const double offset = dot(outward, a);
        // The rectangle's corner least and most out along this edge's outward normal.
        const double lo = outward.x * (outward.x > 0 ? x0 : x1) + outward.z * (outward.z > 0 ? z0 : z1);
        const double hi = outward.x * (outward.x > 0 ? x1 : x0) + outward.z * (outward.z > 0 ? z1 : z0);
        if (lo >= offset) return 0.0;
        all_inside = all_inside && hi <= offset;
    }
    if (all_inside) return (x1 - x0) * (z1 - z0);
    return std::clamp(polygon_area(clip_convex(rectangle(x0, z0, x1, z1), convex)), 0.0, (x1 - x0) * (z1 - z0));
}

}  // namespace granseg
