// Solution verification arithmetic (harness/grid_convergence.hpp, harness/time_series.hpp) against
// worked examples whose answers are known without the procedure: values of an exact power law
// f = f0 + C h^p (the observed order must be p, the extrapolated value f0, and the GCI Fs |C| h1^p,
// since |e21|/(r21^p - 1) = |C| h1^p), the three conditions on hand-picked triples, and series whose
// batch means and trend residuals are known by construction.
#include "core/error.hpp"
#include "harness/grid_convergence.hpp"
#include "harness/time_series.hpp"

#include <boost/test/unit_test.hpp>

#include <cmath>
#include <vector>

using namespace granseg::verify;

BOOST_AUTO_TEST_SUITE(grid_convergence)

namespace {
double power_law(double f0, double C, double p, double h) { return f0 + C * std::pow(h, p); }
}  // namespace

BOOST_AUTO_TEST_CASE(exact_power_law_with_constant_ratio) {
    const std::array<double, 3> h{0.1, 0.2, 0.4};
    const std::array<double, 3> f{power_law(3, 0.5, 1.5, h[0]), power_law(3, 0.5, 1.5, h[1]), power_law(3, 0.5, 1.5, h[2])};
    const GridConvergence g = three_grid_convergence(h, f);
    BOOST_TEST(convergence_name(g.condition) == "monotone");
    BOOST_TEST(g.R == std::pow(2.0, -1.5), boost::test_tools::tolerance(1e-12));
    BOOST_TEST(g.p == 1.5, boost::test_tools::tolerance(1e-10));
    BOOST_TEST(g.f_ext == 3.0, boost::test_tools::tolerance(1e-12));
    BOOST_TEST(g.uncertainty == 1.25 * 0.5 * std::pow(0.1, 1.5), boost::test_tools::tolerance(1e-10));
    BOOST_TEST(g.asymptotic == 1.0, boost::test_tools::tolerance(1e-10));
    BOOST_TEST(g.lo == f[0]);
    BOOST_TEST(g.hi == f[2]);
}

// An observed order far above the formal one (p = 6 against 1): f_ext keeps the observed order,
// the GCI takes the formal order and Fs = 3 (|e21|/(2 - 1) = e21); within [pf/2, 2 pf] (p = 1.5
// against 1) the rule changes nothing; far below (p = 0.3 against 1) the GCI takes p = 1/2.
BOOST_AUTO_TEST_CASE(observed_order_far_from_the_formal_one) {
    const std::array<double, 3> h{0.1, 0.2, 0.4};
    std::array<double, 3> f{};
    for (int i = 0; i < 3; ++i) f[i] = power_law(3, 0.5, 6.0, h[i]);
    const GridConvergence g = three_grid_convergence(h, f, 1.25, 1.0);
    BOOST_TEST(g.p == 6.0, boost::test_tools::tolerance(1e-9));
    BOOST_TEST(g.p_gci == 1.0);
    BOOST_TEST(g.fs == 3.0);
    BOOST_TEST(g.f_ext == 3.0, boost::test_tools::tolerance(1e-12));
    BOOST_TEST(g.uncertainty == 3.0 * (f[1] - f[0]), boost::test_tools::tolerance(1e-10));
    for (int i = 0; i < 3; ++i) f[i] = power_law(3, 0.5, 1.5, h[i]);
    const GridConvergence near = three_grid_convergence(h, f, 1.25, 1.0);
    BOOST_TEST(near.p_gci == near.p);
    BOOST_TEST(near.fs == 1.25);
    for (int i = 0; i < 3; ++i) f[i] = power_law(3, 0.5, 0.3, h[i]);
    const GridConvergence low = three_grid_convergence(h, f, 1.25, 1.0);
    BOOST_TEST(low.p_gci == 0.5);
    BOOST_TEST(low.uncertainty == 3.0 * (f[1] - f[0]) / (std::sqrt(2.0) - 1.0), boost::test_tools::tolerance(1e-10));
}

// The study's grids, 100, 71 and 50 cells per diameter: the ratios differ (1.408, 1.420), so the
// order comes from the fixed-point iteration; a value that rises under refinement (C < 0).
BOOST_AUTO_TEST_CASE(exact_power_law_with_the_study_grids) {
    const std::array<double, 3> h{0.1 / 100, 0.1 / 71, 0.1 / 50};
    std::array<double, 3> f{};
    for (int i = 0; i < 3; ++i) f[i] = power_law(23.1, -200, 0.8, h[i]);
    const GridConvergence g = three_grid_convergence(h, f);
    BOOST_TEST(convergence_name(g.condition) == "monotone");
    BOOST_TEST(g.p == 0.8, boost::test_tools::tolerance(1e-9));
    BOOST_TEST(g.f_ext == 23.1, boost::test_tools::tolerance(1e-12));
    BOOST_TEST(g.uncertainty == 1.25 * 200 * std::pow(h[0], 0.8), boost::test_tools::tolerance(1e-9));
    BOOST_TEST(g.asymptotic == 1.0, boost::test_tools::tolerance(1e-9));
}

BOOST_AUTO_TEST_CASE(oscillatory_triple_gives_half_the_range) {
    const GridConvergence g = three_grid_convergence({1, 2, 4}, {1.0, 1.1, 0.95});
    BOOST_TEST(convergence_name(g.condition) == "oscillatory");
    BOOST_TEST(g.R == 0.1 / -0.15, boost::test_tools::tolerance(1e-12));
    BOOST_TEST(std::isnan(g.f_ext));
    BOOST_TEST(std::isnan(g.p));
    BOOST_TEST(g.lo == 0.95);
    BOOST_TEST(g.hi == 1.1);
    BOOST_TEST(g.uncertainty == 0.075, boost::test_tools::tolerance(1e-12));
}

BOOST_AUTO_TEST_CASE(divergent_and_undetermined_triples_give_the_range) {
    const GridConvergence d = three_grid_convergence({1, 2, 4}, {1.0, 1.1, 1.15});
    BOOST_TEST(convergence_name(d.condition) == "divergent");
    BOOST_TEST(d.R == 2.0, boost::test_tools::tolerance(1e-12));
    BOOST_TEST(d.uncertainty == 0.15, boost::test_tools::tolerance(1e-12));
    BOOST_TEST(std::isnan(d.f_ext));
    const GridConvergence u = three_grid_convergence({1, 2, 4}, {1.0, 1.0, 2.0});
    BOOST_TEST(convergence_name(u.condition) == "undetermined");
    BOOST_TEST(u.uncertainty == 1.0);
}

BOOST_AUTO_TEST_CASE(two_grids_with_the_exact_order) {
    const std::array<double, 2> h{1.0 / 71, 1.0 / 50};
    const GridConvergence g = two_grid_convergence(h, {power_law(0.9, -5, 1, h[0]), power_law(0.9, -5, 1, h[1])}, 1.0);
    BOOST_TEST(convergence_name(g.condition) == "two grids");
    BOOST_TEST(g.f_ext == 0.9, boost::test_tools::tolerance(1e-12));
    BOOST_TEST(g.uncertainty == 3 * 5 * h[0], boost::test_tools::tolerance(1e-12));
    BOOST_TEST(g.fs == 3.0);
}

BOOST_AUTO_TEST_CASE(cell_sizes_must_increase) {
    BOOST_CHECK_THROW(three_grid_convergence({1, 1, 2}, {1, 2, 3}), granseg::InputError);
    BOOST_CHECK_THROW(three_grid_convergence({2, 1, 4}, {1, 2, 3}), granseg::InputError);
    BOOST_CHECK_THROW(two_grid_convergence({1, 2}, {1, 2}, 0.0), granseg::InputError);
}

// 31 samples: the first is left out, then 10 batches of 3 whose means are 0, 1, ..., 9.
BOOST_AUTO_TEST_CASE(batch_means_of_known_batches) {
    std::vector<double> v{1000.0};
    for (int b = 0; b < 10; ++b)
        for (double d : {-1.0, 0.0, 1.0}) v.push_back(b + d);
    const double sd = std::sqrt(82.5 / 9);  // sample standard deviation of 0..9
    BOOST_TEST(batch_mean_error(v, 10) == sd / std::sqrt(10.0), boost::test_tools::tolerance(1e-12));
    BOOST_TEST(std::isnan(batch_mean_error(std::vector<double>(15, 1.0), 10)));
}

// Residuals (a, -a, -a, a) about 2 + 3 t are orthogonal to 1 and t: the fit finds the line, and
// the spread is sqrt(4 a^2 / 2).
BOOST_AUTO_TEST_CASE(detrended_spread_of_a_line_with_known_residuals) {
    const double a = 0.1;
    const std::vector<double> t{0, 1, 2, 3}, v{2 + a, 5 - a, 8 - a, 11 + a};
    BOOST_TEST(detrended_spread(t, v) == a * std::sqrt(2.0), boost::test_tools::tolerance(1e-12));
}

BOOST_AUTO_TEST_SUITE_END()
