// Exact areas in the x-z plane: how much of a grid cell (a rectangle) lies inside a disc, a convex
// polygon or a half-plane. The drum diagnostics weigh each cell by the share of its area inside a
// region (drum/region_weights.hpp), and a drum of any cross-section is a set of such areas
// (drum/drum_shape.hpp).
//
//   solves      nothing over time: areas of intersections, exact up to round-off
//   inputs      polygons (vertices counter-clockwise), discs (centre, radius), half-planes
//   outputs     clipped polygons, signed and unsigned areas
//   invariants  0 <= area in a region <= the polygon's area; a cell wholly inside a region gets
//               exactly (x1 - x0)(z1 - z0), one wholly outside exactly 0
// Methods: Sutherland-Hodgman clipping of a polygon by half-planes (one per edge of a convex
// clipping polygon), the shoelace formula, and for a disc the sum over the polygon's edges of the
// signed area of the part of triangle(centre, edge) inside the disc (each a sector, a triangle, or sector + triangle +
// sector), exact for any simple polygon.
#pragma once

#include <vector>

namespace granseg {

struct Point2 {
    double x = 0, z = 0;
};

/// A polygon by its vertices in order (counter-clockwise for a positive area); no repeated end vertex.
using Polygon = std::vector<Point2>;

/// The rectangle [x0, x1] x [z0, z1] (x0 <= x1, z0 <= z1) as a counter-clockwise polygon.
Polygon rectangle(double x0, double z0, double x1, double z1);

/// Signed area (shoelace): > 0 for counter-clockwise vertices; 0 for fewer than three.
double polygon_area(const Polygon& polygon);

/// The part of `polygon` where normal . p <= offset (Sutherland-Hodgman; convex stays convex).
Polygon clip_half_plane(const Polygon& polygon, Point2 normal, double offset);

/// The part of `polygon` inside the convex, counter-clockwise polygon `convex`.
Polygon clip_convex(const Polygon& polygon, const Polygon& convex);

/// Area of the part of a simple polygon (counter-clockwise) inside the disc of radius R about `centre`.
double area_in_disc(const Polygon& polygon, Point2 centre, double R);

/// Area of the rectangle [x0, x1] x [z0, z1] inside the disc of radius R about `centre`: exactly
/// the rectangle's area if all four corners lie in the closed disc, exactly 0 if no point of the
/// rectangle lies inside.
double rectangle_area_in_disc(double x0, double z0, double x1, double z1, Point2 centre, double R);

/// Area of the rectangle [x0, x1] x [z0, z1] inside a convex, counter-clockwise polygon: exactly
/// the rectangle's area if all four corners lie inside (or on) it, exactly 0 if the rectangle lies
/// wholly outside one of its edges.
double rectangle_area_in_convex(double x0, double z0, double x1, double z1, const Polygon& convex);

}  // namespace granseg
