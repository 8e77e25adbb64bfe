// The flow state keeps Phi < Phi_rcp (flow/flow_solver.hpp), and Phi_rcp follows the mixture: a
// change of phi_hat that moves Phi_rcp to or below a cell's Phi is refused where it happens, by
// set_phi_hat, with a message that names the mixture change (not the next flow step's primitives).
#include "closures/closures.hpp"
#include "core/error.hpp"
#include "flow/flow_solver.hpp"

#include <boost/test/unit_test.hpp>

#include <string>

using namespace granseg;

BOOST_AUTO_TEST_SUITE(flow_mixture_change_tests)

BOOST_AUTO_TEST_CASE(a_mixture_change_that_packs_a_cell_beyond_phi_rcp_is_refused_by_name) {
    const Material m = Material::glass_substitute();
    const FlowSettings s;
    const Grid g = Grid::plane_xz(1, 10, 0.0, 0.0, 0.005, 0.05);
    // A mixed bed packs denser than a pure one: Phi between the two is legal only for the mixture.
    const double mixed = m.packing.Phi_rcp(0.5), pure = m.packing.Phi_rcp(0.0);
    BOOST_REQUIRE(pure < mixed - 2e-3);
    FlowSolver solver(g, m, s, Frame{});
    std::vector<double> Phi(g.cells(), 0.0), zero(g.cells(), 0.0), T(g.cells(), s.T_floor);
    for (int k = 0; k < 5; ++k) Phi[k] = mixed - 1e-3;
    solver.set_state(Phi, {zero, zero, zero}, T);
    solver.set_phi_hat(std::vector<double>(g.cells(), 0.45));  // Phi_rcp moves, stays above Phi
    std::vector<double> separated(g.cells(), 0.5);
    separated[3] = 0.0;
    try {
        solver.set_phi_hat(separated);
        BOOST_ERROR("set_phi_hat accepted Phi_rcp below Phi");
    } catch (const InvariantError& e) {
        const std::string what = e.what();
        BOOST_TEST(what.find("mixture change") != std::string::npos, what);
        BOOST_TEST(what.find("z = 0.0175") != std::string::npos, what);  // cell 3's centre
    }
    // The refused change left the last accepted mixture: the flow steps on.
    BOOST_CHECK_NO_THROW(solver.step());
}

BOOST_AUTO_TEST_SUITE_END()
