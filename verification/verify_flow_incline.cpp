// Verification (c) of the flow solver (Sect. 2.1): a layer on a rough inclined plane.
//
// What the model predicts (docs/flow_solver.md, Sect. 1): eqs. (16)-(20) give eta = eta0 p/sqrt(T),
// eps Phi T = eps0 p sqrt(T), lambda = lambda0 p/sqrt(T) exactly. For steady uniform flow down a
// plane at angle theta (no-slip, adiabatic bottom, free surface) momentum gives tau = p tan(theta),
// and eq. (14) becomes, with s = sqrt(T),
//     3 lambda0 (p s')' = eps0 p s (1 - tan^2(theta)/mu^2),   mu = sqrt(2 eta0 eps0/3),
// with p s' = 0 at both ends. Multiplying by s and integrating shows that a solution s > 0 exists
// only for tan(theta) = mu, and then s is uniform: the boundary-value problem has the one-parameter
// family T = const, u = mu sqrt(T) z/eta0, Phi lithostatic at that T. Below the friction angle
// no steady flow exists (T decays to its floor), above it the layer accelerates. Checked:
//   1. the solver's critical angle (between decay and growth of the kinetic energy, by bisection)
//      converges to atan(mu) as the grid is refined;
//   2. at 18 degrees the flow stops: the kinetic energy falls by orders of magnitude, T reaches its
//      floor, and what remains is the steady creep the floor allows (gamma_dot = tan(theta)
//      sqrt(T_floor)/eta0), converging at first order;
//   3. at 26 degrees the layer accelerates;
//   4. at the critical angle the profiles converge to the boundary-value solution: the relative
//      spread of T in the bed falls at first order, u is linear with slope mu sqrt(T)/eta0 (T the
//      bed's mean), and Phi follows the GSL odeiv2 lithostatic profile for the simulated T(z).
//   5. oblique to the grid: a bed in a box whose surface slopes at 19 deg (below atan(mu)), cells
//      cut by the staircase of the slope, holds: its centre of mass moves by less than half a cell
//      in 1 s. The move of a 26 deg slope is printed beside it (the explicit step's acoustic
//      dissipation holds it too at this cell size; docs/history.md, flow solver).
// Every check runs in both time-stepping modes (explicit, semi-implicit) with the same tolerance.
// Writes flow_incline_*.dat (explicit mode; the semi-implicit mode adds _semi_implicit) for
// figures/fig_flow_incline.gp.
//
// Run: build/verification/verify_flow_incline [--data DIR]
#include "harness/check_table.hpp"
#include "harness/flow_reference.hpp"
#include "harness/incline_flow.hpp"
#include "harness/program.hpp"

#include <algorithm>
#include <cmath>
#include <string>

using namespace granseg;
using granseg::verify::CheckTable;
using granseg::verify::in_bed;
using granseg::verify::kInclineDepth;
using granseg::verify::kInclineWindow;

namespace {

// The scheme is first order: refining h by 2 must shrink an error at least by 2^kOrderMin
// (0.9 leaves room for the pre-asymptotic range).
constexpr double kOrderMin = 0.9;
// Below the friction angle the kinetic energy must fall by this factor within a second (it falls
// exponentially at the rate eps ~ eps0 g sqrt(T) ~ 10^2 1/s until only the creep is left).
constexpr double kStopFactor = 1e-6;

/// How far (m) the centre of mass of a bed whose surface slopes at theta_deg moves along x in
/// t_end: a box 5 cm x 3.5 cm of 40 x 28 cells, no-slip walls, the surface z = 3 mm + x tan(theta)
/// with the cells below it (centres) filled at Phi(p = Phi_co |g| depth): close to the lithostatic
/// state, so that the start itself does not shake the bed. A slope that fails moves downhill (-x).
double slope_shift(const Material& m, const FlowSettings& settings, double theta_deg, double t_end) {
    const Grid g = Grid::plane_xz(40, 28, 0.0, 0.0, 0.05, 0.035);
    Frame frame;
    FlowSolver solver(g, m, settings, frame);
    const double rcp = m.packing.Phi_rcp(settings.phi_hat), co = m.packing.Phi_co(settings.phi_hat);
    std::vector<double> Phi(g.cells(), 0.0), zero(g.cells(), 0.0);
    for (int k = 0; k < g.n[2]; ++k)
        for (int i = 0; i < g.n[0]; ++i) {
            const double depth = 0.003 + g.center(0, i) * std::tan(theta_deg * M_PI / 180.0) - g.center(2, k);
            if (depth > 0.0)
                Phi[g.index(i, 0, k)] = verify::Phi_of_pressure(m, co * frame.gravity * depth, settings.T_floor, rcp, co);
        }
    solver.set_state(Phi, {zero, zero, zero}, zero);
    auto x_mass = [&] {
        double mass = 0.0, moment = 0.0;
        for (int k = 0; k < g.n[2]; ++k)
            for (int i = 0; i < g.n[0]; ++i) {
                const double Phi_c = solver.Phi()[g.index(i, 0, k)];
                mass += Phi_c, moment += Phi_c * g.center(0, i);
            }
        return moment / mass;
    };
    const double x0 = x_mass();
    while (solver.time() < t_end) solver.step(t_end);
    return x_mass() - x0;
}

/// Every check of this program in one time-stepping mode.
void check_mode(CheckTable& table, const verify::ProgramOptions& options, const Material& m, TimeStepping mode) {
    FlowSettings settings;
    settings.time_stepping = mode;
    auto run = [&](double theta_deg, int nz, double t_end) { return verify::run_incline(m, settings, theta_deg, nz, t_end); };
    const double mu = std::sqrt(2.0 * m.eta0 * m.eps0 / 3.0), theta_mu = std::atan(mu) * 180.0 / M_PI;
    // 1. Critical angle against atan(mu).
    const int sizes[] = {16, 32, 64};
    double crit[3];
    DataTable angles;
    for (int i = 0; i < 3; ++i) {
        crit[i] = verify::critical_angle(m, settings, sizes[i]);
        angles.row({{"nz", static_cast<double>(sizes[i])}, {"theta_c_deg", crit[i]}, {"atan_mu_deg", theta_mu}});
        table.note(verify::mode_tag(mode) + "nz = " + std::to_string(sizes[i]) + ": critical angle " + verify::format(crit[i]) +
                   " deg");
    }
    for (int i = 1; i < 3; ++i)
        table.at_least(verify::mode_tag(mode) + "critical angle -> atan(mu): order, nz = " + std::to_string(sizes[i - 1]) +
                           " -> " + std::to_string(sizes[i]),
                       std::log2(std::fabs(crit[i - 1] - theta_mu) / std::fabs(crit[i] - theta_mu)), kOrderMin);

    // 2. Below the friction angle: the flow stops; the remaining creep is set by T_floor.
    const double T_floor = FlowSettings{}.T_floor, theta = 18.0;
    const double creep = std::tan(theta * M_PI / 180.0) * std::sqrt(T_floor) / m.eta0;  // gamma_dot at the floor
    double creep_error[2];
    DataTable below;
    for (int i = 0; i < 2; ++i) {
        const int nz = 40 << i;
        const verify::InclineRun r = run(theta, nz, kInclineWindow[1]);
        const verify::InclineRun start = run(theta, nz, 0.0);
        double worst = 0.0;
        for (int k = 0; k < nz; ++k) {
            below.row({{"nz", static_cast<double>(nz)},
                       {"z", r.z[k]},
                       {"u_x", r.u[k]},
                       {"u_creep_law", in_bed(m, r.Phi[k]) ? creep * r.z[k] : 0.0},
                       {"T", r.T[k]}});
            if (in_bed(m, r.Phi[k])) worst = std::max(worst, std::fabs(r.u[k] - creep * r.z[k]) / (creep * kInclineDepth));
        }
        below.blank();
        below.blank();  // gnuplot index
        creep_error[i] = worst;
        const std::string tag = verify::mode_tag(mode) + "18 deg, nz = " + std::to_string(nz) + ": ";
        table.at_most(tag + "kinetic energy at 1.5 s / at 0 s", r.kinetic[1] / start.kinetic[0], kStopFactor);
        table.near_relative(tag + "max T / T_floor (flow stopped)", r.T_max / T_floor, 1.0, 1e-9);
        table.note(tag + "max |u - tan(theta) sqrt(T_floor) z/eta0| / (gamma_dot_creep depth) = " + verify::format(worst));
    }
    table.at_least(verify::mode_tag(mode) + "18 deg: creep law error, order nz = 40 -> 80",
                   std::log2(creep_error[0] / creep_error[1]), kOrderMin);

    // 3. Above the friction angle the layer accelerates.
    const verify::InclineRun fast = run(26.0, 32, kInclineWindow[1]);
    table.at_least(verify::mode_tag(mode) + "26 deg: kinetic energy at 1.5 s / at 0.5 s (growth)",
                   fast.kinetic[1] / fast.kinetic[0], 1.0);

    // 4. At the critical angle: the profiles against the boundary-value solution.
    DataTable profiles;
    double spread[2], u_errors[2], Phi_errors[2];
    for (int i = 1; i < 3; ++i) {
        const int nz = sizes[i];
        const verify::InclineProfileErrors e = verify::incline_profile_errors(m, run(crit[i], nz, 2.0), crit[i], &profiles);
        spread[i - 1] = e.T_spread, u_errors[i - 1] = e.u, Phi_errors[i - 1] = e.Phi;
        const std::string tag = verify::mode_tag(mode) + "critical angle, nz = " + std::to_string(nz) + ": ";
        table.note(tag + "relative spread of T in the bed " + verify::format(e.T_spread) + ", max |u - u_bvp|/u_bvp(depth) " +
                   verify::format(e.u) + ", max |Phi - Phi_bvp(GSL)| " + verify::format(e.Phi));
    }
    table.at_least(verify::mode_tag(mode) + "critical angle: T spread -> 0 (uniform T), order nz = 32 -> 64",
                   std::log2(spread[0] / spread[1]), kOrderMin);
    table.at_least(verify::mode_tag(mode) + "critical angle: u -> u_bvp, order nz = 32 -> 64",
                   std::log2(u_errors[0] / u_errors[1]), kOrderMin);
    table.at_least(verify::mode_tag(mode) + "critical angle: Phi -> Phi_bvp, order nz = 32 -> 64",
                   std::log2(Phi_errors[0] / Phi_errors[1]), kOrderMin);
    // 5. Oblique to the grid. A bed that holds moves only by settling and by the creep T_floor allows,
    // a small share of a cell; a failing one slides by more than a cell (the program prints the
    // shifts): half a cell tells them apart.
    const double h = 0.05 / 40;
    const double held = slope_shift(m, settings, 19.0, 1.0), steep = slope_shift(m, settings, 26.0, 1.0);
    table.at_most(verify::mode_tag(mode) + "19 deg slope oblique to the grid, 1 s: |move of the centre of mass| / h",
                  std::fabs(held) / h, 0.5);
    table.note(verify::mode_tag(mode) + "26 deg slope oblique to the grid, 1 s: the centre of mass moved " +
               verify::format(1e3 * steep) + " mm (19 deg: " + verify::format(1e3 * held) +
               " mm; h = " + verify::format(1e3 * h) + " mm)");
    verify::write_data(options, "flow_incline_angles" + verify::mode_suffix(mode) + ".dat", angles);
    verify::write_data(options, "flow_incline_below" + verify::mode_suffix(mode) + ".dat", below);
    verify::write_data(options, "flow_incline_profiles" + verify::mode_suffix(mode) + ".dat", profiles);
}

}  // namespace

int main(int argc, char** argv) {
    const verify::FlowProgram program = verify::flow_program(argc, argv);
    const double theta_mu = std::atan(program.material.shear_friction()) * 180.0 / M_PI;
    return verify::run_flow_modes(
        program, "Sect. 2.1 flow (c): inclined plane (friction angle atan(mu) = " + verify::format(theta_mu) + " deg)",
        check_mode);
}
