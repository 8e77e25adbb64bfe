#include "harness/incline_flow.hpp"

#include "closures/closures.hpp"
#include "drum/bed.hpp"
#include "flow/flow_solver.hpp"
#include "harness/flow_reference.hpp"

#include <algorithm>
#include <cmath>
#include <functional>

namespace granseg::verify {

namespace {

constexpr double kStart = 20.0;  // 1/s: the initial linear shear, with T from eq. (45)

}  // namespace

InclineRun run_incline(const Material& m, const FlowSettings& settings, double theta_deg, int nz, double t_end) {
    const double theta = theta_deg * M_PI / 180.0;
    Grid g = Grid::column(nz, kInclineDomain);
    g.periodic[0] = true;
    Frame f;
    f.gravity = kInclineGravity;
    f.tilt = theta;
    FlowSolver solver(g, m, settings, f);
    const double T0 = steady_shear_temperature(m, kStart);
    const std::vector<double> Phi = lithostatic_bed(g, m, kInclineDepth, kInclineGravity * std::cos(theta), T0,
                                                    m.packing.Phi_rcp(settings.phi_hat), m.packing.Phi_co(settings.phi_hat));
    std::vector<double> ux(nz, 0.0), zero(nz, 0.0);
    for (int k = 0; k < nz; ++k) ux[k] = Phi[k] > 0.0 ? kStart * g.center(2, k) : 0.0;
    solver.set_state(Phi, {ux, zero, zero}, std::vector<double>(nz, T0));
    auto kinetic = [&] {
        double e = 0.0;
        for (int k = 0; k < nz; ++k) e += 0.5 * solver.Phi()[k] * solver.u(0)[k] * solver.u(0)[k] * g.h[2];
        return e;
    };
    InclineRun r;
    auto advance = [&](double t) {
        add_timed(r.time, [&] {
            for (; solver.time() < t; ++r.steps) solver.step(t);
        });
    };
    for (int w = 0; w < 2; ++w) {
        advance(std::min(kInclineWindow[w], t_end));
        r.kinetic[w] = kinetic();
    }
    advance(t_end);
    r.work = solver.counters();
    for (int k = 0; k < nz; ++k) {
        r.z.push_back(g.center(2, k)), r.Phi.push_back(solver.Phi()[k]);
        r.u.push_back(solver.u(0)[k]), r.T.push_back(solver.T()[k]);
        r.T_max = std::max(r.T_max, solver.T()[k]);
    }
    return r;
}

double critical_angle(const Material& m, const FlowSettings& settings, int nz, Timing* time) {
    double lo = 20.0, hi = 24.0;
    if (time) *time = Timing{};
    for (int it = 0; it < 11; ++it) {
        const double mid = 0.5 * (lo + hi);
        const InclineRun r = run_incline(m, settings, mid, nz, kInclineWindow[1]);
        (r.kinetic[1] > r.kinetic[0] ? hi : lo) = mid;
        if (time) time->wall += r.time.wall, time->cpu += r.time.cpu;
    }
    return 0.5 * (lo + hi);
}

bool in_bed(const Material& m, double Phi) { return Phi >= 0.5 * m.packing.Phi_co(FlowSettings{}.phi_hat); }

InclineProfileErrors incline_profile_errors(const Material& m, const InclineRun& r, double theta_deg, DataTable* rows) {
    const int nz = static_cast<int>(r.z.size());
    const double mu = std::sqrt(2.0 * m.eta0 * m.eps0 / 3.0), h = kInclineDomain / nz;
    double T_min = INFINITY, T_max = 0.0, PhiT = 0.0, mass = 0.0, bed_mass = 0.0;
    for (int k = 0; k < nz; ++k) {
        mass += r.Phi[k] * h;
        if (!in_bed(m, r.Phi[k])) continue;
        T_min = std::min(T_min, r.T[k]), T_max = std::max(T_max, r.T[k]);
        PhiT += r.Phi[k] * r.T[k], bed_mass += r.Phi[k];
    }
    const double T_bvp = PhiT / bed_mass, x = FlowSettings{}.phi_hat;
    // Normal momentum balance: Phi against the lithostatic profile for the simulated T(z)
    // (piecewise constant per cell) and the simulated angle, GSL odeiv2.
    const std::function<double(double)> T_of_z = [&](double zz) {
        return r.T[std::min(nz - 1, std::max(0, static_cast<int>(zz / h)))];
    };
    double surface = 0.0;
    const std::vector<double> Phi_bvp =
        lithostatic_profile(m, T_of_z, m.packing.Phi_rcp(x), m.packing.Phi_co(x),
                            kInclineGravity * std::cos(theta_deg * M_PI / 180.0), mass, r.z, &surface);
    InclineProfileErrors e;
    e.T_spread = (T_max - T_min) / T_max;
    const double slope = mu * std::sqrt(T_bvp) / m.eta0;
    for (int k = 0; k < nz; ++k) {
        if (rows)
            rows->row({{"nz", static_cast<double>(nz)},
                       {"z", r.z[k]},
                       {"Phi", r.Phi[k]},
                       {"Phi_bvp", Phi_bvp[k]},
                       {"u_x", r.u[k]},
                       {"u_bvp", Phi_bvp[k] > 0 ? slope * r.z[k] : 0.0},
                       {"T", r.T[k]},
                       {"T_bvp", T_bvp}});
        if (!in_bed(m, r.Phi[k]) || r.z[k] + 1.5 * h > surface) continue;  // not the surface cell
        e.u = std::max(e.u, std::fabs(r.u[k] - slope * r.z[k]) / (slope * kInclineDepth));
        e.Phi = std::max(e.Phi, std::fabs(r.Phi[k] - Phi_bvp[k]));
    }
    if (rows) rows->blank(), rows->blank();  // gnuplot index
    return e;
}

}  // namespace granseg::verify
