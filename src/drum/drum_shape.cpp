#include "drum/drum_shape.hpp"

#include "core/error.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace granseg {

namespace {

/// Outward unit normal of the polygon's side v (from corner v to corner v + 1).
Point2 side_normal(const Polygon& p, std::size_t v) {
    const Point2 a = p[v], b = p[(v + 1) % p.size()];
    const double length = std::hypot(b.x - a.x, b.z - a.z);
    return {(b.z - a.z) / length, (a.x - b.x) / length};
}

}  // namespace

DrumShape DrumShape::circle(double R) {
    if (!(R > 0.0 && std::isfinite(R))) throw InputError("drum shape: the radius must be > 0");
    DrumShape s;
    s.R_ = s.a_ = R;
    return s;
}

DrumShape DrumShape::polygon(int sides, double R, double orientation) {
    if (sides < 3) throw InputError("drum shape: a polygon needs sides >= 3");
    if (!(R > 0.0 && std::isfinite(R) && std::isfinite(orientation)))
        throw InputError("drum shape: the radius must be > 0 and the orientation finite");
    DrumShape s;
    s.kind_ = DrumShapeKind::polygon;
    s.R_ = R;
    s.a_ = R * std::cos(M_PI / sides);
    s.orientation_ = orientation;
    // At orientation 0 the bottom side joins the corners at -pi/2 -+ pi/n.
    for (int v = 0; v < sides; ++v) {
        const double angle = -M_PI / 2 - M_PI / sides + 2 * M_PI * v / sides + orientation;
        s.corners_.push_back({R * std::cos(angle), R * std::sin(angle)});
    }
    return s;
}

bool DrumShape::inside(double x, double z) const {
    if (kind_ == DrumShapeKind::circle) return x * x + z * z < R_ * R_;
    return gauge(x, z) < R_;
}

double DrumShape::gauge(double x, double z) const {
    if (kind_ == DrumShapeKind::circle) return std::hypot(x, z);
    double largest = 0.0;
    for (std::size_t v = 0; v < corners_.size(); ++v) {
        const Point2 n = side_normal(corners_, v);
        largest = std::max(largest, n.x * x + n.z * z);
    }
    return R_ * largest / a_;
}

double DrumShape::area() const { return kind_ == DrumShapeKind::circle ? M_PI * R_ * R_ : polygon_area(corners_); }

double DrumShape::lowest() const {
    if (kind_ == DrumShapeKind::circle) return -R_;
    double z = std::numeric_limits<double>::infinity();
    for (const Point2& p : corners_) z = std::min(z, p.z);
    return z;
}

double DrumShape::highest() const {
    if (kind_ == DrumShapeKind::circle) return R_;
    double z = -std::numeric_limits<double>::infinity();
    for (const Point2& p : corners_) z = std::max(z, p.z);
    return z;
}

double DrumShape::half_width() const {
    if (kind_ == DrumShapeKind::circle) return R_;
    double x = 0.0;
    for (const Point2& p : corners_) x = std::max(x, std::fabs(p.x));
    return x;
}

double DrumShape::area_in_rectangle(double x0, double z0, double x1, double z1) const {
    return kind_ == DrumShapeKind::circle ? rectangle_area_in_disc(x0, z0, x1, z1, {0.0, 0.0}, R_)
                                          : rectangle_area_in_convex(x0, z0, x1, z1, corners_);
}

double DrumShape::chord(double offset, double direction) const {
    if (kind_ == DrumShapeKind::circle) return 2.0 * std::sqrt(std::max(0.0, R_ * R_ - offset * offset));
    // The line p(t) = offset n + t u, u = (cos, sin), n = (-sin, cos), against each side's half-plane.
    const Point2 u{std::cos(direction), std::sin(direction)}, p{-offset * u.z, offset * u.x};
    double lo = -std::numeric_limits<double>::infinity(), hi = std::numeric_limits<double>::infinity();
    for (std::size_t v = 0; v < corners_.size(); ++v) {
        const Point2 n = side_normal(corners_, v);
        const double along = n.x * u.x + n.z * u.z, room = a_ - (n.x * p.x + n.z * p.z);
        if (along > 0.0)
            hi = std::min(hi, room / along);
        else if (along < 0.0)
            lo = std::max(lo, room / along);
        else if (room <= 0.0)
            return 0.0;
    }
    return std::max(0.0, hi - lo);
}

double DrumShape::area_below(double offset, double direction) const {
    const Point2 normal{-std::sin(direction), std::cos(direction)};
    if (kind_ == DrumShapeKind::circle) {
        const double d = std::clamp(offset, -R_, R_);  // circular segment above the line, taken from the disc
        const double segment = R_ * R_ * std::acos(d / R_) - d * std::sqrt(R_ * R_ - d * d);
        return M_PI * R_ * R_ - segment;
    }
    return polygon_area(clip_half_plane(corners_, normal, offset));
}

double DrumShape::surface_offset(double area, double direction) const {
    if (!(area > 0.0 && area < this->area())) throw InputError("drum shape: a bed must fill part of the drum");
    double lo = -R_, hi = R_;  // area_below rises from 0 to the whole area across [-R, R]
    for (int it = 0; it < 200 && hi - lo > 4e-16 * R_; ++it) {
        const double mid = 0.5 * (lo + hi);
        (area_below(mid, direction) < area ? lo : hi) = mid;
    }
    return 0.5 * (lo + hi);
}

}  // namespace granseg
