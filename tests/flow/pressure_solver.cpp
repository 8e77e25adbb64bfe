// The pressure solve's rules (flow/pressure/pressure_solver.hpp) on systems whose answers are known: one
// cell (the Jacobian is 1 x 1, each conjugate-gradient solve exact, so the Newton iterates are
// those of the scalar equation Phi(p + dp) - Phi(p) - r = 0, computed here from the equation of
// state), and a column of cells without coupling (each row its own scalar equation).
//   - the stopping rule: Newton stops at the first iterate with |F| <= accuracy max |r| (plus
//     round-off), not before and not after;
//   - at least one Newton step, unless the guess is declared this step's solution or F is at
//     round-off (a bed at rest keeps dp = 0 exactly);
//   - the kink rule: a cell on the stiff branch (Phi > Phi_co) whose step would cross the kink
//     moves by the step in Phi, which for one cell lands on the root at once.
#include "flow/pressure/pressure_solver.hpp"
#include "closures/closures.hpp"
#include "flow/pressure/equation_of_state.hpp"

#include <boost/test/unit_test.hpp>

#include <cmath>
#include <vector>

using namespace granseg;

namespace {

/// nz uncoupled cells of one material at temperature T with volume fractions Phi; the closures
/// hold p(Phi) and the packing limits of phi_hat = 0.5.
struct Cells {
    Material m = Material::glass_substitute();
    FlowMesh mesh;
    FlowState state;
    CellClosures cl;
    PressureFaces faces;
    double rcp, co;

    Cells(const std::vector<double>& Phi, double T)
        : mesh(Grid::plane_xz(1, static_cast<int>(Phi.size()), 0.0, 0.0, 0.01, 0.01 * static_cast<double>(Phi.size()))),
          rcp(m.packing.Phi_rcp(0.5)),
          co(m.packing.Phi_co(0.5)) {
        const std::size_t n = Phi.size();
        state.Phi = Phi, state.T.assign(n, T);
        cl.Phi_rcp.assign(n, rcp), cl.Phi_co.assign(n, co);
        for (double v : Phi) cl.p.push_back(evaluate_closures_at(m, v, T, rcp, co).p);
        for (int a = 0; a < 3; ++a) faces[a].coupling.assign(mesh.face_kind[a].size(), 0.0);
    }
    /// The solve from dp = guess with explicit mass changes r.
    PressureSolveStats solve(const std::vector<double>& r, double accuracy, bool solved_guess, std::vector<double>& dp) {
        return PressureSolver(mesh).solve(mesh, m, state, cl, faces, r, accuracy, solved_guess, dp);
    }
    /// F(dp) of cell c, and the scalar Newton step from dp (the slope from the inverse equation of state).
    double residual(std::size_t c, double dp, double r) const {
        const double base = volume_at_pressure(m, cl.p[c], state.T[c], rcp, co, state.Phi[c]).Phi;
        return volume_at_pressure(m, cl.p[c] + dp, state.T[c], rcp, co, base).Phi - base - r;
    }
    double newton(std::size_t c, double dp, double r) const {
        return dp - residual(c, dp, r) / volume_at_pressure(m, cl.p[c] + dp, state.T[c], rcp, co).slope;
    }
};

}  // namespace

BOOST_AUTO_TEST_SUITE(flow_pressure_solver_tests)

// One cell on the soft branch, compacted by r: Phi(p) is concave, so the scalar Newton iterates
// rise to the root from below, |F| shrinking each step. For every accuracy the solve must take
// exactly the steps until |F| <= accuracy |r| + 1e-15 first holds, and return that iterate (to
// the rounding of the conjugate-gradient solve of a 1 x 1 system: 1e-13 of dp).
BOOST_AUTO_TEST_CASE(newton_stops_at_the_first_iterate_within_the_tolerance) {
    const double r = 0.08;
    Cells cells({0.3}, 1e-3);
    for (const double accuracy : {0.3, 1e-2, 1e-4, 1e-7}) {
        std::vector<double> iterates{0.0};
        while (std::fabs(cells.residual(0, iterates.back(), r)) > accuracy * r + 1e-15 || iterates.size() == 1)
            iterates.push_back(cells.newton(0, iterates.back(), r));
        std::vector<double> dp{0.0};
        const PressureSolveStats stats = cells.solve({r}, accuracy, false, dp);
        BOOST_TEST_INFO("accuracy " << accuracy);
        BOOST_TEST(stats.converged);
        BOOST_TEST(stats.newton == static_cast<int>(iterates.size()) - 1);
        BOOST_TEST(std::fabs(dp[0] - iterates.back()) <= 1e-13 * std::fabs(iterates.back()));
        BOOST_TEST(stats.residual <= accuracy * r + 1e-15);
    }
}

// At least one Newton step, also from a guess already within the tolerance (a lagged pressure
// would not damp the acoustic waves); none when the caller declares the guess this step's
// solution (a repeat after reversed faces: the guess then comes back bit for bit), and none when
// nothing moves (r = 0, guess 0: a bed at rest keeps dp = 0 exactly).
BOOST_AUTO_TEST_CASE(at_least_one_newton_step_unless_solved_or_at_rest) {
    const double r = 0.05, accuracy = 1e-2;
    Cells cells({0.3, 0.31, 0.32}, 1e-3);
    std::vector<double> solved(3, 0.0);
    cells.solve({r, r, r}, 1e-10, false, solved);
    std::vector<double> guess = solved;
    for (double& x : guess) x *= 1.0 + 1e-6;  // within the tolerance, above round-off
    BOOST_REQUIRE(std::fabs(cells.residual(0, guess[0], r)) < accuracy * r);
    BOOST_REQUIRE(std::fabs(cells.residual(0, guess[0], r)) > 1e-12);
    std::vector<double> dp = guess;
    BOOST_TEST(cells.solve({r, r, r}, accuracy, false, dp).newton == 1);
    dp = guess;
    BOOST_TEST(cells.solve({r, r, r}, accuracy, true, dp).newton == 0);
    BOOST_TEST(dp == guess);
    std::vector<double> rest(3, 0.0);
    const PressureSolveStats stats = cells.solve({0.0, 0.0, 0.0}, accuracy, false, rest);
    BOOST_TEST(stats.newton == 0);
    BOOST_TEST(stats.converged);
    BOOST_TEST((rest == std::vector<double>(3, 0.0)));
}

// A dense cell (Phi_co + 0.01, T = 1e-6: the stiff branch) expanded by r = -0.02 to below the
// kink. Linearised on the stiff side the step in p lands far below p = 0, where the soft branch's
// slope is a thousand times larger, and Newton would crawl back over several steps. The step in
// Phi, Phi + slope s = Phi(p) - F = Phi(p) + r, is the root itself for one cell: one Newton step,
// dp = p(Phi(p) + r) - p from the equation of state (its round trip: 1e-12 of dp).
BOOST_AUTO_TEST_CASE(a_step_across_the_kink_moves_in_phi) {
    const Material m = Material::glass_substitute();
    const double Phi0 = m.packing.Phi_co(0.5) + 0.01, r = -0.02, T = 1e-6;
    Cells cells({Phi0}, T);
    std::vector<double> dp{0.0};
    const PressureSolveStats stats = cells.solve({r}, 1e-2, false, dp);
    const double target = volume_at_pressure(cells.m, cells.cl.p[0], T, cells.rcp, cells.co, Phi0).Phi + r;
    const double expected = evaluate_closures_at(cells.m, target, T, cells.rcp, cells.co).p - cells.cl.p[0];
    BOOST_TEST(stats.converged);
    BOOST_TEST(stats.newton == 1);
    BOOST_TEST(std::fabs(dp[0] - expected) <= 1e-12 * std::fabs(expected));
}

BOOST_AUTO_TEST_SUITE_END()
