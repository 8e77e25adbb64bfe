// The kinematic tumbler's pieces on small hand-made states (the full run is checked by
// verification/verify_tumbler_kinematic.cpp).
#include "kinematic/kinematic_tumbler.hpp"
#include "drum/pattern_metrics.hpp"
#include "segregation/invariants.hpp"
#include "segregation/scheme.hpp"

#include <boost/test/unit_test.hpp>

#include <cmath>

using namespace granseg;
namespace tt = boost::test_tools;

BOOST_AUTO_TEST_SUITE(kinematic_tumbler_tests)

namespace {
Grid square(int n) {
    Grid g = Grid::plane_xz(n, n, -1.0, -1.0, 2.0, 2.0);
    g.inside.assign(g.cells(), 1);
    return g;
}
}  // namespace

BOOST_AUTO_TEST_CASE(segregation_index_is_0_mixed_and_1_split) {
    const Grid g = square(4);
    const std::vector<double> Phi(g.cells(), 0.5), mixed(g.cells(), 0.2), initial(g.cells(), 0.4);
    const PatternRegions regions{0.5, 1.0, 1.2};
    BOOST_TEST(pattern_metrics(g, mixed, Phi, regions, initial).index <= 1e-15);  // mean of 16 equal values: round-off
    std::vector<double> split(g.cells(), 0.0);
    for (std::size_t c = 0; c < g.cells(); c += 2) split[c] = 0.5;  // half pure small, half pure large
    const PatternMetrics m = pattern_metrics(g, split, Phi, regions, initial);
    BOOST_TEST(m.index == 1.0, tt::tolerance(1e-15));
    BOOST_TEST(m.mean == 0.5, tt::tolerance(1e-15));
}

BOOST_AUTO_TEST_CASE(regions_by_radius) {
    const Grid g = square(4);  // centres at radius sqrt(2)/4 (4 cells), sqrt(10)/4 (8), sqrt(18)/4 (4)
    const std::vector<double> Phi(g.cells(), 0.5), initial(g.cells(), 1.0);
    std::vector<double> phi(g.cells());
    for (int k = 0; k < 4; ++k)
        for (int i = 0; i < 4; ++i) phi[g.index(i, 0, k)] = std::hypot(g.center(0, i), g.center(2, k)) < 0.5 ? 0.5 : 0.1;
    const PatternMetrics m = pattern_metrics(g, phi, Phi, PatternRegions{0.5, 1.0, 1.0}, initial);
    BOOST_TEST(m.core == 1.0);
    BOOST_TEST(m.ring == 0.2, tt::tolerance(1e-15));
    BOOST_TEST(m.periphery == 0.2, tt::tolerance(1e-15));
    BOOST_TEST(m.core_deviation == 0.0);
    const PatternMetrics empty = pattern_metrics(g, phi, Phi, PatternRegions{0.1, 0.2, 5.0}, initial);
    BOOST_TEST(std::isnan(empty.core));
    const ShellProfile p = shell_profile(g, phi, Phi, 1.5, 3);
    BOOST_TEST(p.cells[0] == 4);
    BOOST_TEST(p.phi_hat[0] == 1.0);
}

BOOST_AUTO_TEST_CASE(mixed_bed_stays_mixed_without_segregation) {
    KinematicTumblerSetup setup;
    setup.cells_per_diameter = 30;
    setup.S = 0.0;  // bulk transport alone keeps phi_hat a convex combination of 0.5
    KinematicTumbler tumbler(setup);
    for (int n = 0; n < 50; ++n) tumbler.step(tumbler.time_step());
    const std::vector<double> phi_hat = composition_field(tumbler.grid(), tumbler.phi(), tumbler.Phi());
    double worst = 0;
    for (std::size_t c = 0; c < phi_hat.size(); ++c)
        if (tumbler.grid().is_inside(c)) worst = std::max(worst, std::fabs(phi_hat[c] - 0.5));
    BOOST_TEST(worst <= 1e-14);
    BOOST_CHECK_THROW(tumbler.step(2 * tumbler.time_step()), InputError);
}

BOOST_AUTO_TEST_CASE(bad_setups_are_rejected) {
    KinematicTumblerSetup setup;
    setup.cells_per_diameter = 30;
    setup.Phi = 1.0;
    BOOST_CHECK_THROW(KinematicTumbler{setup}, InputError);
    setup.Phi = 0.6;
    setup.phi_hat0 = [](double x, double) { return x > 0 ? 1.5 : 0.5; };
    BOOST_CHECK_THROW(KinematicTumbler{setup}, InputError);
}

BOOST_AUTO_TEST_SUITE_END()
