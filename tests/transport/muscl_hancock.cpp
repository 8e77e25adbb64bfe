// The high-resolution transport's face values (transport/muscl_hancock.hpp) and its slope limiters
// (transport/limiter.hpp), against the invariants their headers state: a uniform field gives
// itself, a linear field carried by a uniform velocity the exact value half-way through the step,
// any field and any velocities values within the range of the giving cell and its neighbours.
#include "transport/muscl_hancock.hpp"
#include "transport/limiter.hpp"

#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

using namespace granseg;

namespace {

/// Face velocities of `grid`, U on every face of the active axes (0 on the others).
FaceFields uniform_velocity(const Grid& grid, double U) {
    FaceFields f;
    for (int a = 0; a < 3; ++a) f[a].assign(grid.faces(a), grid.n[a] > 1 ? U : 0.0);
    return f;
}

/// The interior faces of an x-z plane grid (a cell on either side; the walls get no values): their
/// indices along axis a.
std::vector<std::size_t> interior_faces(const Grid& grid, int a) {
    std::vector<std::size_t> faces;
    for (int k = a == 2 ? 1 : 0; k < grid.n[2]; ++k)
        for (int i = a == 0 ? 1 : 0; i < grid.n[0]; ++i) faces.push_back(grid.face_index(a, i, 0, k));
    return faces;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(transport_muscl_hancock_tests)

BOOST_AUTO_TEST_CASE(the_limiters_are_zero_at_an_extremum_and_scale_with_the_field) {
    for (const Limiter l : {Limiter::minmod, Limiter::mc}) {
        BOOST_TEST(limited_slope(1.0, -2.0, l) == 0.0);
        BOOST_TEST(limited_slope(-1.0, 0.5, l) == 0.0);
        BOOST_TEST(limited_slope(0.3, 0.3, l) == 0.3);  // a linear field keeps its slope
        BOOST_TEST(limited_slope(3 * 0.2, 3 * 0.7, l) == 3 * limited_slope(0.2, 0.7, l), boost::test_tools::tolerance(1e-15));
    }
    BOOST_TEST(limited_slope(0.2, 0.7, Limiter::minmod) == 0.2);  // the smaller one-sided slope
}

BOOST_AUTO_TEST_CASE(a_uniform_field_gives_itself_on_every_face) {
    const Grid grid = Grid::plane_xz(6, 5, 0.0, 0.0, 1.2, 1.0);
    MusclHancock muscl(grid, Limiter::mc);
    const std::vector<double> q(grid.cells(), 0.37);
    const FaceFields U = uniform_velocity(grid, 0.8);
    for (const auto form : {MusclHancock::Form::conservative, MusclHancock::Form::advective}) {
        muscl.face_values(q, refs(U), 0.05, form);
        for (int a : {0, 2})
            for (std::size_t f : interior_faces(grid, a)) {
                BOOST_TEST(muscl.from_lower()[a][f] == 0.37, boost::test_tools::tolerance(1e-15));
                BOOST_TEST(muscl.from_upper()[a][f] == 0.37, boost::test_tools::tolerance(1e-15));
            }
    }
}

// In a column with U > 0 the cell below a face gives it q_c + (1 - U dt/h) s/2: for q linear in z
// the value of the field at the face half-way through the step, q(z_face - U dt/2).
BOOST_AUTO_TEST_CASE(a_linear_field_gives_the_exact_value_half_way_through_the_step) {
    const int n = 10;
    const double length = 1.0, h = length / n, U = 0.4, dt = 0.1;
    const Grid grid = Grid::column(n, length);
    MusclHancock muscl(grid, Limiter::mc);
    std::vector<double> q(n);
    for (int k = 0; k < n; ++k) q[k] = 2.0 + 3.0 * grid.center(2, k);
    const FaceFields velocity = uniform_velocity(grid, U);
    muscl.face_values(q, refs(velocity), dt, MusclHancock::Form::conservative);
    for (int k = 1; k + 1 < n; ++k) {  // next to a wall the slope is 0
        const double z_face = (k + 1) * h;
        BOOST_TEST(muscl.from_lower()[2][k + 1] == 2.0 + 3.0 * (z_face - U * dt / 2), boost::test_tools::tolerance(1e-13));
    }
}

BOOST_AUTO_TEST_CASE(face_values_stay_within_the_range_of_the_giving_cell_and_its_neighbours) {
    const Grid grid = Grid::plane_xz(9, 7, 0.0, 0.0, 0.9, 0.7);
    std::mt19937 random(7);
    std::uniform_real_distribution<double> unit(0.0, 1.0), speed(-1.0, 1.0);
    std::vector<double> q(grid.cells());
    for (double& v : q) v = unit(random);
    FaceFields U = uniform_velocity(grid, 0.0);
    for (int a : {0, 2})
        for (double& u : U[a]) u = speed(random);
    MusclHancock muscl(grid, Limiter::mc);
    muscl.face_values(q, refs(U), 0.02, MusclHancock::Form::advective);
    const auto [lo, hi] = std::minmax_element(q.begin(), q.end());
    for (int a : {0, 2})
        for (std::size_t f : interior_faces(grid, a))
            for (const double v : {muscl.from_lower()[a][f], muscl.from_upper()[a][f]}) {
                BOOST_TEST(v >= *lo);
                BOOST_TEST(v <= *hi);
            }
}

BOOST_AUTO_TEST_SUITE_END()
