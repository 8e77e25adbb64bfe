// Solution verification arithmetic (harness/grid_convergence.hpp, harness/time_series.hpp) against
// a published worked example (Celik et al., J. Fluids Eng. 130:078001, 2008, Table 1, first
// column), Roy's rule case by case, values of an exact power law f = f0 + C h^p (the fit must find
// p and f0, and the uncertainty Fs |C| h1^p_u when the fit is exact), the conditions on hand-picked
// series, and series whose batch means and trend residuals are known by construction.
#include "harness/grid_convergence.hpp"
#include "core/error.hpp"
#include "harness/time_series.hpp"

#include <boost/test/unit_test.hpp>

#include <cmath>
#include <vector>

BOOST_AUTO_TEST_SUITE(harness_grid_convergence_tests)

using namespace granseg::verify;

namespace {
double power_law(double f0, double C, double p, double h) { return f0 + C * std::pow(h, p); }
std::vector<double> power_law(double f0, double C, double p, const std::vector<double>& h) {
    std::vector<double> f;
    for (double x : h) f.push_back(power_law(f0, C, p, x));
    return f;
}
const std::vector<double> kExact{0.0, 0.0, 0.0, 0.0};
}  // namespace

// Celik et al. (2008), Table 1, first column: 2-D grids of 18000, 8000 and 4500 cells (h ~ N^-1/2,
// r21 = 1.5, r32 = 4/3), reattachment lengths 6.063, 5.972, 5.863; published p = 1.53,
// f_ext = 6.1685, e_a = 1.5 %, e_ext = 1.7 %, GCI_fine = 2.2 % (Fs = 1.25 at the observed order).
// Three grids: the least-squares fit passes through the three values, so it is the three-grid
// procedure. Tolerances: half a unit of the published last digit (p: 0.005; f_ext: p's rounding
// moves it by 8e-4, so 1e-3; percentages: 0.05 %).
BOOST_AUTO_TEST_CASE(celik_worked_example) {
    const std::vector<double> h{1 / std::sqrt(18000.0), 1 / std::sqrt(8000.0), 1 / std::sqrt(4500.0)}, f{6.063, 5.972, 5.863};
    // The published order taken as the formal one: Roy's rule keeps Fs = 1.25 and p_u = 1.53.
    const GridConvergence g = grid_convergence(h, f, {0, 0, 0}, 1.53);
    BOOST_TEST(convergence_name(g.condition) == "monotone");
    BOOST_TEST(std::fabs(g.p - 1.53) <= 0.005);
    BOOST_TEST(std::fabs(g.f0 - 6.1685) <= 1e-3);
    BOOST_TEST(std::fabs(100 * g.e_a - 1.5) <= 0.05);
    BOOST_TEST(std::fabs(100 * g.e_ext - 1.7) <= 0.05);
    BOOST_TEST(g.fs == 1.25);
    BOOST_TEST(std::fabs(100 * g.uncertainty / f[0] - 2.2) <= 0.05);
    // A second-order scheme (pf = 2): p = 1.53 is not within 10 % of it, so Fs = 3 with
    // p_u = min(max(0.5, 1.53), 2) = p, and U = 3 |e21| / (r21^p - 1).
    const GridConvergence far = grid_convergence(h, f, {0, 0, 0}, 2.0);
    BOOST_TEST(far.fs == 3.0);
    BOOST_TEST(far.p_u == far.p);
    BOOST_TEST(far.sigma < 1e-9);  // three values, the fit at the observed order passes through them
    BOOST_TEST(far.uncertainty == 3 * 0.091 / (std::pow(1.5, far.p) - 1), boost::test_tools::tolerance(1e-9));
}

// Roy (AIAA 2010-126; Oberkampf & Roy 2010, Sect. 8.7): within 10 % of pf: Fs = 1.25 with pf;
// otherwise Fs = 3 with the observed order limited to [0.5, pf].
BOOST_AUTO_TEST_CASE(roy_rule_case_by_case) {
    using P = std::pair<double, double>;
    BOOST_TEST((roy_order_and_safety(1.05, 1.0) == P{1.0, 1.25}));
    BOOST_TEST((roy_order_and_safety(0.95, 1.0) == P{1.0, 1.25}));
    BOOST_TEST((roy_order_and_safety(1.15, 1.0) == P{1.0, 3.0}));
    BOOST_TEST((roy_order_and_safety(0.85, 1.0) == P{0.85, 3.0}));
    BOOST_TEST((roy_order_and_safety(0.3, 1.0) == P{0.5, 3.0}));
    BOOST_TEST((roy_order_and_safety(9.0, 2.0) == P{2.0, 3.0}));
    BOOST_TEST((roy_order_and_safety(2.1, 2.0) == P{2.0, 1.25}));
    BOOST_CHECK_THROW(roy_order_and_safety(1.0, 0.0), granseg::InputError);
}

// Four grids of the study (50, 70, 100, 140 cells per diameter of 0.1 m) on an exact power law
// with p = 0.8 against pf = 1 (outside 10 %: Fs = 3, p_u = 0.8): the fit recovers p and f0, its
// standard deviation vanishes, and U = 3 |C| h1^0.8. Tolerances: the fit's order is found by a
// minimiser whose residual is quadratic in p, so p to about sqrt(eps) relative: 1e-6.
BOOST_AUTO_TEST_CASE(exact_power_law_on_four_grids) {
    const std::vector<double> h{0.1 / 140, 0.1 / 100, 0.1 / 70, 0.1 / 50};
    const std::vector<double> f = power_law(0.9, -5.0, 0.8, h);
    const GridConvergence g = grid_convergence(h, f, {1e-6, 1e-6, 1e-6, 1e-6}, 1.0, Bounds{0.0, 1.0});
    BOOST_TEST(convergence_name(g.condition) == "monotone");
    BOOST_TEST(g.p == 0.8, boost::test_tools::tolerance(1e-6));
    BOOST_TEST(g.f0 == 0.9, boost::test_tools::tolerance(1e-6));
    BOOST_TEST(g.fs == 3.0);
    BOOST_TEST(g.p_u == g.p);
    BOOST_TEST(g.sigma < 1e-8);
    BOOST_TEST(g.uncertainty == 3 * 5.0 * std::pow(h[0], 0.8), boost::test_tools::tolerance(1e-5));
    BOOST_TEST(!g.outside_bounds);
    BOOST_TEST(g.grids == 4);
}

// The sampling errors weigh in: a coarsest value thrown off by 0.05 with a sampling error of 1e3
// does not move the fit of the other three (exact) values.
BOOST_AUTO_TEST_CASE(a_noisy_run_counts_less) {
    const std::vector<double> h{1.0, 1.4, 2.0, 2.8};
    std::vector<double> f = power_law(3.0, 0.5, 1.5, h);
    f[3] += 0.05;
    const GridConvergence g = grid_convergence(h, f, {1e-6, 1e-6, 1e-6, 1e3}, 1.5);
    BOOST_TEST(g.p == 1.5, boost::test_tools::tolerance(1e-6));
    BOOST_TEST(g.f0 == 3.0, boost::test_tools::tolerance(1e-6));
    BOOST_TEST(g.fs == 1.25);
    BOOST_TEST(g.p_u == 1.5);
}

// Values that scatter about one constant within their sampling errors: no order is claimed, the
// uncertainty is their range. The same differences with ten times smaller errors are a trend.
BOOST_AUTO_TEST_CASE(differences_within_the_sampling_errors_refuse_an_order) {
    const std::vector<double> h{1, 1.4, 2, 2.8}, f{1.0, 1.006, 1.015, 1.03};
    const GridConvergence g = grid_convergence(h, f, {0.01, 0.01, 0.01, 0.01}, 1.0);
    BOOST_TEST(convergence_name(g.condition) == "within noise");
    BOOST_TEST(std::isnan(g.p));
    BOOST_TEST(std::isnan(g.f0));
    BOOST_TEST(g.uncertainty == 0.03, boost::test_tools::tolerance(1e-12));
    BOOST_TEST(g.chi2 <= g.chi2_limit);
    const GridConvergence trend = grid_convergence(h, f, {0.001, 0.001, 0.001, 0.001}, 1.0);
    BOOST_TEST(convergence_name(trend.condition) == "monotone");
}

BOOST_AUTO_TEST_CASE(oscillatory_series_gives_half_the_range) {
    const GridConvergence g = grid_convergence({1, 2, 4}, {1.0, 1.1, 0.95}, {0, 0, 0}, 1.0);
    BOOST_TEST(convergence_name(g.condition) == "oscillatory");
    BOOST_TEST(std::isnan(g.f0));
    BOOST_TEST(g.lo == 0.95);
    BOOST_TEST(g.hi == 1.1);
    BOOST_TEST(g.uncertainty == 0.075, boost::test_tools::tolerance(1e-12));
}

// Differences that grow under refinement (0.05 then 0.1): no positive order fits, the range.
BOOST_AUTO_TEST_CASE(divergent_series_gives_the_range) {
    const GridConvergence d = grid_convergence({1, 2, 4}, {1.0, 1.1, 1.15}, {0, 0, 0}, 1.0);
    BOOST_TEST(convergence_name(d.condition) == "divergent");
    BOOST_TEST(d.uncertainty == 0.15, boost::test_tools::tolerance(1e-12));
    BOOST_TEST(std::isnan(d.f0));
}

// Two grids: the formal order assumed, Fs = 3 (Richardson with p = pf, U = 3 |e21|/(r^pf - 1)).
BOOST_AUTO_TEST_CASE(two_grids_with_the_exact_order) {
    const std::vector<double> h{1.0 / 70, 1.0 / 50};
    const GridConvergence g = grid_convergence(h, power_law(0.9, -5, 1, h), {0, 0}, 1.0);
    BOOST_TEST(convergence_name(g.condition) == "two grids");
    BOOST_TEST(g.f0 == 0.9, boost::test_tools::tolerance(1e-12));
    BOOST_TEST(g.uncertainty == 3 * 5 * h[0], boost::test_tools::tolerance(1e-12));
    BOOST_TEST(g.fs == 3.0);
}

// The uncertainty of a coarser member is the same rule at its own h: with two grids and the exact
// order, 3 |f2 - f0| (the coarser run carries the larger error); a range is the same for all.
BOOST_AUTO_TEST_CASE(the_uncertainty_of_each_member_at_its_own_h) {
    const std::vector<double> h{1.0 / 70, 1.0 / 50};
    const std::vector<double> f = power_law(0.9, -5, 1, h);
    const GridConvergence g = grid_convergence(h, f, {0, 0}, 1.0);
    BOOST_TEST(uncertainty_at(g, h, f, 0) == g.uncertainty);
    BOOST_TEST(uncertainty_at(g, h, f, 1) == 3 * 5 * h[1], boost::test_tools::tolerance(1e-12));
    const std::vector<double> wavy{1.0, 1.2, 0.9, 1.1};
    const std::vector<double> h4{1, 1.4, 2, 2.8};
    const GridConvergence o = grid_convergence(h4, wavy, {0.01, 0.01, 0.01, 0.01}, 1.0);
    BOOST_TEST(uncertainty_at(o, h4, wavy, 3) == o.uncertainty);
}

// A share whose fit extrapolates below 0 is flagged; the same fit for an unbounded quantity is not.
BOOST_AUTO_TEST_CASE(extrapolation_outside_the_physical_range_is_flagged) {
    const std::vector<double> h{1, 1.4, 2, 2.8};
    const std::vector<double> f = power_law(-0.015, 0.05, 1.0, h);
    BOOST_TEST(grid_convergence(h, f, kExact, 1.0, Bounds{0.0, 1.0}).outside_bounds);
    BOOST_TEST(!grid_convergence(h, f, kExact, 1.0).outside_bounds);
}

BOOST_AUTO_TEST_CASE(cell_sizes_must_increase) {
    BOOST_CHECK_THROW(grid_convergence({1, 1, 2}, {1, 2, 3}, {0, 0, 0}, 1.0), granseg::InputError);
    BOOST_CHECK_THROW(grid_convergence({2, 1, 4}, {1, 2, 3}, {0, 0, 0}, 1.0), granseg::InputError);
    BOOST_CHECK_THROW(grid_convergence({1, 2}, {1, 2}, {0}, 1.0), granseg::InputError);
    BOOST_CHECK_THROW(grid_convergence({1, 2}, {1, 2}, {0, 0}, 0.0), granseg::InputError);
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
