// Sect. 2.1 closures: values at hand-checked states and the [material] section.
#include "closures/closures.hpp"
#include "core/error.hpp"
#include "run/scene_file.hpp"
#include "scenes/material_section.hpp"

#include <boost/test/unit_test.hpp>

#include <cmath>

using namespace granseg;
namespace tt = boost::test_tools;

BOOST_AUTO_TEST_SUITE(closures_tests)

BOOST_AUTO_TEST_CASE(hand_computed_state_below_Phi_co) {
    const Material m = Material::glass_substitute();
    const double Phi = 0.5, x = 0.0, T = 0.04;  // sqrt(T) = 0.2
    const ClosureValues v = evaluate_closures(m, Phi, x, T);
    const double g = 1.0 / (1.0 - Phi / v.Phi_rcp);
    BOOST_TEST(v.g == g, tt::tolerance(1e-14));
    BOOST_TEST(v.p_y == 0.0);
    BOOST_TEST(v.p == Phi * g * T, tt::tolerance(1e-14));
    BOOST_TEST(v.eta == m.eta0 * Phi * 0.2 * g, tt::tolerance(1e-14));
    BOOST_TEST(v.lambda == m.lambda0 * Phi * 0.2 * g, tt::tolerance(1e-14));
    BOOST_TEST(v.eps == m.eps0 * 0.2 * g, tt::tolerance(1e-14));
}

BOOST_AUTO_TEST_CASE(hand_computed_state_above_Phi_co) {
    const Material m = Material::glass_substitute();
    const double x = 1.0, T = 0.01;  // pure small particles: Phi_co = 0.58 at the table end point
    const double Phi = m.packing.Phi_co(x) + 0.02;
    const ClosureValues v = evaluate_closures(m, Phi, x, T);
    const double p_k = Phi * v.g * T, p_y = m.T0 * 0.02 * v.g;
    BOOST_TEST(v.p_y == p_y, tt::tolerance(1e-12));
    BOOST_TEST(v.p == p_k + p_y, tt::tolerance(1e-12));
    // eq. (20) in its original, unexpanded form
    BOOST_TEST(v.eta == m.eta0 * Phi * 0.1 * v.g * (1 + p_y / p_k), tt::tolerance(1e-12));
    BOOST_TEST(v.eps * Phi * T == v.dissipation, tt::tolerance(1e-12));
}

BOOST_AUTO_TEST_CASE(phi_hat_is_clamped_and_packing_limits_are_ordered) {
    const Material m = Material::glass_substitute();
    BOOST_TEST(m.packing.Phi_rcp(-0.5) == m.packing.Phi_rcp(0.0));
    BOOST_TEST(m.packing.Phi_rcp(1.5) == m.packing.Phi_rcp(1.0));
    BOOST_TEST(m.packing.Phi_rcp(0.4) > m.packing.Phi_rcp(0.0) + 0.02);  // mixtures pack denser
    BOOST_TEST(std::isinf(compressibility_factor(m, 0.7, 0.65)));
}

BOOST_AUTO_TEST_CASE(material_section_overrides_and_validates) {
    const SceneFile s = SceneFile::parse("[material]\neta0 = 2e-4\ng_law = \"lun-savage\"\n", "m.toml");
    const Material m = read_material(s);
    BOOST_TEST(m.eta0 == 2e-4);
    BOOST_CHECK(m.g_law == CompressibilityLaw::lun_savage);
    BOOST_CHECK_NO_THROW(s.finish());

    BOOST_CHECK_THROW(read_material(SceneFile::parse("[material]\neta0 = -1\n", "m.toml")), InputError);
    BOOST_CHECK_THROW(read_material(SceneFile::parse("[material]\ng_law = \"lun-savage\"\nbeta = 2\n", "m.toml")), InputError);
    BOOST_CHECK_THROW(read_material(SceneFile::parse("[material]\npacking_table = \"/nonexistent\"\n", "m.toml")), InputError);
}

BOOST_AUTO_TEST_CASE(packing_table_parser_rejects_bad_rows) {
    BOOST_CHECK_THROW(parse_packing_table("# x y z\n0 0.6 0.5\n", "p.dat"), InputError);
    BOOST_CHECK_THROW(parse_packing_table("# phi_hat Phi_rcp Phi_co\n0 0.5 0.6\n", "p.dat"), InputError);
    BOOST_CHECK_THROW(parse_packing_table("# phi_hat Phi_rcp Phi_co\n0 0.6\n", "p.dat"), InputError);
    const PackingTable t = builtin_packing_table();
    BOOST_TEST(t.phi_hat.size() == 21u);
    BOOST_TEST(!t.comments.empty());  // the file names its source
}

BOOST_AUTO_TEST_CASE(polynomial_fit_reproduces_a_polynomial) {
    std::vector<double> x, y;
    for (int i = 0; i <= 10; ++i) x.push_back(i / 10.0), y.push_back(1 - 2 * x.back() + 3 * x.back() * x.back());
    const Polynomial p = fit_polynomial(x, y, 2);
    BOOST_TEST(p.c.at(0) == 1.0, tt::tolerance(1e-12));
    BOOST_TEST(p.c.at(1) == -2.0, tt::tolerance(1e-12));
    BOOST_TEST(p.c.at(2) == 3.0, tt::tolerance(1e-12));
}

BOOST_AUTO_TEST_SUITE_END()
