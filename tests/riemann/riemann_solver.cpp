// The exact Riemann solver of system (52), its sampling and the Table 1 classifier at
// hand-checked states (the full verification is verification/verify_table1*.cpp).
#include "riemann/riemann_solver.hpp"
#include "core/error.hpp"
#include "riemann/flux_curves.hpp"
#include "riemann/riemann_sample.hpp"
#include "riemann/table1_classifier.hpp"

#include <boost/test/unit_test.hpp>

#include <cmath>

using namespace granseg;
namespace tt = boost::test_tools;

BOOST_AUTO_TEST_SUITE(riemann_solver_tests)

BOOST_AUTO_TEST_CASE(flux_inverse_branches) {
    // f(phi; 0.8, 1) = phi (phi - 0.8)/0.8 = -0.15 at phi = 0.2 and 0.6.
    BOOST_TEST(phi_left_of_gamma(-0.15, 0.8, 1.0) == 0.2, tt::tolerance(1e-14));
    BOOST_TEST(phi_right_of_gamma(-0.15, 0.8, 1.0) == 0.6, tt::tolerance(1e-14));
    BOOST_TEST(phi_left_of_gamma(flux_extremum(0.8, 1.0), 0.8, 1.0) == gamma_phi(0.8));
    // Concave flux (a < 0): f = -f(.; a > 0), same roots.
    BOOST_TEST(phi_left_of_gamma(0.15, 0.8, -1.0) == 0.2, tt::tolerance(1e-14));
    // Near phi = 0 without cancellation: f ~ -a phi.
    BOOST_TEST(phi_left_of_gamma(-1e-20, 0.5, 2.0) == 5e-21, tt::tolerance(1e-12));
    BOOST_CHECK_THROW(phi_left_of_gamma(-0.3, 0.8, 1.0), InputError);  // below f_min = -0.2
}

BOOST_AUTO_TEST_CASE(region_c_example_of_fig5) {
    // Rarefaction 0.1 -> 0.25 on f_L, standing wave to the right branch of f_R at f_L^min = -0.125,
    // shock down to 0.3 with speed (f_R(0.3) - f_L^min)/(0.3 - phi_plus).
    const FluxSide L{0.1, 0.5, 1.0}, R{0.3, 0.8, 1.0};
    const RiemannSolution s = solve_riemann(L, R);
    const double phi_plus = 0.4 * (1.0 + std::sqrt(0.375));
    BOOST_TEST(s.flux == -0.125, tt::tolerance(1e-15));
    BOOST_TEST(s.phi_minus == 0.25);
    BOOST_TEST(s.phi_plus == phi_plus, tt::tolerance(1e-14));
    BOOST_REQUIRE(s.waves.size() == 3u);
    BOOST_TEST((s.waves[0].kind == WaveKind::rarefaction && s.waves[1].kind == WaveKind::standing &&
                s.waves[2].kind == WaveKind::shock));
    BOOST_TEST(s.waves[0].speed_left == -0.6, tt::tolerance(1e-15));
    BOOST_TEST(s.waves[2].speed_left == (0.3 * (0.3 - 0.8) / 0.8 + 0.125) / (0.3 - phi_plus), tt::tolerance(1e-13));
    BOOST_TEST(sample_phi(s, -0.3) == 0.25 * (1.0 - 0.3), tt::tolerance(1e-15));  // inside the fan
    BOOST_TEST(sample_phi(s, 0.0) == s.phi_plus);
    BOOST_TEST(sample_Phi(s, -0.1) == 0.5);
    BOOST_TEST(classify_table1(L, R).region == 'C');
}

BOOST_AUTO_TEST_CASE(classifier_picks_every_region_of_fig4) {
    // Q_L = (0.15, 0.5) left of Gamma (Fig. 4a) and (0.4, 0.5) right of it (Fig. 4b).
    const double left[6][2] = {{0.1, 0.4}, {0.2, 0.48}, {0.4, 0.8}, {0.5, 0.6}, {0.3, 0.45}, {0.25, 0.3}};
    const double right[4][2] = {{0.05, 0.3}, {0.35, 0.7}, {0.35, 0.4}, {0.2, 0.25}};
    for (int k = 0; k < 6; ++k) BOOST_TEST(classify_table1({0.15, 0.5, 1.0}, {left[k][0], left[k][1], 1.0}).number == k + 1);
    for (int k = 0; k < 4; ++k) BOOST_TEST(classify_table1({0.4, 0.5, 1.0}, {right[k][0], right[k][1], 1.0}).number == k + 7);
}

BOOST_AUTO_TEST_CASE(negative_coefficients_are_the_mirror_image) {
    const FluxSide L{0.1, 0.5, -1.0}, R{0.3, 0.8, -2.0};
    const RiemannSolution s = solve_riemann(L, R), m = solve_riemann({R.phi, R.Phi, 2.0}, {L.phi, L.Phi, 1.0});
    BOOST_TEST(s.flux == -m.flux);
    BOOST_TEST(s.phi_minus == m.phi_plus);
    BOOST_REQUIRE(s.waves.size() == m.waves.size());
    for (std::size_t k = 0; k < s.waves.size(); ++k) {
        const Wave &w = s.waves[k], &v = m.waves[m.waves.size() - 1 - k];
        BOOST_TEST((w.kind == v.kind));
        BOOST_TEST(w.speed_left == -v.speed_right);
    }
    const Table1Case c = classify_table1(L, R);
    BOOST_TEST((c.mirrored && c.number == classify_table1({R.phi, R.Phi, 2.0}, {L.phi, L.Phi, 1.0}).number));
    BOOST_TEST(s.flux == modified_godunov_flux({L, R}), tt::tolerance(1e-15));
}

BOOST_AUTO_TEST_CASE(opposite_signs_empty_or_fill_with_zero_flux) {
    // a_L > 0 > a_R: both sides move away from z = 0 and empty next to it.
    const RiemannSolution away = solve_riemann({0.2, 0.5, 1.0}, {0.3, 0.6, -1.0});
    BOOST_TEST(away.flux == 0.0);
    BOOST_TEST((away.phi_minus == 0.0 && away.phi_plus == 0.0));
    // a_L < 0 < a_R: both move towards it and fill up.
    const RiemannSolution towards = solve_riemann({0.2, 0.5, -1.0}, {0.3, 0.6, 1.0});
    BOOST_TEST((towards.phi_minus == 0.5 && towards.phi_plus == 0.6));
    BOOST_TEST(towards.waves.front().speed_left == -1.0 * 0.2 / 0.5, tt::tolerance(1e-15));  // a_L phi_L/Phi_L
    // a = 0 on one side: that side does not move.
    const RiemannSolution still = solve_riemann({0.2, 0.5, 0.0}, {0.3, 0.6, 1.0});
    BOOST_TEST(still.phi_minus == 0.2);
    BOOST_TEST(classify_table1({0.2, 0.5, 0.0}, {0.3, 0.6, 1.0}).number == 0);
}

BOOST_AUTO_TEST_CASE(same_state_has_no_wave) {
    const FluxSide q{0.3, 0.6, 1.2};
    const RiemannSolution s = solve_riemann(q, q);
    BOOST_TEST(s.waves.empty());
    BOOST_TEST(s.flux == segregation_flux(0.3, 0.6, 1.2));
}

BOOST_AUTO_TEST_CASE(states_outside_the_physical_set_are_rejected) {
    BOOST_CHECK_THROW(solve_riemann({0.6, 0.5, 1.0}, {0.3, 0.8, 1.0}), InputError);
    BOOST_CHECK_THROW(solve_riemann({0.1, 0.5, 1.0}, {0.0, 0.0, 1.0}), InputError);
}

BOOST_AUTO_TEST_SUITE_END()
