// Material points (coupled/material_points.hpp): a rigid rotation about the axis keeps every point
// on its circle (the midpoint rule's radial error per step is O((omega dt)^4) r, here below 2e-6 of
// r over a turn), so the marked share within any radius stays what it was; a field at rest moves
// nothing.
#include "coupled/material_points.hpp"
#include "drum/drum.hpp"

#include <boost/test/unit_test.hpp>

#include <cmath>
#include <vector>

using namespace granseg;

BOOST_AUTO_TEST_SUITE(coupled_material_points_tests)

namespace {
constexpr double kCore = 0.013;
double in_core(double x, double z) { return std::hypot(x, z) < kCore ? 1.0 : 0.0; }
/// A 60-cell drum: four points per cell 0.83 mm apart, several between kCore and 1.1 kCore.
Grid drum_grid() {
    DrumSpec spec;
    spec.cells_per_diameter = 60;
    return spec.grid();
}
}  // namespace

BOOST_AUTO_TEST_CASE(a_rigid_rotation_keeps_the_core_marked) {
    const Grid g = drum_grid();
    const std::vector<double> Phi(g.cells(), 0.6);
    MaterialPoints points(g, Phi, 0.3, in_core);
    const double before = points.marked_share_within(kCore);
    BOOST_TEST(before == 1.0);
    // u = omega x (-z, x): one turn at omega = 1 rad/s in 500 steps; bilinear interpolation of a
    // linear field is exact away from the walls.
    std::vector<double> ux(g.cells(), 0.0), uz(g.cells(), 0.0);
    for (int k = 0; k < g.n[2]; ++k)
        for (int i = 0; i < g.n[0]; ++i) ux[g.index(i, 0, k)] = -g.center(2, k), uz[g.index(i, 0, k)] = g.center(0, i);
    const int steps = 500;
    for (int n = 0; n < steps; ++n) points.advance(ux, uz, 2 * M_PI / steps);
    BOOST_TEST(points.marked_share_within(kCore) == 1.0);
    BOOST_TEST(points.marked_share_within(0.99 * kCore) == 1.0);
    BOOST_TEST(points.marked_share_within(1.1 * kCore) < 1.0);  // unmarked points between 13 and 14.3 mm
}

BOOST_AUTO_TEST_CASE(a_bed_at_rest_moves_nothing) {
    const Grid g = drum_grid();
    const std::vector<double> Phi(g.cells(), 0.6), zero(g.cells(), 0.0);
    MaterialPoints points(g, Phi, 0.3, in_core);
    const double share = points.marked_share_within(0.02);
    for (int n = 0; n < 10; ++n) points.advance(zero, zero, 0.01);
    BOOST_TEST(points.marked_share_within(0.02) == share);
    BOOST_TEST(points.size() > 0u);
}

BOOST_AUTO_TEST_SUITE_END()
