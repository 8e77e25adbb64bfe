// The coupled implicit viscosity (flow/diffusion/coupled_viscosity.hpp) against exact steady creep: with a
// step much longer than the viscous time, Phi u_new - dt div(eta grad u_new) = Phi u solves
// div(eta grad u) = -Phi f for the impulse Phi u = dt Phi f, up to Phi/(dt eta k^2) ~ 1e-9.
#include "flow/diffusion/viscosity.hpp"
#include "flow/diffusion/coupled_viscosity.hpp"

#include <boost/test/unit_test.hpp>

#include <cmath>

using namespace granseg;

BOOST_AUTO_TEST_SUITE(flow_viscosity_tests)

namespace {

constexpr double kPhi = 0.5, kEta = 1.0, kForce = 1.0, kDt = 1e8;  // dt eta/(Phi h^2) >= 1e8

/// A square [0, 1]^2 of n x n cells (walls all round), Phi = kPhi, u_y = dt f (the impulse).
FlowState duct_state(const Grid& g) {
    FlowState s;
    s.Phi.assign(g.cells(), kPhi);
    s.E = s.T = s.Phi;
    for (int b = 0; b < 3; ++b) s.u[b].assign(g.cells(), 0.0), s.m[b].assign(g.cells(), 0.0);
    s.u[1].assign(g.cells(), kDt * kForce);
    return s;
}

/// Steady flow along a square duct of side 1 with no-slip walls: eta Lap u = -G (G = Phi f),
/// u = G x(1-x)/2 - sum over odd n of 4 G/(n pi)^3 cosh(n pi (z - 1/2))/cosh(n pi/2) sin(n pi x).
double duct(double x, double z) {
    const double G = kPhi * kForce / kEta;
    double u = 0.5 * G * x * (1.0 - x);
    for (int n = 1; n < 200; n += 2) {
        const double k = n * M_PI;
        u -= 4.0 * G / (k * k * k) * std::cosh(k * (z - 0.5)) / std::cosh(0.5 * k) * std::sin(k * x);
    }
    return u;
}

/// Max |u_y - duct| over the cells after one coupled step on n x n cells.
double duct_error(int n) {
    const Grid g = Grid::plane_xz(n, n, 0.0, 0.0, 1.0, 1.0);
    const FlowMesh mesh(g);
    FlowState s = duct_state(g);
    CoupledViscosity(mesh).apply(mesh, FlowSettings{}, WallVelocities{}, kDt, std::vector<double>(g.cells(), kEta), s);
    double error = 0.0;
    for (int k = 0; k < n; ++k)
        for (int i = 0; i < n; ++i)
            error = std::max(error, std::fabs(s.u[1][g.index(i, 0, k)] - duct(g.center(0, i), g.center(2, k))));
    return error;
}

}  // namespace

// Second order: the five-point operator and the walls at h/2 (2 eta/h^2) are both O(h^2); the
// maximum of u is 0.0737 G, so 16 cells should already be within 1e-3 G.
BOOST_AUTO_TEST_CASE(coupled_step_gives_the_steady_duct_flow) {
    const double e16 = duct_error(16), e32 = duct_error(32);
    BOOST_TEST(e16 < 1e-3);
    BOOST_TEST(std::log2(e16 / e32) > 1.8);
}

// The split line solves multiply the two axes' responses: at this dt their steady creep is far
// too slow (the reason the coupled solve exists, docs/flow_solver.md Sect. 4).
BOOST_AUTO_TEST_CASE(split_step_creeps_too_slowly_at_long_steps) {
    const Grid g = Grid::plane_xz(16, 16, 0.0, 0.0, 1.0, 1.0);
    const FlowMesh mesh(g);
    FlowState s = duct_state(g);
    DiffusionLines lines(mesh);
    std::vector<double> work(g.cells());
    implicit_viscosity(mesh, FlowSettings{}, WallVelocities{}, kDt, std::vector<double>(g.cells(), kEta), lines, work, s);
    const std::size_t centre = g.index(8, 0, 8);
    BOOST_TEST(s.u[1][centre] < 1e-3 * duct(g.center(0, 8), g.center(2, 8)));
}

// A lid moving along x on the upper wall of the domain over a layer periodic in x: the steady
// profile is linear, u_x = U z, which the scheme holds exactly; an empty cell stays at rest.
BOOST_AUTO_TEST_CASE(coupled_step_moves_with_the_lid_and_keeps_empty_cells_at_rest) {
    Grid g = Grid::plane_xz(4, 8, 0.0, 0.0, 0.5, 1.0);
    g.periodic[0] = true;
    const FlowMesh mesh(g);
    WallVelocities walls{};
    walls[2][1] = {1.0, 0.0, 0.0};
    std::vector<double> eta(g.cells(), kEta);
    CoupledViscosity solve(mesh);
    FlowState s = duct_state(g);
    solve.apply(mesh, FlowSettings{}, walls, kDt, eta, s);
    for (int k = 0; k < 8; ++k)
        for (int i = 0; i < 4; ++i) BOOST_TEST(s.u[0][g.index(i, 0, k)] == g.center(2, k), boost::test_tools::tolerance(1e-6));
    const std::size_t hole = g.index(1, 0, 3);
    s.Phi[hole] = 0.0, s.u[0][hole] = 1.0, eta[hole] = 0.0;
    solve.apply(mesh, FlowSettings{}, walls, kDt, eta, s);
    BOOST_TEST(s.u[0][hole] == 0.0);
}

BOOST_AUTO_TEST_SUITE_END()
