// Faces the pressure reverses (flow/faces/semi_implicit_faces.hpp, mark_reversed_faces; the stage
// corrected_fluxes of flow/flow_solver.hpp): a face whose corrected velocity turns towards a cell
// that gives clearly less than the donor the pressure equation counted is solved again with the
// smaller donor. A face reversed onto an empty cell carries nothing once the dust cap has acted,
// and must be marked before it: otherwise the pressure equation counts an inflow that the
// transport never delivers, the step's Phi is not the Phi of its pressure, and the pressure
// increment no longer damps what the face smoothing moves (docs/history.md, "A slab's
// alternating mode at 2 ms").
#include "closures/closures.hpp"
#include "drum/bed.hpp"
#include "flow/flow_solver.hpp"

#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

using namespace granseg;

BOOST_AUTO_TEST_SUITE(flow_reversed_faces_tests)

// The drum of verify_flow_rotation's slab with two slices, at the default dt_max (2 ms) from its bed
// at rest: the surface cells' upper faces are reversed onto the empty cells above them at every
// step. The slices start equal and must stay equal to round-off; with the faces marked after the
// dust cap, a mode alternating from slice to slice grew by about 1.5 per step there (3.9e-10 of
// Phi at step 60, 3.9e-7 at step 80).
BOOST_AUTO_TEST_CASE(a_slab_keeps_its_slices_equal_at_the_default_step) {
    const Material m = Material::glass_substitute();
    FlowSettings s;
    // Solved tightly: at the default tolerance Newton stops where the two slices' rounding differs,
    // which leaves them apart by up to 1e-7 of Phi (verify_flow_rotation holds that part apart).
    s.pressure_tolerance = 1e-11;
    const double R = 0.05;
    const int n = 24, ny = 2;
    Frame f;
    f.omega = 2.0 * M_PI * 0.1;
    const Grid g = drum_grid(n, R, ny, ny * 2.0 * R / n);
    FlowSolver solver(g, m, s, f);
    const std::vector<double> Phi =
        lithostatic_bed(g, m, -R + 0.075, f.gravity, s.T_floor, m.packing.Phi_rcp(s.phi_hat), m.packing.Phi_co(s.phi_hat));
    const std::vector<double> zero(g.cells(), 0.0), T(g.cells(), s.T_floor);
    solver.set_state(Phi, {zero, zero, zero}, T);
    double spread = 0.0;
    for (int step = 0; step < 90; ++step) {
        solver.step();
        for (int k = 0; k < n; ++k)
            for (int i = 0; i < n; ++i)
                spread = std::max(spread, std::fabs(solver.Phi()[g.index(i, 0, k)] - solver.Phi()[g.index(i, 1, k)]));
    }
    BOOST_TEST(solver.last_dt() == s.dt_max);  // the default step, not a bound, set the last one
    BOOST_TEST(spread <= 1e-13);
}

BOOST_AUTO_TEST_SUITE_END()
