// The flux-corrected bulk transport (segregation/bulk_transport_fct.hpp) on hand-made states: a
// step carried around a periodic column.
#include "segregation/bulk_transport_fct.hpp"
#include "core/error.hpp"
#include "segregation/bulk_transport.hpp"
#include "segregation/invariants.hpp"
#include "segregation/scheme.hpp"

#include <boost/test/unit_test.hpp>

#include <cmath>

using namespace granseg;
namespace tt = boost::test_tools;

BOOST_AUTO_TEST_SUITE(segregation_bulk_transport_fct_tests)

namespace {
/// A periodic column of n cells carrying a step profile at uniform speed: M = Phi v on every face.
struct PeriodicColumn {
    Grid grid = Grid::column(40, 1.0);
    std::vector<double> Phi = std::vector<double>(40, 0.6);
    FaceFields M;
    std::vector<double> phi;
    PeriodicColumn() {
        grid.periodic[2] = true;
        M[2].assign(grid.faces(2), 0.6 * 0.7);
        for (int k = 0; k < 40; ++k) phi.push_back(k >= 10 && k < 20 ? 0.6 : 0.0);
    }
};
double l1_distance(const std::vector<double>& a, const std::vector<double>& b) {
    double d = 0;
    for (std::size_t k = 0; k < a.size(); ++k) d += std::fabs(a[k] - b[k]);
    return d;
}
}  // namespace

BOOST_AUTO_TEST_CASE(fct_conserves_keeps_bounds_and_beats_donor_cell) {
    PeriodicColumn fct, donor;
    const std::vector<double> start = fct.phi;
    FctBulkTransport transport(fct.grid);
    const double dt = bulk_time_step(fct.grid, fct.Phi, fct.M, 0.8), amount = total_amount(fct.grid, fct.phi);
    for (int n = 0; n < 100; ++n) {
        transport.step(fct.Phi, fct.Phi, refs(fct.M), {}, dt, fct.phi);
        transport_bulk(donor.grid, donor.Phi, donor.M, {}, dt, donor.phi);
    }
    BOOST_TEST(total_amount(fct.grid, fct.phi) == amount, tt::tolerance(1e-14));  // across the periodic face too
    for (double v : fct.phi) {
        BOOST_TEST(v >= -1e-15);
        BOOST_TEST(v <= 0.6 + 1e-15);
    }
    // 100 steps at CFL 0.8 carry the step exactly twice around the column: back to the start.
    BOOST_TEST(l1_distance(fct.phi, start) < l1_distance(donor.phi, start) / 2);
}

BOOST_AUTO_TEST_CASE(fct_leaves_a_uniform_mixture_uniform) {
    PeriodicColumn c;
    std::fill(c.phi.begin(), c.phi.end(), 0.3);
    FctBulkTransport transport(c.grid);
    transport.step(c.Phi, c.Phi, refs(c.M), {}, bulk_time_step(c.grid, c.Phi, c.M, 1.0), c.phi);
    for (double v : c.phi) BOOST_TEST(v == 0.3, tt::tolerance(1e-15));
    BOOST_CHECK_THROW(parse_bulk_scheme("upwind"), InputError);
}

BOOST_AUTO_TEST_SUITE_END()
