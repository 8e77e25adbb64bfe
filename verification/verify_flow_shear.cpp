// Verification (b) of the flow solver (Sect. 2.1): homogeneous simple shear.
//
// A layer of height H between walls moving at -U/2 (z = 0) and +U/2 (z = H) along x, no gravity,
// uniform Phi, starting at rest. (With walls at 0 and U the start from rest heats the upper half
// first; in the kinetic regime that antisymmetric temperature mode decays only by conduction,
// e-folding ~4 s here. The symmetric frame is the same problem and does not excite it.) With adiabatic walls the only steady
// state is uniform shear gamma_dot = U/H with uniform T (docs/flow_solver.md: the heat equation
// with adiabatic walls forces uniform sqrt(T) when tau/p is uniform), and eq. (14) then gives
// heating (3/2) eta gamma_dot^2 = eps Phi T, i.e. eq. (45):
//     T = 3 eta0 gamma_dot^2 / (2 eps0),   tau/p = eta0 gamma_dot/sqrt(T) = sqrt(2 eta0 eps0 / 3),
// and p_k = Phi g T grows like gamma_dot^2 (Bagnold). Checked for gamma_dot = 1, 10, 100 1/s in the
// yield regime (Phi = Phi_co + 0.01) and for gamma_dot = 100 1/s in the kinetic regime
// (Phi = Phi_co - 0.05). The expected values are the closed forms above; the measured ones come
// from the solver's fields through the closures (tau = eta (u_(k+1) - u_k)/h, p, p_k).
// Every check runs in both time-stepping modes (explicit, semi-implicit) with the same tolerance.
// Writes flow_shear_*.dat (explicit mode; the semi-implicit mode adds _semi_implicit) for
// figures/fig_flow_shear.gp.
//
// Run: build/verification/verify_flow_shear [--data DIR]   (a few seconds)
#include "closures/closures.hpp"
#include "flow/flow_solver.hpp"
#include "harness/check_table.hpp"
#include "harness/flow_reference.hpp"
#include "harness/program.hpp"

#include <cfloat>
#include <cmath>
#include <string>

using namespace granseg;
using granseg::verify::CheckTable;

namespace {

constexpr double kHeight = 0.01;
constexpr int kCells = 20;
// Time to steady state: the slowest process is momentum diffusion, H^2 Phi/eta, with
// eta = eta0 p/sqrt(T): 2e-3 s (yield regime, gamma_dot = 1) to 0.09 s (gamma_dot = 100), 3 s in the
// kinetic regime at gamma_dot = 100. Runs last 30 of these times, so transients are below e^-30.
constexpr double kYieldTime = 3.0, kKineticTime = 90.0;
// The uniform steady state is exact for the scheme (linear u, uniform T: the discrete heating is
// eta gamma_dot^2 in every cell, walls included), so T, tau/p match eq. (45) up to the remaining
// transient (1e-13) and the rounding of a few hundred operations per step: 1e-9 relative.
constexpr double kSteadyTol = 1e-9;

struct Shear {
    double T, tau_over_p, p_k, linear_error, T_spread;
};

Shear run(const Material& m, TimeStepping mode, double Phi, double gamma_dot, double T0, double t_end, DataTable& profiles) {
    const Grid g = Grid::column(kCells, kHeight);
    FlowSettings s;
    s.time_stepping = mode;
    FlowSolver solver(g, m, s, Frame{0.0});
    const double U = gamma_dot * kHeight;
    solver.set_wall_velocity(2, 0, {-0.5 * U, 0.0, 0.0});
    solver.set_wall_velocity(2, 1, {0.5 * U, 0.0, 0.0});
    const std::vector<double> zero(kCells, 0.0);
    solver.set_state(std::vector<double>(kCells, Phi), {zero, zero, zero}, std::vector<double>(kCells, std::max(T0, s.T_floor)));
    while (solver.time() < t_end) solver.step(t_end);

    const double rcp = m.packing.Phi_rcp(s.phi_hat), co = m.packing.Phi_co(s.phi_hat);
    Shear r{};
    double T_min = INFINITY, T_max = 0.0;
    for (int k = 0; k < kCells; ++k) {
        const double T = solver.T()[k], z = g.center(2, k);
        T_min = std::min(T_min, T), T_max = std::max(T_max, T);
        r.linear_error = std::max(r.linear_error, std::fabs(solver.u(0)[k] - gamma_dot * (z - 0.5 * kHeight)) / U);
        profiles.row({{"gamma_dot", gamma_dot},
                      {"Phi", Phi},
                      {"z", z},
                      {"u_x", solver.u(0)[k]},
                      {"T", T},
                      {"p", evaluate_closures_at(m, solver.Phi()[k], T, rcp, co).p}});
    }
    profiles.blank();
    profiles.blank();
    const int k = kCells / 2;
    const ClosureValues v = evaluate_closures_at(m, solver.Phi()[k], solver.T()[k], rcp, co);
    r.T = solver.T()[k];
    r.tau_over_p = v.eta * (solver.u(0)[k] - solver.u(0)[k - 1]) / g.h[2] / v.p;
    r.p_k = v.p_k;
    r.T_spread = (T_max - T_min) / T_max;
    return r;
}

/// Every check of this program in one time-stepping mode.
void check_mode(CheckTable& table, const verify::ProgramOptions& options, const Material& m, TimeStepping mode) {
    const double co = m.packing.Phi_co(FlowSettings{}.phi_hat);
    const double mu = std::sqrt(2.0 * m.eta0 * m.eps0 / 3.0);
    DataTable profiles;
    DataTable scan;

    // The yield-regime runs start with T at its floor. In the kinetic regime eta ~ sqrt(T) vanishes
    // with T, and a shear layer grown from the wall out of T_floor takes minutes; that run starts
    // with T at half its steady value instead (still at rest).
    struct Case {
        const char* regime;
        double Phi, gamma_dot, T0, t_end;
    };
    const double T100 = 3.0 * m.eta0 * 100.0 * 100.0 / (2.0 * m.eps0);
    const Case cases[] = {{"yield", co + 0.01, 1.0, 0.0, kYieldTime},
                          {"yield", co + 0.01, 10.0, 0.0, kYieldTime},
                          {"yield", co + 0.01, 100.0, 0.0, kYieldTime},
                          {"kinetic", co - 0.05, 100.0, 0.5 * T100, kKineticTime}};
    double lx[3], ly[3];
    int n = 0;
    for (const Case& c : cases) {
        const Shear r = run(m, mode, c.Phi, c.gamma_dot, c.T0, c.t_end, profiles);
        const double T_eq = 3.0 * m.eta0 * c.gamma_dot * c.gamma_dot / (2.0 * m.eps0);  // eq. (45)
        const std::string tag = verify::mode_tag(mode) + c.regime + ", gamma_dot = " + verify::format(c.gamma_dot) + ": ";
        table.near_relative(tag + "T vs 3 eta0 gamma_dot^2/(2 eps0)", r.T, T_eq, kSteadyTol);
        table.near_relative(tag + "tau/p vs sqrt(2 eta0 eps0/3)", r.tau_over_p, mu, kSteadyTol);
        table.at_most(tag + "(T_max - T_min)/T_max", r.T_spread, kSteadyTol);
        table.at_most(tag + "max |u - gamma_dot (z - H/2)|/U", r.linear_error, kSteadyTol);
        if (c.regime == std::string("yield")) {
            scan.row({{"gamma_dot", c.gamma_dot}, {"T", r.T}, {"T_eq45", T_eq}, {"tau_over_p", r.tau_over_p}, {"p_k", r.p_k}});
            lx[n] = std::log(c.gamma_dot), ly[n] = std::log(r.p_k), ++n;
        }
    }
    // Bagnold: least-squares slope of ln p_k against ln gamma_dot over the two decades.
    const double mx = (lx[0] + lx[1] + lx[2]) / 3, my = (ly[0] + ly[1] + ly[2]) / 3;
    double sxy = 0, sxx = 0;
    for (int i = 0; i < 3; ++i) sxy += (lx[i] - mx) * (ly[i] - my), sxx += (lx[i] - mx) * (lx[i] - mx);
    table.near(verify::mode_tag(mode) + "yield: d ln p_k / d ln gamma_dot over 1..100 1/s", sxy / sxx, 2.0, 2 * kSteadyTol);
    verify::write_data(options, "flow_shear_profiles" + verify::mode_suffix(mode) + ".dat", profiles);
    verify::write_data(options, "flow_shear_scan" + verify::mode_suffix(mode) + ".dat", scan);
}

}  // namespace

int main(int argc, char** argv) {
    const verify::FlowProgram program = verify::flow_program(argc, argv);
    return verify::run_flow_modes(program, "Sect. 2.1 flow (b): homogeneous simple shear (eq. 45)", check_mode);
}
