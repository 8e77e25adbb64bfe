// The kinematic rolling-drum flow at hand-checked points (the systematic checks are
// verification/verify_kinematic_flow.cpp).
#include "kinematic/kinematic_flow.hpp"
#include "core/error.hpp"

#include <boost/test/unit_test.hpp>

#include <cmath>

using namespace granseg;
using Eigen::Vector3d;
namespace tt = boost::test_tools;

BOOST_AUTO_TEST_SUITE(kinematic_flow_tests)

BOOST_AUTO_TEST_CASE(geometry_of_the_sect_4_2_drum) {
    const RollingDrumFlow f{RollingDrumParameters{}};
    BOOST_TEST(f.radius() == 0.05);
    BOOST_TEST(f.surface_distance() == 0.025, tt::tolerance(1e-15));  // 75 % of the height
    BOOST_TEST(f.half_chord() == std::sqrt(0.05 * 0.05 - 0.025 * 0.025), tt::tolerance(1e-15));
    BOOST_TEST(f.Omega() == 0.2 * M_PI, tt::tolerance(1e-15));
    BOOST_TEST(f.tangent().dot(f.normal()) == 0.0, tt::tolerance(1e-15));
    BOOST_TEST(f.tangent()(2) < 0.0);  // downslope
    BOOST_TEST(f.tangent()(0) < 0.0);  // counter-clockwise: the surface falls to the left
}

BOOST_AUTO_TEST_CASE(invalid_parameters_are_rejected) {
    RollingDrumParameters p;
    p.layer_thickness = 0.05;  // thicker than the half chord
    BOOST_CHECK_THROW(RollingDrumFlow{p}, InputError);
    p = RollingDrumParameters{};
    p.rotation_rate = 0.0;
    BOOST_CHECK_THROW(RollingDrumFlow{p}, InputError);
    p = RollingDrumParameters{};
    p.fill_fraction = 1.0;
    BOOST_CHECK_THROW(RollingDrumFlow{p}, InputError);
}

BOOST_AUTO_TEST_CASE(stream_function_vanishes_on_wall_and_surface) {
    const RollingDrumFlow f{RollingDrumParameters{}};
    const double R = f.radius() * (1 - 1e-12);
    BOOST_TEST(f.stream_function(0.0, -R) == 0.0, tt::tolerance(1e-14));  // Omega R^2 1e-12 off the wall
    const Vector3d on_surface = (f.surface_distance() - 1e-15) * f.normal() + 0.3 * f.half_chord() * f.tangent();
    BOOST_TEST(f.stream_function(on_surface(0), on_surface(2)) == 0.0, tt::tolerance(1e-15));
    BOOST_TEST(f.stream_function(0.0, 0.0) > 0.0);  // flux between the centre and the wall
}

BOOST_AUTO_TEST_CASE(clockwise_rotation_mirrors_the_flow) {
    RollingDrumParameters p;
    const RollingDrumFlow ccw{p};
    p.rotation_rate = -p.rotation_rate;
    const RollingDrumFlow cw{p};
    for (const auto& [x, z] : {std::pair{-0.01, 0.015}, {0.005, 0.025}, {0.02, -0.03}}) {
        const Vector3d a = ccw.velocity(x, z), b = cw.velocity(-x, z);
        BOOST_TEST(a(0) == -b(0), tt::tolerance(1e-12));
        BOOST_TEST(a(2) == b(2), tt::tolerance(1e-12));
    }
}

BOOST_AUTO_TEST_CASE(relative_velocity_vanishes_in_the_core) {
    const RollingDrumFlow f{RollingDrumParameters{}};
    BOOST_TEST(f.relative_velocity(0.0, -0.03).norm() == 0.0);
    BOOST_TEST(f.velocity(0.0, -0.03)(0) == f.Omega() * 0.03, tt::tolerance(1e-15));  // Omega x x
}

BOOST_AUTO_TEST_CASE(cell_accessors) {
    std::array<std::vector<double>, 9> t;
    for (int i = 0; i < 9; ++i) t[i] = {0.0, double(i)};
    BOOST_TEST(cell_tensor(t, 1)(1, 2) == 5.0);
    const std::array<std::vector<double>, 3> v{{{1.0}, {2.0}, {3.0}}};
    BOOST_TEST(cell_vector(v, 0)(2) == 3.0);
}

BOOST_AUTO_TEST_SUITE_END()
