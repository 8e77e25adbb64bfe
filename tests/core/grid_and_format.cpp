// The ground of core: the grid (core/grid.hpp) and exact number formats (core/format.hpp).
#include "core/error.hpp"
#include "core/format.hpp"
#include "core/grid.hpp"

#include <boost/test/unit_test.hpp>

#include <cstdlib>

using namespace granseg;

BOOST_AUTO_TEST_SUITE(core_grid_and_format_tests)

BOOST_AUTO_TEST_CASE(grid_indexing_and_geometry) {
    const Grid g = Grid::plane_xz(4, 3, -1.0, 0.0, 2.0, 3.0);
    BOOST_TEST(g.cells() == 12u);
    BOOST_TEST(g.index(1, 0, 2) == 9u);
    BOOST_TEST(g.stride(2) == 4u);
    BOOST_TEST(g.center(0, 0) == -0.75);
    BOOST_TEST(g.center(2, 2) == 2.5);
    BOOST_TEST(g.is_inside(5));
    const Grid c = Grid::column(50, 1.0);
    BOOST_TEST(c.h[2] == 0.02);
    BOOST_TEST(c.stride(2) == 1u);
    BOOST_CHECK_THROW(Grid::column(0, 1.0), InputError);
    // Faces: 5 x 1 x 3 normal to x, 4 x 1 x 4 normal to z; upper face = lower face + stride.
    BOOST_TEST(g.faces(0) == 15u);
    BOOST_TEST(g.faces(2) == 16u);
    BOOST_TEST(g.face_index(0, 4, 0, 2) == 14u);
    BOOST_TEST(g.face_index(2, 3, 0, 3) == 15u);
    BOOST_TEST(g.face_index(2, 1, 0, 1) + g.face_stride(2) == g.face_index(2, 1, 0, 2));
    BOOST_TEST(g.face_index(0, 1, 0, 1) + g.face_stride(0) == g.face_index(0, 2, 0, 1));
}

BOOST_AUTO_TEST_CASE(format_exact_is_the_shortest_text_that_reads_back_exactly) {
    BOOST_TEST(format_exact(0.1) == "0.1");  // not 0.10000000000000001
    BOOST_TEST(format_exact(25.0) == "25");
    BOOST_TEST(format_exact(0.1 + 0.2) == "0.30000000000000004");  // 0.3 would be another double
    for (double v : {1.0 / 3.0, 2e-3, -7.25e-300, 6.02214076e23}) BOOST_TEST(std::strtod(format_exact(v).c_str(), nullptr) == v);
}

BOOST_AUTO_TEST_SUITE_END()
