// The Sect. 2.3 direction procedure and the segregation velocity at hand-checked points (the
// systematic checks are verification/verify_direction*.cpp).
#include "direction/segregation_direction.hpp"
#include "closures/closures.hpp"
#include "direction/segregation_velocity.hpp"

#include <boost/test/unit_test.hpp>

#include <limits>
#include <ostream>

namespace granseg {
// Lets BOOST_TEST print a status (found by argument-dependent lookup).
std::ostream& operator<<(std::ostream& out, DirectionStatus status) { return out << to_string(status); }
}  // namespace granseg

using namespace granseg;
using Eigen::Matrix3d;
using Eigen::Vector3d;
namespace tt = boost::test_tools;

namespace {
Matrix3d simple_shear(double gamma) {  // u = (gamma z, 0, 0)
    Matrix3d g = Matrix3d::Zero();
    g(0, 2) = gamma;
    return g;
}
}  // namespace

BOOST_AUTO_TEST_SUITE(direction_segregation_direction_tests)

BOOST_AUTO_TEST_CASE(simple_shear_gives_the_shear_normal) {
    const SegregationDirection r = segregation_direction(simple_shear(2.385), Vector3d(-1.3, 0, 0));
    BOOST_TEST(r.status == DirectionStatus::ok);
    BOOST_TEST((r.d_s - Vector3d(0, 0, 1)).norm() == 0.0, tt::tolerance(1e-15));
    BOOST_TEST(r.gamma_dot == 2.385, tt::tolerance(1e-15));
    BOOST_TEST(r.principal_shear == 2.385, tt::tolerance(1e-15));
    BOOST_TEST((r.P() - Vector3d(0, 0, 1) * Vector3d(0, 0, 1).transpose()).norm() == 0.0, tt::tolerance(1e-15));
}

BOOST_AUTO_TEST_CASE(sign_normalisation_makes_the_largest_component_positive) {
    BOOST_TEST((sign_normalised(Vector3d(0.1, -0.9, 0.3)) - Vector3d(-0.1, 0.9, -0.3)).norm() == 0.0);
    BOOST_TEST((sign_normalised(Vector3d(0.5, 0.0, -0.5)) - Vector3d(0.5, 0.0, -0.5)).norm() == 0.0);  // first on a tie
}

BOOST_AUTO_TEST_CASE(status_names) {
    BOOST_TEST(std::string(to_string(DirectionStatus::no_shear)) == "no_shear");
    BOOST_TEST(std::string(to_string(DirectionStatus::repeated_eigenvalue)) == "repeated_eigenvalue");
    BOOST_TEST(std::string(to_string(DirectionStatus::equal_candidates)) == "equal_candidates");
}

BOOST_AUTO_TEST_CASE(thresholds_are_parameters) {
    DirectionOptions o;
    o.shear_threshold = 3.0;  // a shear of 2.385 1/s now counts as no shear
    BOOST_TEST(segregation_direction(simple_shear(2.385), Vector3d(1, 0, 0), o).status == DirectionStatus::no_shear);
    o = DirectionOptions{};
    o.min_speed = 2.0;  // |u| = 1 counts as u = 0: the gradient rule still finds e_z
    const SegregationDirection r = segregation_direction(simple_shear(2.385), Vector3d(1, 0, 0), o);
    BOOST_TEST(r.status == DirectionStatus::zero_velocity);
    BOOST_TEST(r.d_s(2) == 1.0, tt::tolerance(1e-15));
}

BOOST_AUTO_TEST_CASE(u_along_an_eigenvector_is_a_tie_resolved_by_the_gradient) {
    // u along k_max = (1, 0, 1)/sqrt(2) is equally orthogonal to both candidates e_x and e_z.
    const SegregationDirection r = segregation_direction(simple_shear(1.0), Vector3d(1, 0, 1));
    BOOST_TEST(r.status == DirectionStatus::equal_candidates);
    BOOST_TEST(r.d_s(2) == 1.0, tt::tolerance(1e-15));
}

BOOST_AUTO_TEST_CASE(planar_mode_uses_the_xz_block) {
    DirectionOptions o;
    o.planar_xz = true;
    const SegregationDirection r = segregation_direction(simple_shear(0.7), Vector3d(1, 0, 0), o);
    BOOST_TEST(r.eigen.k_max(1) == 0.0);
    BOOST_TEST(r.d_s(2) == 1.0, tt::tolerance(1e-15));
}

BOOST_AUTO_TEST_CASE(non_finite_input_is_rejected) {
    Matrix3d g = simple_shear(1.0);
    g(1, 1) = std::numeric_limits<double>::quiet_NaN();
    BOOST_CHECK_THROW(segregation_direction(g, Vector3d(1, 0, 0)), InputError);
}

BOOST_AUTO_TEST_CASE(eq42_with_eq45_is_eq46) {
    const Material m = Material::glass_substitute();
    const double B_over_c = 2.385e-3, T = 3.7e-4;
    const Vector3d d_s = Vector3d(0.3, 0.0, 0.9).normalized(), g(0, 0, -9.81);
    const Vector3d eq42 = segregation_velocity_from_shear_rate(B_over_c, shear_rate_from_temperature(T, m.eps0, m.eta0), d_s, g);
    const Vector3d eq46 = segregation_velocity(segregation_rate(B_over_c, m.eps0, m.eta0), T, d_s, g);
    BOOST_TEST((eq42 - eq46).norm() / eq46.norm() == 0.0, tt::tolerance(1e-15));
    // eq. (45) is the inverse of steady_shear_temperature (Sect. 2.1).
    BOOST_TEST(steady_shear_temperature(m, shear_rate_from_temperature(T, m.eps0, m.eta0)) == T, tt::tolerance(1e-14));
    // Small particles move along -S^sl: down the projected gravity.
    BOOST_TEST(segregation_velocity(1.0, T, Vector3d(0, 0, 1), g)(2) > 0.0);
}

BOOST_AUTO_TEST_SUITE_END()
