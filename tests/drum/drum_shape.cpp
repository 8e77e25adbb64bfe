// Drum cross-sections (drum/drum_shape.hpp) against closed forms, and the drum's grid and
// surface for them (drum/bed.hpp drum_grid, drum/drum.hpp). Tolerances: a few roundings of
// numbers of size R (1e-14 relative); the bisection of surface_offset stops at 4e-16 R.
#include "drum/drum_shape.hpp"
#include "core/error.hpp"
#include "drum/bed.hpp"
#include "drum/drum.hpp"

#include <boost/test/unit_test.hpp>

#include <cmath>

using namespace granseg;
namespace tt = boost::test_tools;

BOOST_AUTO_TEST_SUITE(drum_shape_tests)

BOOST_AUTO_TEST_CASE(regular_polygons_against_closed_forms) {
    const double R = 0.05;
    const DrumShape square = DrumShape::polygon(4, R, 0.0), triangle = DrumShape::polygon(3, R, 0.0);
    BOOST_TEST(square.area() == 2 * R * R, tt::tolerance(1e-14));
    BOOST_TEST(triangle.area() == 0.75 * std::sqrt(3.0) * R * R, tt::tolerance(1e-14));
    BOOST_TEST(square.inradius() == R / std::sqrt(2.0), tt::tolerance(1e-14));
    BOOST_TEST(triangle.lowest() == -R / 2, tt::tolerance(1e-14));  // a side at the bottom
    BOOST_TEST(triangle.highest() == R, tt::tolerance(1e-14));      // the opposite corner on top
    BOOST_TEST(triangle.half_width() == R * std::sqrt(3.0) / 2, tt::tolerance(1e-14));
    // The gauge: R on the wall, linear along a ray.
    BOOST_TEST(square.gauge(square.inradius(), 0.0) == R, tt::tolerance(1e-14));
    BOOST_TEST(square.gauge(0.0, -0.5 * square.inradius()) == R / 2, tt::tolerance(1e-14));
    BOOST_TEST(DrumShape::circle(R).gauge(0.03, 0.04) == 0.05);
    BOOST_TEST(square.inside(0.0, 0.0));
    BOOST_TEST(!square.inside(0.036, 0.0));
    BOOST_TEST(triangle.inside(0.0, 0.045));
    BOOST_TEST(!triangle.inside(0.01, 0.045));
    BOOST_CHECK_THROW(DrumShape::polygon(2, R, 0.0), InputError);
}

BOOST_AUTO_TEST_CASE(chords_areas_below_and_surface_offsets) {
    const double R = 0.05, a = R / std::sqrt(2.0);
    const DrumShape square = DrumShape::polygon(4, R, 0.0), circle = DrumShape::circle(R);
    // Horizontal chords of the square: its side; diagonal ones through the axis: 2 R.
    BOOST_TEST(square.chord(0.01, 0.0) == 2 * a, tt::tolerance(1e-14));
    BOOST_TEST(square.chord(0.0, M_PI / 4) == 2 * R, tt::tolerance(1e-14));
    BOOST_TEST(square.chord(0.9 * R, 3 * M_PI / 4) == 0.2 * R, tt::tolerance(1e-12));  // across a corner: 2 (R - d)
    BOOST_TEST(circle.chord(0.03, 1.0) == 0.08, tt::tolerance(1e-14));
    // Areas below a horizontal line, and the line holding a given area.
    BOOST_TEST(square.area_below(0.0, 0.0) == a * a * 2, tt::tolerance(1e-14));
    BOOST_TEST(circle.area_below(0.0, 0.3) == M_PI * R * R / 2, tt::tolerance(1e-14));
    BOOST_TEST(square.area_below(a / 2, 0.0) == 2 * a * 1.5 * a, tt::tolerance(1e-14));
    BOOST_TEST(square.surface_offset(3 * a * a, 0.0) == a / 2, tt::tolerance(1e-13));
    BOOST_TEST(std::fabs(square.surface_offset(square.area() / 2, 0.7)) <= 1e-15);
    BOOST_CHECK_THROW(square.surface_offset(0.0, 0.0), InputError);
}

BOOST_AUTO_TEST_CASE(drum_grids_of_shapes) {
    // The circle's grid is the one of Sect. 4.2 (n x n over [-R, R]^2, inside by the centre).
    const Grid c = drum_grid(20, 0.05);
    BOOST_TEST(c.n[0] == 20);
    BOOST_TEST(c.origin[0] == -0.05);
    BOOST_TEST(c.is_inside(c.index(10, 0, 10)));
    BOOST_TEST(!c.is_inside(c.index(0, 0, 0)));
    // A triangle: its extent in whole cells, symmetric about x = 0, inside by the centre.
    const DrumShape triangle = DrumShape::polygon(3, 0.05, 0.0);
    const Grid g = drum_grid(triangle, 40);
    BOOST_TEST(g.n[0] == 35);  // sqrt(3) R / (2R/40) = 34.6
    BOOST_TEST(g.n[2] == 30);  // 1.5 R / (2R/40)
    BOOST_TEST(g.origin[0] == -0.5 * g.n[0] * g.h[0], tt::tolerance(1e-14));
    for (int k = 0; k < g.n[2]; ++k)
        for (int i = 0; i < g.n[0]; ++i) {
            BOOST_TEST(g.is_inside(g.index(i, 0, k)) == triangle.inside(g.center(0, i), g.center(2, k)));
            BOOST_TEST(g.is_inside(g.index(i, 0, k)) == g.is_inside(g.index(g.n[0] - 1 - i, 0, k)));  // mirror
        }
}

BOOST_AUTO_TEST_CASE(drum_spec_surface_and_closest_distance) {
    DrumSpec d;  // the Sect. 4.2 circle: the surface as before, fill - R
    BOOST_TEST(d.surface_height() == d.fill_height - d.radius());
    BOOST_TEST(closest_surface_distance(d) == d.surface_height());
    d.shape = DrumShapeKind::polygon, d.sides = 4;
    d.fill_height = 0.05 / std::sqrt(2.0);  // half full
    BOOST_TEST(std::fabs(d.surface_height()) <= 1e-17);
    BOOST_TEST(std::fabs(closest_surface_distance(d)) <= 1e-15);  // centrally symmetric: through the axis at every angle
    d.fill_height = 0.75 * std::sqrt(2.0) * 0.05;  // three quarters of the side: the surface is closest turned by 45 degrees
    const double a = 0.05 / std::sqrt(2.0), area = 2 * a * 1.5 * a;
    BOOST_TEST(closest_surface_distance(d) == DrumShape::polygon(4, 0.05, 0.0).surface_offset(area, M_PI / 4),
               tt::tolerance(1e-12));
    BOOST_TEST(closest_surface_distance(d) < d.surface_height());
}

BOOST_AUTO_TEST_SUITE_END()
