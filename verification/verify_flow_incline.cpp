// Verification (c) of the flow solver (Sect. 2.1): a layer on a rough inclined plane.
//
// What the model predicts (docs/flow_solver.md, Sect. 6): eqs. (16)-(20) give eta = eta0 p/sqrt(T),
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
// Every check runs in both time-stepping modes (explicit, semi-implicit) with the same tolerance.
// Writes flow_incline_*.dat (explicit mode; the semi-implicit mode adds _semi_implicit) for
// figures/fig_flow_incline.gp.
//
// Run: build/verification/verify_flow_incline [--data DIR]   (about 10 s)
#include "closures/closures.hpp"
#include "flow/bed.hpp"
#include "flow/flow_solver.hpp"
#include "harness/check_table.hpp"
#include "harness/flow_reference.hpp"
#include "harness/program.hpp"

#include <cmath>
#include <functional>
#include <string>

using namespace granseg;
using granseg::verify::CheckTable;

namespace {

constexpr double kDomain = 0.02, kDepth = 0.01, kGravity = 9.81;
constexpr double kStart = 20.0;        // 1/s: the initial linear shear, with T from eq. (45)
constexpr double kWindow[2] = {0.5, 1.5};  // s: kinetic energy compared between these times
// The scheme is first order: refining h by 2 must shrink an error at least by 2^kOrderMin
// (0.9 leaves room for the pre-asymptotic range).
constexpr double kOrderMin = 0.9;
// Below the friction angle the kinetic energy must fall by this factor within a second (it falls
// exponentially at the rate eps ~ eps0 g sqrt(T) ~ 10^2 1/s until only the creep is left).
constexpr double kStopFactor = 1e-6;

struct Incline {
    double kinetic[2] = {0.0, 0.0};  // at kWindow[0], kWindow[1]
    std::vector<double> z, Phi, u, T;
    double T_max = 0.0;
};

Incline run(const Material& m, TimeStepping mode, double theta_deg, int nz, double t_end) {
    const double theta = theta_deg * M_PI / 180.0;
    Grid g = Grid::column(nz, kDomain);
    g.periodic[0] = true;
    FlowSettings s;
    s.time_stepping = mode;
    Frame f;
    f.gravity = kGravity;
    f.tilt = theta;
    FlowSolver solver(g, m, s, f);
    const double T0 = steady_shear_temperature(m, kStart);
    const std::vector<double> Phi = lithostatic_bed(g, m, kDepth, kGravity * std::cos(theta), T0,
                                                    m.packing.Phi_rcp(s.phi_hat), m.packing.Phi_co(s.phi_hat));
    std::vector<double> ux(nz, 0.0), zero(nz, 0.0);
    for (int k = 0; k < nz; ++k) ux[k] = Phi[k] > 0.0 ? kStart * g.center(2, k) : 0.0;
    solver.set_state(Phi, {ux, zero, zero}, std::vector<double>(nz, T0));
    auto kinetic = [&] {
        double e = 0.0;
        for (int k = 0; k < nz; ++k) e += 0.5 * solver.Phi()[k] * solver.u(0)[k] * solver.u(0)[k] * g.h[2];
        return e;
    };
    Incline r;
    for (int w = 0; w < 2; ++w) {
        const double t = std::min(kWindow[w], t_end);
        while (solver.time() < t) solver.step(t);
        r.kinetic[w] = kinetic();
    }
    while (solver.time() < t_end) solver.step(t_end);
    for (int k = 0; k < nz; ++k) {
        r.z.push_back(g.center(2, k)), r.Phi.push_back(solver.Phi()[k]);
        r.u.push_back(solver.u(0)[k]), r.T.push_back(solver.T()[k]);
        r.T_max = std::max(r.T_max, solver.T()[k]);
    }
    return r;
}

/// The solver's critical angle: bisection on the sign of the kinetic-energy trend (0.002 degrees).
double critical_angle(const Material& m, TimeStepping mode, int nz) {
    double lo = 20.0, hi = 24.0;
    for (int it = 0; it < 11; ++it) {
        const double mid = 0.5 * (lo + hi);
        const Incline r = run(m, mode, mid, nz, kWindow[1]);
        (r.kinetic[1] > r.kinetic[0] ? hi : lo) = mid;
    }
    return 0.5 * (lo + hi);
}

/// Bed cells: those holding at least half of Phi_co (the surface cell and dust are left out).
bool in_bed(const Material& m, double Phi) { return Phi >= 0.5 * m.packing.Phi_co(FlowSettings{}.phi_hat); }

/// Every check of this program in one time-stepping mode.
void check_mode(CheckTable& table, const verify::ProgramOptions& options, const Material& m, TimeStepping mode) {
    const double mu = std::sqrt(2.0 * m.eta0 * m.eps0 / 3.0), theta_mu = std::atan(mu) * 180.0 / M_PI;
    // 1. Critical angle against atan(mu).
    const int sizes[] = {16, 32, 64};
    double crit[3];
    DataTable angles({"nz", "theta_c_deg", "atan_mu_deg"});
    for (int i = 0; i < 3; ++i) {
        crit[i] = critical_angle(m, mode, sizes[i]);
        angles.row({static_cast<double>(sizes[i]), crit[i], theta_mu});
        table.note(verify::mode_tag(mode) + "nz = " + std::to_string(sizes[i]) + ": critical angle " + verify::format(crit[i]) + " deg");
    }
    for (int i = 1; i < 3; ++i)
        table.at_least(verify::mode_tag(mode) + "critical angle -> atan(mu): order, nz = " + std::to_string(sizes[i - 1]) + " -> " + std::to_string(sizes[i]),
                       std::log2(std::fabs(crit[i - 1] - theta_mu) / std::fabs(crit[i] - theta_mu)), kOrderMin);

    // 2. Below the friction angle: the flow stops; the remaining creep is set by T_floor.
    const double T_floor = FlowSettings{}.T_floor, theta = 18.0;
    const double creep = std::tan(theta * M_PI / 180.0) * std::sqrt(T_floor) / m.eta0;  // gamma_dot at the floor
    double creep_error[2];
    DataTable below({"nz", "z", "u_x", "u_creep_law", "T"});
    for (int i = 0; i < 2; ++i) {
        const int nz = 40 << i;
        const Incline r = run(m, mode, theta, nz, kWindow[1]);
        const Incline start = run(m, mode, theta, nz, 0.0);
        double worst = 0.0;
        for (int k = 0; k < nz; ++k) {
            below.row({static_cast<double>(nz), r.z[k], r.u[k], in_bed(m, r.Phi[k]) ? creep * r.z[k] : 0.0, r.T[k]});
            if (in_bed(m, r.Phi[k])) worst = std::max(worst, std::fabs(r.u[k] - creep * r.z[k]) / (creep * kDepth));
        }
        below.blank();
        below.blank();  // gnuplot index
        creep_error[i] = worst;
        const std::string tag = verify::mode_tag(mode) + "18 deg, nz = " + std::to_string(nz) + ": ";
        table.at_most(tag + "kinetic energy at 1.5 s / at 0 s", r.kinetic[1] / start.kinetic[0], kStopFactor);
        table.near_relative(tag + "max T / T_floor (flow stopped)", r.T_max / T_floor, 1.0, 1e-9);
        table.note(tag + "max |u - tan(theta) sqrt(T_floor) z/eta0| / (gamma_dot_creep depth) = " + verify::format(worst));
    }
    table.at_least(verify::mode_tag(mode) + "18 deg: creep law error, order nz = 40 -> 80", std::log2(creep_error[0] / creep_error[1]), kOrderMin);

    // 3. Above the friction angle the layer accelerates.
    const Incline fast = run(m, mode, 26.0, 32, kWindow[1]);
    table.at_least(verify::mode_tag(mode) + "26 deg: kinetic energy at 1.5 s / at 0.5 s (growth)", fast.kinetic[1] / fast.kinetic[0], 1.0);

    // 4. At the critical angle: the profiles against the boundary-value solution.
    DataTable profiles({"nz", "z", "Phi", "Phi_bvp", "u_x", "u_bvp", "T", "T_bvp"});
    double spread[2], u_errors[2], Phi_errors[2];
    for (int i = 1; i < 3; ++i) {
        const int nz = sizes[i];
        const Incline r = run(m, mode, crit[i], nz, 2.0);
        double T_min = INFINITY, T_max = 0.0, PhiT = 0.0, mass = 0.0, bed_mass = 0.0;
        for (int k = 0; k < nz; ++k) {
            mass += r.Phi[k] * kDomain / nz;
            if (!in_bed(m, r.Phi[k])) continue;
            T_min = std::min(T_min, r.T[k]), T_max = std::max(T_max, r.T[k]);
            PhiT += r.Phi[k] * r.T[k], bed_mass += r.Phi[k];
        }
        const double T_bvp = PhiT / bed_mass, x = FlowSettings{}.phi_hat;
        // Normal momentum balance: Phi against the lithostatic profile for the simulated T(z)
        // (piecewise constant per cell) and the simulated angle, GSL odeiv2.
        const double h = kDomain / nz;
        const std::function<double(double)> T_of_z = [&](double zz) {
            return r.T[std::min(nz - 1, std::max(0, static_cast<int>(zz / h)))];
        };
        double surface = 0.0;
        const std::vector<double> Phi_bvp = verify::lithostatic_profile(
            m, T_of_z, m.packing.Phi_rcp(x), m.packing.Phi_co(x), kGravity * std::cos(crit[i] * M_PI / 180.0), mass, r.z, &surface);
        double u_err = 0.0, Phi_err = 0.0;
        const double slope = mu * std::sqrt(T_bvp) / m.eta0;
        for (int k = 0; k < nz; ++k) {
            profiles.row({static_cast<double>(nz), r.z[k], r.Phi[k], Phi_bvp[k], r.u[k], Phi_bvp[k] > 0 ? slope * r.z[k] : 0.0, r.T[k], T_bvp});
            if (!in_bed(m, r.Phi[k]) || r.z[k] + 1.5 * kDomain / nz > surface) continue;  // not the surface cell
            u_err = std::max(u_err, std::fabs(r.u[k] - slope * r.z[k]) / (slope * kDepth));
            Phi_err = std::max(Phi_err, std::fabs(r.Phi[k] - Phi_bvp[k]));
        }
        profiles.blank();
        profiles.blank();  // gnuplot index
        spread[i - 1] = (T_max - T_min) / T_max;
        u_errors[i - 1] = u_err, Phi_errors[i - 1] = Phi_err;
        const std::string tag = verify::mode_tag(mode) + "critical angle, nz = " + std::to_string(nz) + ": ";
        table.note(tag + "relative spread of T in the bed " + verify::format(spread[i - 1]) + ", max |u - u_bvp|/u_bvp(depth) " +
                   verify::format(u_err) + ", max |Phi - Phi_bvp(GSL)| " + verify::format(Phi_err));
    }
    table.at_least(verify::mode_tag(mode) + "critical angle: T spread -> 0 (uniform T), order nz = 32 -> 64", std::log2(spread[0] / spread[1]), kOrderMin);
    table.at_least(verify::mode_tag(mode) + "critical angle: u -> u_bvp, order nz = 32 -> 64", std::log2(u_errors[0] / u_errors[1]), kOrderMin);
    table.at_least(verify::mode_tag(mode) + "critical angle: Phi -> Phi_bvp, order nz = 32 -> 64", std::log2(Phi_errors[0] / Phi_errors[1]), kOrderMin);
    verify::write_data(options, "flow_incline_angles" + verify::mode_suffix(mode) + ".dat", angles);
    verify::write_data(options, "flow_incline_below" + verify::mode_suffix(mode) + ".dat", below);
    verify::write_data(options, "flow_incline_profiles" + verify::mode_suffix(mode) + ".dat", profiles);
}

}  // namespace

int main(int argc, char** argv) {
    const auto [options, m] = verify::flow_program(argc, argv);
    const double theta_mu = std::atan(std::sqrt(2.0 * m.eta0 * m.eps0 / 3.0)) * 180.0 / M_PI;
    CheckTable table("Sect. 2.1 flow (c): inclined plane (friction angle atan(mu) = " + verify::format(theta_mu) + " deg)");
    for (const TimeStepping mode : verify::kFlowModes) check_mode(table, options, m, mode);
    return table.finish();
}
