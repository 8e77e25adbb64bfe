// Exact areas of cells inside discs, convex polygons and half-planes (drum/plane_geometry.hpp) and
// the region weights built on them (drum/region_weights.hpp), against closed-form areas.
// Tolerances: each area is a sum of a few (tiled grids: a few thousand) terms of size <= the
// answer, each rounded once or twice, so 1e-13 relative holds with a wide margin.
#include "drum/plane_geometry.hpp"
#include "core/error.hpp"
#include "drum/region_weights.hpp"

#include <boost/test/unit_test.hpp>

#include <cmath>
#include <limits>

using namespace granseg;
namespace tt = boost::test_tools;

namespace {

/// Sum of rectangle_area_in_disc over an n x n grid of cells covering [-L, L]^2.
double tiled_disc_area(int n, double L, Point2 centre, double R) {
    const double h = 2 * L / n;
    double sum = 0.0;
    for (int k = 0; k < n; ++k)
        for (int i = 0; i < n; ++i)
            sum += rectangle_area_in_disc(-L + i * h, -L + k * h, -L + (i + 1) * h, -L + (k + 1) * h, centre, R);
    return sum;
}

Polygon regular(int sides, double R, double start) {
    Polygon p;
    for (int v = 0; v < sides; ++v)
        p.push_back({R * std::cos(start + 2 * M_PI * v / sides), R * std::sin(start + 2 * M_PI * v / sides)});
    return p;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(drum_plane_geometry_tests)

BOOST_AUTO_TEST_CASE(cells_wholly_inside_or_outside_are_exact) {
    BOOST_TEST(rectangle_area_in_disc(0.1, 0.2, 0.3, 0.7, {0, 0}, 1.0) == (0.3 - 0.1) * (0.7 - 0.2));
    BOOST_TEST(rectangle_area_in_disc(1.0, 0.0, 2.0, 1.0, {0, 0}, 1.0) == 0.0);  // touches at one point
    BOOST_TEST(rectangle_area_in_disc(-1, -1, 1, 1, {0, 0}, std::sqrt(2.0) + 1e-15) == 4.0);
    BOOST_TEST(rectangle_area_in_disc(0, 0, 1, 1, {0, 0}, std::numeric_limits<double>::infinity()) == 1.0);
    const Polygon triangle{{0, 0}, {2, 0}, {0, 2}};
    BOOST_TEST(rectangle_area_in_convex(0, 0, 1, 1, triangle) == 1.0);  // corner (1, 1) on the edge
    BOOST_TEST(rectangle_area_in_convex(1, 1, 2, 2, triangle) == 0.0);
}

BOOST_AUTO_TEST_CASE(rectangles_cut_by_a_circle) {
    const double R = 0.7;
    // The disc inside the square: pi R^2; a quarter of it in the quadrant's square.
    BOOST_TEST(rectangle_area_in_disc(-1, -1, 1, 1, {0, 0}, R) == M_PI * R * R, tt::tolerance(1e-14));
    BOOST_TEST(rectangle_area_in_disc(0, 0, 1, 1, {0, 0}, R) == M_PI * R * R / 4, tt::tolerance(1e-14));
    // The square [-a, a]^2 with a < R < a sqrt(2): the disc less four segments of height R - a.
    const double a = 0.6, segment = R * R * std::acos(a / R) - a * std::sqrt(R * R - a * a);
    BOOST_TEST(rectangle_area_in_disc(-a, -a, a, a, {0, 0}, R) == M_PI * R * R - 4 * segment, tt::tolerance(1e-14));
    // A half disc about an off-origin centre on the rectangle's lower edge.
    BOOST_TEST(rectangle_area_in_disc(0, 0, 1, 1, {0.5, 0.0}, 0.5) == M_PI / 8, tt::tolerance(1e-14));
    // One segment: the strip z >= z0 of the disc.
    const double z0 = 0.3, cap = R * R * std::acos(z0 / R) - z0 * std::sqrt(R * R - z0 * z0);
    BOOST_TEST(rectangle_area_in_disc(-1, z0, 1, 1, {0, 0}, R) == cap, tt::tolerance(1e-14));
}

BOOST_AUTO_TEST_CASE(cells_tiling_a_disc_sum_to_its_area) {
    for (const Point2 centre : {Point2{0, 0}, Point2{0.013, -0.21}})
        for (int n : {7, 50, 101}) BOOST_TEST(tiled_disc_area(n, 1.0, centre, 0.63) == M_PI * 0.63 * 0.63, tt::tolerance(1e-13));
}

BOOST_AUTO_TEST_CASE(cells_in_regular_polygons_sum_to_their_areas) {
    for (int sides : {3, 4, 6, 512}) {
        const double R = 0.9, exact = 0.5 * sides * R * R * std::sin(2 * M_PI / sides);
        const Polygon p = regular(sides, R, 0.3);
        BOOST_TEST(polygon_area(p) == exact, tt::tolerance(1e-13));
        const int n = 64;
        const double h = 2.0 / n;
        double sum = 0.0;
        for (int k = 0; k < n; ++k)
            for (int i = 0; i < n; ++i)
                sum += rectangle_area_in_convex(-1 + i * h, -1 + k * h, -1 + (i + 1) * h, -1 + (k + 1) * h, p);
        BOOST_TEST(sum == exact, tt::tolerance(1e-13));
    }
    // The line x + z = 2 cuts a unit triangle from the square [0.5, 1.5]^2.
    BOOST_TEST(rectangle_area_in_convex(0.5, 0.5, 1.5, 1.5, {{0, 0}, {2, 0}, {0, 2}}) == 0.5, tt::tolerance(1e-14));
}

BOOST_AUTO_TEST_CASE(polygons_clipped_by_half_planes_and_discs) {
    const Polygon square = rectangle(0, 0, 1, 1);
    BOOST_TEST(polygon_area(square) == 1.0);
    BOOST_TEST(polygon_area(clip_half_plane(square, {1, 1}, 1.0)) == 0.5, tt::tolerance(1e-15));  // x + z <= 1
    BOOST_TEST(clip_half_plane(square, {0, 1}, -0.1).empty());                                    // z <= -0.1
    // A triangle inside a large disc keeps its area; a polygon around a disc holds all of it.
    const Polygon triangle{{0.1, 0.1}, {0.4, 0.1}, {0.1, 0.5}};
    BOOST_TEST(area_in_disc(triangle, {0, 0}, 10.0) == polygon_area(triangle), tt::tolerance(1e-14));
    BOOST_TEST(area_in_disc(regular(6, 2.0, 0.0), {0.1, 0.2}, 0.5) == M_PI * 0.25, tt::tolerance(1e-14));
}

BOOST_AUTO_TEST_CASE(region_weights_split_every_cell) {
    const Grid g = Grid::plane_xz(40, 40, -1.0, -1.0, 2.0, 2.0);
    const double r1 = 0.31, r2 = 0.77, inf = std::numeric_limits<double>::infinity();
    const auto core = region_weights(g, 0.0, r1), ring = region_weights(g, r1, r2), rest = region_weights(g, r2, inf);
    double disc = 0.0;
    for (std::size_t c = 0; c < g.cells(); ++c) {
        BOOST_TEST(core[c] + ring[c] + rest[c] == 1.0, tt::tolerance(1e-14));
        disc += (core[c] + ring[c]) * g.h[0] * g.h[2];
    }
    BOOST_TEST(disc == M_PI * r2 * r2, tt::tolerance(1e-13));
    BOOST_TEST(cell_area_in_disc(g, 20, 20, r1) == g.h[0] * g.h[2]);  // the cell at the centre's corner
    BOOST_CHECK_THROW(region_weights(g, r2, r1), InputError);
    // A uniform mixture has its own phi_hat in every weighted region; wall cells weigh nothing.
    std::vector<double> Phi(g.cells(), 0.6), phi(g.cells(), 0.6 * 0.3);
    BOOST_TEST(weighted_share(phi, Phi, ring, 0.0) == 0.3, tt::tolerance(1e-14));
    Grid walled = g;
    walled.inside.assign(g.cells(), 0);
    BOOST_TEST(std::isnan(weighted_share(phi, Phi, disc_weights(walled, r2), 0.0)));
}

BOOST_AUTO_TEST_SUITE_END()
