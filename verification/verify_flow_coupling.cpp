// The flow solver's hand-over to the segregation solver (coupling contract, docs/flow_solver.md):
//   1. in a turning drum (thin 3-D slab with periodic ends, gravity, a phi field present), after
//      every step: Phi_new = Phi_old - dt sum_axis (M[upper] - M[lower])/h_axis in every inside
//      cell to round-off; M = 0 exactly on wall faces; the periodic end faces carry equal M; the
//      outflow condition dt sum_outflow M/h <= Phi_old holds (so donor-cell transport of phi with M
//      keeps phi_hat in [0, 1]); the handed-over fields are finite;
//   2. Phi_rcp and Phi_co follow phi_hat = phi/Phi: a column whose phi field holds phi_hat = 0.2
//      settles to the lithostatic profile of the phi_hat = 0.2 packing limits (GSL odeiv2), not to
//      the one of the default mixture.
//
// Every check runs in both time-stepping modes (explicit, semi-implicit) with the same tolerance.
//
// Run: build/verification/verify_flow_coupling [--data DIR]   (a few seconds)
#include "closures/closures.hpp"
#include "drum/bed.hpp"
#include "flow/flow_solver.hpp"
#include "harness/check_table.hpp"
#include "harness/flow_reference.hpp"
#include "harness/program.hpp"

#include <cfloat>
#include <cmath>

using namespace granseg;
using granseg::verify::CheckTable;

namespace {

// The identity holds to the rounding of the update's few operations: 8 units of 2^-52 of the
// magnitudes involved, Phi_old + dt sum |M|/h.
constexpr double kIdentityUlps = 8 * DBL_EPSILON;

void drum_handover(CheckTable& table, const Material& m, TimeStepping mode) {
    const int n = 24, ny = 2;
    const Grid g = drum_grid(n, 0.05, ny, 2 * 0.1 / n);
    FlowSettings s;
    s.time_stepping = mode;
    Frame f;
    f.omega = 2.0 * M_PI * 0.1;
    FlowSolver solver(g, m, s, f);
    const double x = 0.3;
    std::vector<double> Phi = lithostatic_bed(g, m, 0.025, f.gravity, s.T_floor, m.packing.Phi_rcp(x), m.packing.Phi_co(x));
    solver.set_phi_hat(std::vector<double>(g.cells(), x));
    const std::vector<double> zero(g.cells(), 0.0), T(g.cells(), s.T_floor);
    solver.set_state(Phi, {zero, zero, zero}, T);
    double identity = 0.0, wall = 0.0, periodic = 0.0, outflow = 0.0;
    long bad_fields = 0;
    while (solver.time() < 3.0) {
        const double dt = solver.step(3.0);
        const std::vector<double>& before = solver.Phi_before();
        for (int k = 0; k < n; ++k)
            for (int j = 0; j < ny; ++j)
                for (int i = 0; i < n; ++i) {
                    const std::size_t c = g.index(i, j, k);
                    if (!g.is_inside(c)) continue;
                    double div = 0.0, size = before[c], out = 0.0;
                    for (int a = 0; a < 3; ++a) {
                        if (!solver.active(a)) continue;
                        const std::vector<double>& M = solver.mass_flux(a);
                        const std::size_t lo = g.face_index(a, i, j, k), hi = lo + g.face_stride(a);
                        div += (M[hi] - M[lo]) / g.h[a];
                        size += dt * (std::fabs(M[hi]) + std::fabs(M[lo])) / g.h[a];
                        out += dt * (std::max(0.0, M[hi]) + std::max(0.0, -M[lo])) / g.h[a];
                        // Wall faces: a neighbour along a outside the drum or the domain boundary.
                        std::array<int, 3> nb_lo{i, j, k}, nb_hi{i, j, k};
                        nb_lo[a] -= 1, nb_hi[a] += 1;
                        auto is_wall = [&](const std::array<int, 3>& q) {
                            if (g.periodic[a]) return false;
                            if (q[a] < 0 || q[a] >= g.n[a]) return true;
                            return !g.is_inside(g.index(q[0], q[1], q[2]));
                        };
                        if (is_wall(nb_lo)) wall = std::max(wall, std::fabs(M[lo]));
                        if (is_wall(nb_hi)) wall = std::max(wall, std::fabs(M[hi]));
                    }
                    identity = std::max(identity, std::fabs(solver.Phi()[c] - (before[c] - dt * div)) / size);
                    outflow = std::max(outflow, out - before[c]);
                    for (int b = 0; b < 3; ++b)
                        for (int a = 0; a < 3; ++a)
                            if (!std::isfinite(solver.velocity_gradient(b, a)[c])) ++bad_fields;
                    if (!std::isfinite(solver.T()[c]) || !std::isfinite(solver.u(0)[c])) ++bad_fields;
                }
        // Periodic ends along y: face layer 0 and layer ny are the same face.
        const std::vector<double>& My = solver.mass_flux(1);
        for (int k = 0; k < n; ++k)
            for (int i = 0; i < n; ++i)
                periodic = std::max(periodic, std::fabs(My[g.face_index(1, i, 0, k)] - My[g.face_index(1, i, ny, k)]));
    }
    const std::string tag = verify::mode_tag(mode);
    table.note(tag + "drum 24 x 2 x 24, phi_hat = 0.3, 3 s: " + std::to_string(solver.steps()) + " steps checked");
    table.at_most(tag + "identity: max |Phi_new - (Phi_old - dt div M)| / (Phi_old + dt sum|M|/h)", identity, kIdentityUlps);
    table.near(tag + "M on wall faces, max |M|", wall, 0.0, 0.0);
    table.near(tag + "periodic end faces: max |M(layer 0) - M(layer ny)|", periodic, 0.0, 0.0);
    table.at_most(tag + "outflow condition: max (dt sum_outflow M/h - Phi_old)", outflow, 0.0);
    table.count(tag + "non-finite T, u or velocity gradient handed over", bad_fields, 0);
}

void packing_follows_phi(CheckTable& table, const Material& m, TimeStepping mode) {
    const int nz = 30;
    const double height = 0.06, x = 0.2;
    Grid g = Grid::column(nz, height);
    FlowSettings s;
    s.time_stepping = mode;
    s.T_floor = 1e-8;  // fast settling, as in verify_flow_rest
    FlowSolver solver(g, m, s, Frame{});
    std::vector<double> Phi(nz, 0.0), zero(nz, 0.0), T(nz, s.T_floor);
    const double Phi0 = m.packing.Phi_co(x) + 0.004;
    for (int k = 0; k < nz; ++k) Phi[k] = g.center(2, k) < 0.04 ? Phi0 : 0.0;
    solver.set_phi_hat(std::vector<double>(nz, x));  // settings.phi_hat stays 0.5: the field must win
    solver.set_state(Phi, {zero, zero, zero}, T);
    while (solver.time() < 8.0) solver.step(8.0);
    std::vector<double> z;
    double mass = 0.0;
    for (int k = 0; k < nz; ++k) z.push_back(g.center(2, k)), mass += solver.Phi()[k] * g.h[2];
    double surface = 0.0, other_surface = 0.0;
    const auto own =
        verify::lithostatic_profile(m, s.T_floor, m.packing.Phi_rcp(x), m.packing.Phi_co(x), 9.81, mass, z, &surface);
    const auto other = verify::lithostatic_profile(m, s.T_floor, m.packing.Phi_rcp(s.phi_hat), m.packing.Phi_co(s.phi_hat), 9.81,
                                                   mass, z, &other_surface);
    double err_own = 0.0, separation = 0.0;
    for (int k = 0; k < nz; ++k) {
        if (z[k] + 1.5 * g.h[2] > std::min(surface, other_surface)) continue;
        err_own = std::max(err_own, std::fabs(solver.Phi()[k] - own[k]));
        separation = std::max(separation, std::fabs(own[k] - other[k]));
    }
    // A solver that ignored phi would settle to the default mixture's profile, `separation` away;
    // at this resolution the discretisation error is ~1.5e-7 (verify_flow_rest), four orders below.
    table.note(verify::mode_tag(mode) + "lithostatic profiles for phi_hat = 0.2 and 0.5 (GSL) differ by up to " +
               verify::format(separation));
    table.at_most(verify::mode_tag(mode) + "column with phi_hat = 0.2: max |Phi - Phi_lithostatic(0.2)| / that",
                  err_own / separation, 1e-3);
}

}  // namespace

int main(int argc, char** argv) {
    const Material m = verify::flow_program(argc, argv).material;
    CheckTable table("Sect. 2.1 flow: hand-over to the segregation solver (coupling contract)");
    for (const TimeStepping mode : verify::kFlowModes) {
        drum_handover(table, m, mode);
        packing_follows_phi(table, m, mode);
    }
    return table.finish();
}
