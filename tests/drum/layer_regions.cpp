// The coupled drum's own regions (drum/layer_regions.hpp): a uniform mixture has its share in
// every region; a composition that depends on the radius only through the regions' circles is
// read exactly, cut cells by their area share; a layer thicker than d leaves no core.
#include "drum/layer_regions.hpp"
#include "drum/drum.hpp"
#include "drum/region_weights.hpp"

#include <boost/test/unit_test.hpp>

#include <cmath>
#include <utility>
#include <vector>

using namespace granseg;

BOOST_AUTO_TEST_SUITE(drum_layer_regions_tests)

namespace {
constexpr double kD = 0.025, kR = 0.05, kAxis = 0.005, kLayer = 0.012;

/// Phi = 0.6 and phi = share * 0.6 in every inside cell, 0 outside.
std::pair<std::vector<double>, std::vector<double>> uniform_bed(const Grid& g, double share) {
    std::vector<double> Phi(g.cells(), 0.0), phi(g.cells(), 0.0);
    for (std::size_t c = 0; c < Phi.size(); ++c)
        if (g.is_inside(c)) Phi[c] = 0.6, phi[c] = share * 0.6;
    return {Phi, phi};
}
}  // namespace

// phi = 0.3 Phi everywhere: every region reads 0.3 to round-off (a ratio of two sums of ~1e3 terms).
BOOST_AUTO_TEST_CASE(a_uniform_mixture_reads_its_share_everywhere) {
    const Grid g = DrumSpec{}.grid();
    const auto [Phi, phi] = uniform_bed(g, 0.3);
    const LayerRegions regions(g, kD, kR, kAxis);
    const LayerRegionShares s = regions.shares(phi, Phi, kLayer, 0.3);
    BOOST_TEST(s.r_core == kD - kLayer, boost::test_tools::tolerance(1e-15));
    for (double v : {s.core, s.ring, s.periphery, s.axis}) BOOST_TEST(v == 0.3, boost::test_tools::tolerance(1e-12));
}

// phi_hat = w (the cell's area share of the core's disc) with Phi = 1: the core reads
// sum(w^2)/sum(w), computed here from the same weights; the ring, outside that disc but inside d,
// reads sum((w_d - w) w)/sum(w_d - w).
BOOST_AUTO_TEST_CASE(the_core_counts_cut_cells_by_their_area) {
    const DrumSpec drum;
    const Grid g = drum.grid();
    const std::vector<double> w = disc_weights(g, kD - kLayer), wd = disc_weights(g, kD);
    std::vector<double> Phi(g.cells(), 0.0), phi(g.cells(), 0.0);
    double w2 = 0, w1 = 0, ring_num = 0, ring_den = 0;
    for (std::size_t c = 0; c < Phi.size(); ++c) {
        if (!g.is_inside(c)) continue;
        Phi[c] = 1.0, phi[c] = w[c];
        w2 += w[c] * w[c], w1 += w[c];
        ring_num += (wd[c] - w[c]) * w[c], ring_den += wd[c] - w[c];
    }
    const LayerRegionShares s = LayerRegions(g, kD, kR, kAxis).shares(phi, Phi, kLayer, 0.5);
    BOOST_TEST(s.core == w2 / w1, boost::test_tools::tolerance(1e-12));
    BOOST_TEST(s.ring == ring_num / ring_den, boost::test_tools::tolerance(1e-12));
    BOOST_TEST(s.periphery == 0.0);
}

BOOST_AUTO_TEST_CASE(a_layer_thicker_than_d_leaves_no_core) {
    const Grid g = DrumSpec{}.grid();
    const auto [Phi, phi] = uniform_bed(g, 0.5);
    const LayerRegionShares s = LayerRegions(g, kD, kR, kAxis).shares(phi, Phi, 2 * kD, 0.3);
    BOOST_TEST(std::isnan(s.core));
    BOOST_TEST(s.ring == 0.5, boost::test_tools::tolerance(1e-12));
}

BOOST_AUTO_TEST_SUITE_END()
