// The cross-section of a rotating drum in the frame that turns with it: the circle of Sect. 4.2 or
// a regular polygon (the square and triangular drums of the segregation literature,
// docs/drum_shapes.md). The axis is the origin; the solver sees a drum as its inside cells
// (drum/drum.hpp), the diagnostics as exact areas and lengths (drum/plane_geometry.hpp).
//
//   solves      nothing over time: inside tests, areas, chords, the free surface's distance
//   inputs      the radius R of the circle through the corners; sides and orientation of a polygon
//   outputs     geometry of the shape
//   invariants  a shape is convex and holds the axis; gauge = R on the wall, < R inside
//
// A polygon's orientation is the angle (rad, counter-clockwise) it is turned from the position
// with one side at the bottom, horizontal; at orientation 0 every regular polygon is symmetric
// under x -> -x.
#pragma once

#include "drum/plane_geometry.hpp"

namespace granseg {

enum class DrumShapeKind { circle, polygon };

class DrumShape {
public:
    /// The circle of radius R about the axis.
    static DrumShape circle(double R);
    /// The regular polygon with `sides` >= 3 corners on the circle of radius R about the axis.
    static DrumShape polygon(int sides, double R, double orientation);

    DrumShapeKind kind() const { return kind_; }
    int sides() const { return static_cast<int>(corners_.size()); }  // 0 for the circle
    double orientation() const { return orientation_; }
    double radius() const { return R_; }                 // the circle through the corners (m)
    double inradius() const { return a_; }               // the largest circle about the axis inside (m)
    const Polygon& corners() const { return corners_; }  // counter-clockwise; empty for the circle

    /// True for a point strictly inside.
    bool inside(double x, double z) const;
    /// The shape's own radius of a point: R times the factor by which the shape must be scaled
    /// about the axis to reach it (its gauge); the distance from the axis for the circle. The wall
    /// is gauge = R, and gauge < s R is the shape scaled by s.
    double gauge(double x, double z) const;
    double area() const;
    /// Lowest and highest z, and the largest |x|, of the shape.
    double lowest() const;
    double highest() const;
    double half_width() const;
    /// Exact area of the rectangle [x0, x1] x [z0, z1] inside the shape.
    double area_in_rectangle(double x0, double z0, double x1, double z1) const;
    /// Length of the line {p : -sin(direction) x + cos(direction) z = offset} inside the shape.
    double chord(double offset, double direction) const;
    /// Area of the shape on the side -sin(direction) x + cos(direction) z < offset of that line.
    double area_below(double offset, double direction) const;
    /// The offset of the line at `direction` below which the shape holds `area` (bisection to
    /// round-off): the distance from the axis of a flat free surface over a bed of that area.
    double surface_offset(double area, double direction) const;

private:
    DrumShapeKind kind_ = DrumShapeKind::circle;
    double R_ = 0, a_ = 0, orientation_ = 0;
    Polygon corners_;
};

}  // namespace granseg
