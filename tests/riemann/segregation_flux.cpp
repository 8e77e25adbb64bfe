// Interface fluxes of Sect. 3 at hand-checked states (the full Table 1 verification is
// verification/verify_table1.cpp).
#include "riemann/segregation_flux.hpp"
#include "segregation/scheme.hpp"

#include <boost/test/unit_test.hpp>

using namespace granseg;
namespace tt = boost::test_tools;

BOOST_AUTO_TEST_SUITE(riemann_segregation_flux_tests)

BOOST_AUTO_TEST_CASE(flux_vanishes_at_both_ends_and_is_extreme_on_Gamma) {
    BOOST_TEST(segregation_flux(0.0, 0.6, 1.0) == 0.0);
    BOOST_TEST(segregation_flux(0.6, 0.6, 1.0) == 0.0);
    BOOST_TEST(segregation_flux(0.3, 0.6, 1.0) == -0.15, tt::tolerance(1e-15));  // -a Phi/4
    BOOST_TEST(segregation_speed(0.3, 0.6, 2.0) == 0.0);
    BOOST_TEST(segregation_flux(0.0, 0.0, 1.0) == 0.0);  // no material
}

BOOST_AUTO_TEST_CASE(consistency_F_u_u_equals_f_u) {
    for (double a : {-2.0, -0.5, 0.0, 0.5, 2.0})
        for (double phi : {0.0, 0.1, 0.3, 0.5, 0.6}) {
            const FluxSide s{phi, 0.6, a};
            for (const SchemeRow& row : kSegregationSchemes)  // every flux of the scheme table
                BOOST_TEST(row.flux({s, s, 0.6, a}) == segregation_flux(phi, 0.6, a), tt::tolerance(1e-15));
        }
}

BOOST_AUTO_TEST_CASE(constant_Phi_reduces_to_classic_godunov) {
    for (double a : {-1.0, 1.0})
        for (double l = 0.0; l <= 0.6; l += 0.05)
            for (double r = 0.0; r <= 0.6; r += 0.05)
                BOOST_TEST(
                    modified_godunov_flux({{l, 0.6, a}, {r, 0.6, a}}) == classic_godunov_flux({{l, 0.6, a}, {r, 0.6, a}, 0.6, a}),
                    tt::tolerance(1e-14));
}

BOOST_AUTO_TEST_CASE(full_and_empty_cells_stay_in_bounds) {
    // A full cell below an arbitrary cell receives nothing from above (F = 0 at its top face).
    BOOST_TEST(modified_godunov_flux({{0.55, 0.55, 1.0}, {0.2, 0.6, 1.3}}) == 0.0);
    // An empty cell above anything loses nothing through its bottom face.
    BOOST_TEST(modified_godunov_flux({{0.3, 0.62, 0.7}, {0.0, 0.5, 1.0}}) == 0.0);
}

BOOST_AUTO_TEST_CASE(opposite_signs_give_zero_flux) {
    BOOST_TEST(modified_godunov_flux({{0.2, 0.6, 1.0}, {0.4, 0.6, -1.0}}) == 0.0);
    BOOST_TEST(modified_godunov_flux({{0.2, 0.6, -1.0}, {0.4, 0.6, 1.0}}) == 0.0);
}

BOOST_AUTO_TEST_CASE(classic_flux_ignores_the_jump_in_Phi) {
    // Table 1, case 3 (region C): the exact flux is f_L^min = -Phi_L/4, the classic one is not.
    const FluxSide L{0.1, 0.5, 1.0}, R{0.35, 0.62, 1.0};
    BOOST_TEST(modified_godunov_flux({L, R}) == -0.125, tt::tolerance(1e-15));
    BOOST_TEST(classic_godunov_flux({L, R, 0.56, 1.0}) != -0.125);
}

BOOST_AUTO_TEST_CASE(rusanov_fills_a_full_cell_from_a_fuller_one) {
    // Both cells full, Phi_R > Phi_L: the exact flux is 0, Rusanov's dissipation -alpha (phi_R - phi_L)/2
    // moves alpha (0.62 - 0.54)/2 = 0.04 of small particles down into the full cell (alpha = 1).
    BOOST_TEST(modified_godunov_flux({{0.54, 0.54, 1.0}, {0.62, 0.62, 1.0}}) == 0.0);
    BOOST_TEST(rusanov_flux({{0.54, 0.54, 1.0}, {0.62, 0.62, 1.0}}) == -0.04, tt::tolerance(1e-14));
}

BOOST_AUTO_TEST_CASE(scheme_table_names_parse_back_to_their_rows) {
    for (const SegregationScheme s : SegregationScheme::all()) {
        BOOST_CHECK(parse_scheme(scheme_name(s)) == s);
        BOOST_TEST((s.row().order == 1 || s.row().order == 2));
    }
    BOOST_TEST(SegregationScheme::all().size() == scheme_names().size());
    BOOST_TEST(bounded_scheme_names() == "modified-godunov, modified-godunov-2");
    BOOST_TEST(scheme_order(SegregationScheme::modified_godunov_2) == 2);
    BOOST_TEST(uses_interface_values(SegregationScheme::classic_upwind));
}

BOOST_AUTO_TEST_SUITE_END()
