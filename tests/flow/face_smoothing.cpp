// The face velocity's pressure smoothing of the semi-implicit step (flow/faces/semi_implicit_faces.hpp,
// docs/flow_solver_pressure.md). With the default, face_smoothing = acoustic, its strength is the
// scheme's smoothing time tau, not the step dt, the checkerboard it is there to suppress is damped at
// the smallest steps the control takes, and no step is longer than acoustic_courant_max smoothing
// times; with face_smoothing = step its time is dt.
#include "closures/closures.hpp"
#include "flow/faces/semi_implicit_faces.hpp"
#include "flow/flow_solver.hpp"

#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <vector>

using namespace granseg;
namespace tt = boost::test_tools;

BOOST_AUTO_TEST_SUITE(flow_face_smoothing_tests)

namespace {

/// U* - V* on every interior face of a row of cells along x for a step dt: the face predictor
/// less the mass-weighted mean of the cells' predicted velocities. The state: Phi varying from
/// cell to cell, a face force D that is not the cells' forces interpolated (a cubic pressure),
/// and cells whose force part A is dt times their own acceleration (what the predictor gives).
std::vector<double> smoothing_velocities(double dt, FaceSmoothing mode) {
    const int n = 8;
    const Grid grid = Grid::plane_xz(n, 1, 0.0, 0.0, 0.008, 0.001);
    const FlowMesh mesh(grid);
    const std::size_t cells = grid.cells(), faces = grid.faces(0);
    const double h = grid.h[0];
    FlowState state;
    std::array<std::vector<double>, 3> A;
    for (auto& a : A) a.assign(cells, 0.0);
    state.Phi.assign(cells, 0.0), state.u = A;
    std::vector<double> p(cells);
    for (int i = 0; i < n; ++i) {
        const double x = (i + 0.5) * h;
        state.Phi[i] = 0.58 + 0.01 * std::sin(400.0 * x);
        p[i] = 200.0 + 4e6 * x * x * x;              // Pa per (kg/m^3): a cubic, so D differs from the cells' mean
        state.u[0][i] = 0.01 * std::cos(300.0 * x);  // u* (m/s)
    }
    for (int i = 1; i + 1 < n; ++i) {  // A = dt x the cell's acceleration from its centred pressure gradient
        A[0][i] = -dt * (p[i + 1] - p[i - 1]) / (2.0 * h * state.Phi[i]);
        state.u[0][i] += A[0][i];
    }
    CellClosures closures;
    closures.Phi_co.assign(cells, 0.55);
    closures.c.assign(cells, 0.0);
    for (int i = 0; i < n; ++i) closures.c[i] = 3.0 + 0.5 * i;  // m/s: tau = h/c below smoothing_time_max
    AxisPressureFaces pf;
    pf.force.assign(faces, 0.0), pf.predictor.assign(faces, 0.0), pf.smoothing.assign(faces, 0.0);
    for (int i = 0; i + 1 < n; ++i) pf.force[grid.face_index(0, i + 1, 0, 0)] = p[i] - p[i + 1];
    FlowSettings settings;
    settings.face_smoothing = mode;
    face_velocity_predictor(mesh, settings, 0, dt, state, closures, A, pf);
    std::vector<double> smoothing;
    for (int i = 1; i + 2 < n; ++i) {  // faces away from the rows where A is not set
        const double Phi_lo = state.Phi[i], Phi_hi = state.Phi[i + 1];
        const double mean = (Phi_lo * state.u[0][i] + Phi_hi * state.u[0][i + 1]) / (Phi_lo + Phi_hi);
        smoothing.push_back(pf.predictor[grid.face_index(0, i + 1, 0, 0)] - mean);
    }
    return smoothing;
}

}  // namespace

BOOST_AUTO_TEST_CASE(the_smoothing_of_a_state_is_the_same_at_dt_and_dt_over_2) {
    // tau (D/(h Phi_f) - mean(A)/dt): tau is set by the cells (h/c), and A/dt is the cells'
    // acceleration whatever the step, so the smoothing of one state does not change when the step
    // is halved. A smoothing taken over dt itself (U* = V* + dt D/(h Phi_f) - mean(A)) halves
    // with it and fails here.
    const double dt = FlowSettings{}.dt_max;
    const std::vector<double> full = smoothing_velocities(dt, FaceSmoothing::acoustic),
                              half = smoothing_velocities(0.5 * dt, FaceSmoothing::acoustic);
    double largest = 0.0;
    for (std::size_t f = 0; f < full.size(); ++f) {
        largest = std::max(largest, std::fabs(full[f]));
        BOOST_TEST(half[f] == full[f], tt::tolerance(1e-9));
    }
    BOOST_TEST(largest > 1e-6);  // the state does have a smoothing to compare
}

BOOST_AUTO_TEST_CASE(the_step_smoothing_takes_the_step_as_its_time) {
    // face_smoothing = step (Rhie and Chow's coefficient): the same state's smoothing halves with dt.
    const double dt = FlowSettings{}.dt_max;
    const std::vector<double> full = smoothing_velocities(dt, FaceSmoothing::step),
                              half = smoothing_velocities(0.5 * dt, FaceSmoothing::step);
    for (std::size_t f = 0; f < full.size(); ++f) BOOST_TEST(half[f] == 0.5 * full[f], tt::tolerance(1e-9));
}

BOOST_AUTO_TEST_CASE(a_checkerboard_is_damped_at_the_smallest_steps) {
    // A packed column at rest without gravity, its Phi alternating from cell to cell: the pressure
    // checkerboard that the cells' interpolated forces do not see. At a step far below dt_max
    // (here a tenth of a cell's acoustic time h/c, the scale of the acoustic first steps) a step
    // multiplies it by 1 - 4 c^2 dt tau/h^2 / (1 + 4 c^2 dt^2/h^2) (linear analysis, doc
    // flow_solver_pressure.md): 0.62 with tau = h/c, so ten steps leave 0.008 of it; a smoothing
    // time equal to dt would leave 0.96 per step, 0.66 after ten.
    const int n = 80;
    const double height = 0.08, h = height / n;
    const Material m = Material::glass_substitute();
    FlowSettings s;
    s.face_smoothing = FaceSmoothing::acoustic;
    Frame frame;
    frame.gravity = 0.0;
    const double Phi0 = 0.5 * (m.packing.Phi_co(s.phi_hat) + m.packing.Phi_rcp(s.phi_hat));
    const Grid grid = Grid::column(n, height);
    std::vector<double> Phi(grid.cells(), Phi0), zero(grid.cells(), 0.0), T(grid.cells(), s.T_floor);
    for (int k = 0; k < n; ++k) Phi[k] += (k % 2 ? 1e-4 : -1e-4);
    const double c =
        std::sqrt(evaluate_closures_at(m, Phi0, s.T_floor, m.packing.Phi_rcp(s.phi_hat), m.packing.Phi_co(s.phi_hat)).c2);
    s.dt_max = 0.1 * h / c;
    FlowSolver solver(grid, m, s, frame);
    solver.set_state(Phi, {zero, zero, zero}, T);
    // The mode's amplitude: the largest second difference / 4 in the middle half of the column,
    // which the waves the walls send out in these steps do not reach.
    const auto checkerboard = [&] {
        const std::vector<double>& P = solver.Phi();
        double largest = 0.0;
        for (int k = n / 4; k < 3 * n / 4; ++k) largest = std::max(largest, std::fabs(P[k - 1] - 2.0 * P[k] + P[k + 1]) / 4.0);
        return largest;
    };
    const double start = checkerboard();
    for (int step = 0; step < 10; ++step) solver.step();
    BOOST_TEST(solver.last_dt() <= s.dt_max);
    BOOST_TEST(checkerboard() < 0.05 * start);
}

BOOST_AUTO_TEST_CASE(no_step_is_longer_than_the_acoustic_courant_number_allows) {
    // A packed column at rest under gravity with dt_max at 8 ms: the material speeds allow that
    // step, the acoustic smoothing does not (tau_s = h/c, dt <= acoustic_courant_max tau_s). With
    // face_smoothing = step the same column takes dt_max.
    const int n = 20;
    const double height = 0.04, h = height / n;
    const Material m = Material::glass_substitute();
    const Grid grid = Grid::column(n, height);
    struct LastStep {
        double dt, dt_acoustic;  // the step taken, and acoustic_courant_max h/c at its start
        StepBound bound;
    };
    auto run = [&](FaceSmoothing mode) {
        FlowSettings s;
        s.face_smoothing = mode;
        s.dt_max = 8e-3;
        const double Phi0 = 0.5 * (m.packing.Phi_co(s.phi_hat) + m.packing.Phi_rcp(s.phi_hat));
        std::vector<double> Phi(grid.cells(), Phi0), zero(grid.cells(), 0.0), T(grid.cells(), s.T_floor);
        FlowSolver solver(grid, m, s, Frame{});
        solver.set_state(Phi, {zero, zero, zero}, T);
        for (int step = 0; step < 29; ++step) solver.step();
        double c_max = 0.0;  // the largest sound speed at the start of the last step, from which its dt is set
        for (int k = 0; k < n; ++k)
            c_max = std::max(c_max, std::sqrt(evaluate_closures_at(m, solver.Phi()[k], solver.T()[k],
                                                                   m.packing.Phi_rcp(s.phi_hat), m.packing.Phi_co(s.phi_hat))
                                                  .c2));
        solver.step();
        return LastStep{solver.last_dt(), s.acoustic_courant_max * h / c_max, solver.last_bound()};
    };
    const LastStep acoustic = run(FaceSmoothing::acoustic), step = run(FaceSmoothing::step);
    BOOST_TEST(acoustic.dt_acoustic < 0.5 * 8e-3);  // the bound is what sets the step here, not dt_max
    BOOST_TEST(std::string(step_bound_name(acoustic.bound)) == "acoustic");
    BOOST_TEST(acoustic.dt <= acoustic.dt_acoustic * (1.0 + 1e-9));  // the same sound speeds, up to round-off
    BOOST_TEST(acoustic.dt > 0.5 * acoustic.dt_acoustic);            // set by the step before's state, which changed little
    BOOST_TEST(std::string(step_bound_name(step.bound)) != "acoustic");
    BOOST_TEST(step.dt > acoustic.dt);
}

BOOST_AUTO_TEST_SUITE_END()
