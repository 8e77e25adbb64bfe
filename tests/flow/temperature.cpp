// The temperature step (flow/diffusion/temperature.hpp) against exact discrete solutions: heating,
// dissipation and conduction solved together. One long step must give the steady balance of a
// sheared layer heated at one face, where the heat reaches only a few cells before dissipation
// takes it (conducting first and dissipating after would spread it over the whole column).
#include "flow/diffusion/temperature.hpp"

#include <boost/test/unit_test.hpp>

#include <cmath>

using namespace granseg;

BOOST_AUTO_TEST_SUITE(flow_temperature_tests)

namespace {

constexpr int kCells = 16;  // along z; 2 periodic cells along x
constexpr double kPhi = 0.5, kEta = 2e-3, kLambda = 5.0, kEpsPhi = 4e3, kShear = 1.0;

/// 2 periodic cells along x, `cells` along z, over a height of 1.
Grid column_grid(int cells) {
    Grid g = Grid::plane_xz(2, cells, 0.0, 0.0, 2.0 / cells, 1.0);
    g.periodic[0] = true;
    return g;
}

struct Column {
    Grid grid;
    FlowMesh mesh{grid};
    FlowState state;
    CellClosures closures;
    WallVelocities walls{};
    std::vector<double> heat = std::vector<double>(grid.cells(), 0.0);

    /// Uniform Phi and closures, T = T0; u_x = 0 in the lower half, kShear in the upper half
    /// (the upper wall moves with it), so only the two cells at the middle face are heated.
    explicit Column(double T0, int cells = kCells) : grid(column_grid(cells)) {
        const std::size_t n = grid.cells();
        state.Phi.assign(n, kPhi), state.T.assign(n, T0), state.E.assign(n, kPhi * T0);
        for (int b = 0; b < 3; ++b) state.u[b].assign(n, 0.0), state.m[b].assign(n, 0.0);
        for (int k = cells / 2; k < cells; ++k)
            for (int i = 0; i < 2; ++i) state.u[0][grid.index(i, 0, k)] = kShear;
        walls[2][1] = {kShear, 0.0, 0.0};
        closures.eta.assign(n, kEta), closures.lambda.assign(n, kLambda), closures.epsPhi.assign(n, kEpsPhi);
    }
    double T(int k) const { return state.T[grid.index(0, 0, k)]; }
};

}  // namespace

// Upper half k' = k - kCells/2 = 0 .. m-1 (m = kCells/2), by symmetry about the middle face:
//   (e + w) T_0 - w T_1 = S,   (e + 2w) T_k' - w (T_k'+1 + T_k'-1) = 0,   adiabatic top (ghost = T_m-1),
// e = eps Phi + Phi/dt, w = (3/2) lambda/h^2, S = (3/2) (eta/2) (U/h)^2 (half the face's heating).
// Solution T_k' = C cosh(theta (k' - m + 1/2)) with cosh(theta) = 1 + e/(2w). The solver stops at
// 1e-8 of the change's initial residual; with the condition number below 1 + 4w/e = 2.9 the error
// is below 3e-8 of the change (here T itself, T* = 0): 1e-7 of the largest T.
BOOST_AUTO_TEST_CASE(long_step_gives_the_steady_balance_of_heating_dissipation_and_conduction) {
    Column col(0.0);
    const double dt = 1e3, h = 1.0 / kCells;
    FlowSettings settings;
    settings.T_floor = 1e-30;
    TemperatureSolver(col.mesh).apply(col.mesh, settings, col.walls, dt, col.closures, col.heat, col.state);
    const double e = kEpsPhi + kPhi / dt, w = 1.5 * kLambda / (h * h), S = 1.5 * 0.5 * kEta * kShear * kShear / (h * h);
    const double theta = std::acosh(1.0 + e / (2.0 * w)), m = kCells / 2;
    const double C = S / ((e + w) * std::cosh(theta * (m - 0.5)) - w * std::cosh(theta * (m - 1.5)));
    const double T_max = C * std::cosh(theta * (m - 0.5));
    for (int k = 0; k < kCells / 2; ++k) {
        const double exact = C * std::cosh(theta * (k - m + 0.5));
        BOOST_TEST(std::fabs(col.T(kCells / 2 + k) - exact) <= 1e-7 * T_max);
        BOOST_TEST(std::fabs(col.T(kCells / 2 - 1 - k) - exact) <= 1e-7 * T_max);
    }
    // Conduction matters here (w/e = 0.48): T_0 = S/(e + w (1 - r)) with r = exp(-theta), 26 % below S/e.
    BOOST_TEST(std::fabs(col.T(kCells / 2) - S / e) > 0.1 * S / e);
}

// Without heating a uniform T decays as Phi T/(Phi + dt eps Phi), conduction doing nothing (to
// 1e-7 of the change, as above); an empty cell is at T_floor.
BOOST_AUTO_TEST_CASE(uniform_decay_is_exact_and_empty_cells_sit_at_the_floor) {
    Column col(2.0);
    for (auto& u : col.state.u[0]) u = 0.0;
    col.walls[2][1] = {0.0, 0.0, 0.0};
    const std::size_t hole = col.grid.index(1, 0, 5);
    col.state.Phi[hole] = 0.0;
    FlowSettings settings;
    const double dt = 1e-3;
    TemperatureSolver(col.mesh).apply(col.mesh, settings, col.walls, dt, col.closures, col.heat, col.state);
    const double exact = 2.0 * kPhi / (kPhi + dt * kEpsPhi);
    for (std::size_t c = 0; c < col.grid.cells(); ++c)
        if (c != hole) BOOST_TEST(std::fabs(col.state.T[c] - exact) <= 1e-7 * (2.0 - exact));
    BOOST_TEST(col.state.T[hole] == settings.T_floor);
}

// The warm start (the last step's change of T as the guess): step after step of a heated column,
// the solver that carries its guess gives what a fresh solver gives from the same state, to the
// solve's tolerance (1e-8 of the change's residual, times the condition number, at most
// 1 + 4w/e ~ 11 here: 1e-6 of the step's largest change), and needs fewer iterations. With little
// dissipation the heat of the sheared face spreads by conduction and T rises at a nearly steady
// rate, so each step's change is close to the last one's. (128 cells: on the 16-cell column the
// conjugate gradients end by exhausting the few modes the heating excites, whatever the guess.)
BOOST_AUTO_TEST_CASE(a_warm_started_solve_equals_a_fresh_one_in_fewer_iterations) {
    const int cells = 128;
    Column col(0.0, cells);
    for (double& e : col.closures.epsPhi) e = 1.0;
    FlowSettings settings;
    settings.T_floor = 1e-30;
    const double dt = 1e-5;
    TemperatureSolver warm(col.mesh);
    for (int step = 0; step < 20; ++step) warm.apply(col.mesh, settings, col.walls, dt, col.closures, col.heat, col.state);
    for (int step = 0; step < 3; ++step) {
        Column fresh = col;
        const std::vector<double> before = col.state.T;
        const int warm_iterations = warm.apply(col.mesh, settings, col.walls, dt, col.closures, col.heat, col.state);
        const int fresh_iterations =
            TemperatureSolver(fresh.mesh).apply(fresh.mesh, settings, fresh.walls, dt, fresh.closures, fresh.heat, fresh.state);
        double change = 0.0, difference = 0.0;
        for (std::size_t c = 0; c < col.grid.cells(); ++c) {
            change = std::max(change, std::fabs(col.state.T[c] - before[c]));
            difference = std::max(difference, std::fabs(col.state.T[c] - fresh.state.T[c]));
        }
        BOOST_TEST_INFO("step " << step + 21 << ": " << warm_iterations << " iterations warm, " << fresh_iterations
                                << " fresh; difference " << difference << " of a change " << change);
        BOOST_TEST(change > 0.0);
        BOOST_TEST(difference <= 1e-6 * change);
        BOOST_TEST(warm_iterations < fresh_iterations);
    }
}

BOOST_AUTO_TEST_SUITE_END()
