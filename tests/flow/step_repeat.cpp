// The semi-implicit step's repeat (flow/flow_solver.hpp, the stage that halves dt after a broken
// bound): a step attempt whose corrected fluxes break a bound restores the state at t^n,
// including the warm start of the pressure solve, and tries again with half the dt. The repeat
// must therefore be the step a copy of the solver takes from the same state with that dt from
// the start: bit for bit, since both run the same arithmetic on the same data.
#include "closures/closures.hpp"
#include "flow/flow_solver.hpp"

#include <boost/test/unit_test.hpp>

#include <cmath>
#include <optional>

using namespace granseg;

BOOST_AUTO_TEST_SUITE(flow_step_repeat_tests)

// A dense column (Phi_rcp - 0.002) thrown at 1 m/s onto the floor: after some steps of
// compaction the corrected fluxes of a step would compact the bottom cells beyond the bound and the
// step is repeated; a copy of the solver made before that step is told to stop at t + dt/2. Both
// start the pressure solve from the last step's dp, so they must agree bit for bit.
BOOST_AUTO_TEST_CASE(a_repeat_equals_a_step_taken_at_half_the_dt) {
    const Material m = Material::glass_substitute();
    FlowSettings s;
    // The repeat must end exactly on a double (t0 + dt/2 - t0 == dt/2) for the copy to stop there;
    // with the acoustic smoothing's steps left unbounded the column's first repeat does (with the
    // bound or the step's smoothing it falls where the sum rounds). The repeat itself does not
    // depend on the smoothing or on what set the step.
    s.acoustic_courant_max = 1e5;
    const Grid g = Grid::plane_xz(1, 20, 0.0, 0.0, 0.002, 0.04);
    FlowSolver solver(g, m, s, Frame{});
    std::vector<double> zero(g.cells(), 0.0), T(g.cells(), s.T_floor), Phi(g.cells(), 0.0), u_z(g.cells(), 0.0);
    for (int k = 0; k < 14; ++k) Phi[k] = m.packing.Phi_rcp(s.phi_hat) - 0.002, u_z[k] = -1.0;
    solver.set_state(Phi, {zero, zero, u_z}, T);
    std::optional<FlowSolver> before;
    while (solver.time() < 0.5 && solver.counters().repeated == 0) {
        before.emplace(solver);
        solver.step();
    }
    BOOST_REQUIRE(solver.counters().repeated == 1);
    BOOST_REQUIRE(solver.last_bound() == StepBound::halved);
    BOOST_REQUIRE(solver.steps() > 1);  // the last step's dp is the warm start
    const double t0 = before->time(), half = solver.last_dt();
    BOOST_REQUIRE((t0 + half) - t0 == half);  // the copy's step ends exactly there
    before->step(t0 + half);
    BOOST_TEST(before->last_dt() == half);
    BOOST_TEST(before->counters().repeated == 0);
    for (std::size_t c = 0; c < g.cells(); ++c) {
        BOOST_TEST_INFO("cell " << c);
        BOOST_TEST(solver.Phi()[c] == before->Phi()[c]);
        BOOST_TEST(solver.T()[c] == before->T()[c]);
        BOOST_TEST(solver.u(2)[c] == before->u(2)[c]);
    }
}

BOOST_AUTO_TEST_SUITE_END()
