// Stress program for the flow solver (Sect. 2.1): hard cases must run without a NaN, keep
// Phi >= 0 and T >= T_floor, conserve mass, or stop with a clear one-line message when a limit of
// the model is reached (never crash).
//   1. dam break: a block at Phi = Phi_rcp - 0.01 (next to vacuum: Phi from 0 to near Phi_rcp in
//      one cell) at T = 0, collapsing under gravity in a box;
//   2. two blocks just above Phi_co colliding in mid-air at 0.5 m/s each: the collision compacts
//      them towards Phi_rcp and the pressure must stop them below it;
//   3. the same at 30 m/s: beyond what the model can take at this resolution; the run must end
//      with an InvariantError whose message names the limit (Phi_rcp or dt_min), or complete;
//   4. a drum at rest starting to turn at 1 rps in one step (10 times the tumbler's rate), with a
//      cloud of cold dust (Phi = 0.01, T = 0) above the bed;
//   5. a loose heap (Phi_co + 0.005, T = 0) sloping at 40 deg collapsing in a box: cells at its top
//      corner drain until they hold almost nothing (the semi-implicit step once kicked them to 1e5 m/s).
//
// Every case runs in both time-stepping modes; the semi-implicit mode also at the largest dt its
// bound allows and above it (6.), with the same checks.
//   6. the dam break in the semi-implicit mode at cfl = 1 and 2 on the material speed;
//   7. dust above the bed of a drum turning at 0.1 rps in the semi-implicit mode: single cells from
//      1e-4 down to just above Phi_vacuum in a haze of empty cells (just below it). The dust must not set dt (its
//      outflow is capped, assumption F11): every step after the first ones is dt_max. Before the
//      cap, a cell just above Phi_vacuum between empty ones had only closed faces and kept
//      accelerating under gravity and set ever smaller steps in a drum whose bed was at rest.
//
// Run: build/verification/verify_flow_stress [--data DIR]
#include "closures/closures.hpp"
#include "core/error.hpp"
#include "drum/bed.hpp"
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

struct Outcome {
    std::string error;  // InvariantError message, empty if the run completed
    double Phi_min = INFINITY, Phi_max = 0.0, T_min = INFINITY, mass_change = 0.0, dt_min = INFINITY;
    long steps = 0;
    bool finite = true;
};

/// Runs to t_end, tracking the extremes after every step.
Outcome run(FlowSolver& solver, double t_end) {
    Outcome o;
    const long double mass0 = verify::exact_mass(solver);
    const Grid& g = solver.grid();
    try {
        while (solver.time() < t_end) {
            solver.step(t_end);
            o.dt_min = std::min(o.dt_min, solver.time() < t_end ? solver.last_dt() : o.dt_min);
            for (std::size_t c = 0; c < g.cells(); ++c) {
                if (!g.is_inside(c)) continue;
                const double Phi = solver.Phi()[c], T = solver.T()[c];
                o.finite = o.finite && std::isfinite(Phi) && std::isfinite(T) && std::isfinite(solver.u(0)[c]) &&
                           std::isfinite(solver.u(2)[c]);
                o.Phi_min = std::min(o.Phi_min, Phi), o.Phi_max = std::max(o.Phi_max, Phi), o.T_min = std::min(o.T_min, T);
            }
        }
    } catch (const InvariantError& e) {
        o.error = e.what();
    }
    o.steps = solver.steps();
    o.mass_change = static_cast<double>((verify::exact_mass(solver) - mass0) / mass0);
    return o;
}

/// The invariants over the run, which must reach its end.
void check_clean(CheckTable& table, const std::string& tag, const Outcome& o, double T_floor) {
    table.count(tag + ": runs to the end (InvariantError count)", o.error.empty() ? 0 : 1, 0);
    if (!o.error.empty()) table.note(tag + ": " + o.error);
    table.count(tag + ": non-finite values after any step", o.finite ? 0 : 1, 0);
    table.at_least(tag + ": min Phi over the run", o.Phi_min, 0.0);
    table.at_least(tag + ": min T / T_floor over the run", o.T_min / T_floor, 1.0);
    table.at_most(tag + ": relative mass change, " + std::to_string(o.steps) + " steps", std::fabs(o.mass_change),
                  o.steps * DBL_EPSILON);
}

/// A box 4 cm x 4 cm (32 x 32) with blocks of volume fraction `dense` where block(x, z) != 0,
/// moving at block(x, z) * speed along x, at T = 0, under gravity |g| = `gravity`.
FlowSolver boxes(const Material& m, const FlowSettings& s, const std::function<int(double, double)>& block, double speed,
                 double dense, double gravity) {
    const Grid g = Grid::plane_xz(32, 32, 0.0, 0.0, 0.04, 0.04);
    Frame f;
    f.gravity = gravity;
    FlowSolver solver(g, m, s, f);
    std::vector<double> Phi(g.cells(), 0.0), ux(g.cells(), 0.0), zero(g.cells(), 0.0);
    for (int k = 0; k < 32; ++k)
        for (int i = 0; i < 32; ++i) {
            const int b = block(g.center(0, i), g.center(2, k));
            Phi[g.index(i, 0, k)] = b != 0 ? dense : 0.0;
            ux[g.index(i, 0, k)] = b * speed;
        }
    solver.set_state(Phi, {ux, zero, zero}, zero);  // T = 0: floored to T_floor
    return solver;
}

/// Every case of this program in one time-stepping mode (settings s).
void check_mode(CheckTable& table, const Material& m, const FlowSettings& s) {
    const std::string tag = verify::mode_tag(s.time_stepping);
    const double rcp = m.packing.Phi_rcp(s.phi_hat);
    // 1. Dam break: a block at Phi_rcp - 0.01 (p ~ 3 m^2/s^2) in the lower left quarter-box.
    FlowSolver dam = boxes(
        m, s, [](double x, double z) { return x < 0.02 && z < 0.03 ? 1 : 0; }, 0.0, rcp - 0.01, 9.81);
    check_clean(table, tag + "dam break, 0.3 s", run(dam, 0.3), s.T_floor);

    // 2. and 3. Two blocks at Phi_co + 0.005 colliding in mid-air (no gravity, no wall contact:
    // a bed at T_floor resting on the no-slip floor would be stopped by it at once).
    const double loose = m.packing.Phi_co(s.phi_hat) + 0.005;
    auto blocks = [](double x, double z) {
        return z > 0.01 && z < 0.03 ? (x > 0.004 && x < 0.016 ? 1 : x > 0.024 && x < 0.036 ? -1 : 0) : 0;
    };
    FlowSolver slow = boxes(m, s, blocks, 0.5, loose, 0.0);
    const Outcome o = run(slow, 0.1);
    check_clean(table, tag + "collision at 0.5 m/s, 0.1 s", o, s.T_floor);
    table.at_most(tag + "collision at 0.5 m/s: max Phi - Phi_rcp (stays below)", o.Phi_max - rcp, 0.0);
    table.at_least(tag + "collision at 0.5 m/s: max Phi - Phi_co (compacted by the collision)", o.Phi_max - loose, 0.0);
    table.note(tag + "collision at 0.5 m/s: max Phi = " + verify::format(o.Phi_max) + " (Phi_rcp = " + verify::format(rcp) +
               "), smallest dt = " + verify::format(o.dt_min) + " s");
    FlowSolver fast = boxes(m, s, blocks, 30.0, loose, 0.0);
    const Outcome v = run(fast, 0.01);
    const bool named = v.error.find("Phi_rcp") != std::string::npos || v.error.find("dt_min") != std::string::npos;
    const bool one_line = v.error.find('\n') == std::string::npos;
    table.count(tag + "collision at 30 m/s: completed, or stopped naming the limit",
                v.error.empty() || (named && one_line) ? 1 : 0, 1);
    table.note(tag + "collision at 30 m/s: " +
               (v.error.empty() ? std::string("completed, max Phi = ") + verify::format(v.Phi_max) : v.error));
    table.count(tag + "collision at 30 m/s: non-finite values before it stopped", v.finite ? 0 : 1, 0);
    table.at_least(tag + "collision at 30 m/s: min Phi before it stopped", v.Phi_min, 0.0);

    // 4. Sudden rotation at 1 rps with cold dust above the bed.
    const Grid g = drum_grid(32, 0.05);
    Frame f;
    f.omega = 2.0 * M_PI;
    FlowSolver drum(g, m, s, f);
    std::vector<double> Phi = lithostatic_bed(g, m, 0.025, f.gravity, s.T_floor, rcp, m.packing.Phi_co(s.phi_hat));
    for (int k = 0; k < 32; ++k)
        for (int i = 0; i < 32; ++i)
            if (g.center(2, k) > 0.035 && g.is_inside(g.index(i, 0, k))) Phi[g.index(i, 0, k)] = 0.01;
    const std::vector<double> zero(g.cells(), 0.0);
    drum.set_state(Phi, {zero, zero, zero}, zero);
    check_clean(table, tag + "sudden start at 1 rps with cold dust, 1 s", run(drum, 1.0), s.T_floor);

    // 5. A loose heap sloping at 40 deg (above the friction angle) collapsing against the wall:
    // the cells at its top corner drain into the falling ones below them.
    FlowSolver heap = boxes(
        m, s, [](double x, double z) { return z < 0.005 + std::tan(40.0 * M_PI / 180.0) * x ? 1 : 0; }, 0.0, loose, 9.81);
    check_clean(table, tag + "heap at 40 deg collapsing, 0.5 s", run(heap, 0.5), s.T_floor);
}

}  // namespace

/// The semi-implicit step at the largest dt its bound allows (cfl = 1 on the material speed, dt_max
/// out of the way) and above it (cfl = 2), on the dam break: what happens there.
void at_the_bound(CheckTable& table, const Material& m) {
    for (const double cfl : {1.0, 2.0}) {
        FlowSettings s;
        s.time_stepping = TimeStepping::semi_implicit;
        s.cfl = cfl;
        s.dt_max = 0.01;
        FlowSolver dam = boxes(
            m, s, [](double x, double z) { return x < 0.02 && z < 0.03 ? 1 : 0; }, 0.0, m.packing.Phi_rcp(s.phi_hat) - 0.01,
            9.81);
        const Outcome o = run(dam, 0.3);
        const std::string tag = verify::mode_tag(s.time_stepping) + "dam break at cfl = " + verify::format(cfl) +
                                (cfl > 1.0 ? " (above the bound)" : " (the bound)") + ", 0.3 s";
        check_clean(table, tag, o, s.T_floor);
        table.at_most(tag + ": max Phi - Phi_rcp (stays below)", o.Phi_max - m.packing.Phi_rcp(s.phi_hat), 0.0);
        table.note(tag + ": " + std::to_string(o.steps) + " steps, " + std::to_string(dam.counters().repeated) +
                   " repeated with half the dt (outflow or compaction bound broken), smallest dt " + verify::format(o.dt_min) +
                   " s, " + verify::format(static_cast<double>(dam.counters().newton) / dam.counters().pressure_solves) +
                   " Newton steps per solve");
    }
}

/// 7. Dust falling onto the bed of a drum turning at the tumbler's rate, in the semi-implicit mode:
/// which bounds set dt.
void dust_in_drum(CheckTable& table, const Material& m) {
    FlowSettings s;
    s.time_stepping = TimeStepping::semi_implicit;
    const Grid g = drum_grid(32, 0.05);
    Frame f;
    f.omega = 0.2 * M_PI;
    FlowSolver drum(g, m, s, f);
    std::vector<double> Phi =
        lithostatic_bed(g, m, 0.0, f.gravity, s.T_floor, m.packing.Phi_rcp(s.phi_hat), m.packing.Phi_co(s.phi_hat));
    // Above the bed: a haze just below Phi_vacuum (empty cells) and in it single dust cells on every
    // fourth cell of every fourth row, from 1e-4 down to just above Phi_vacuum.
    int n = 0;
    for (int k = 20; k < 32; ++k)
        for (int i = 0; i < 32; ++i) {
            const std::size_t c = g.index(i, 0, k);
            if (!g.is_inside(c)) continue;
            const bool dust = k % 4 == 0 && i % 4 == 0;
            Phi[c] = dust ? 1e-4 * std::pow(1.01 * s.Phi_vacuum / 1e-4, (n++ % 16) / 15.0) : 0.5 * s.Phi_vacuum;
        }
    const std::vector<double> zero(g.cells(), 0.0);
    drum.set_state(Phi, {zero, zero, zero}, zero);
    const Outcome o = run(drum, 1.0);
    const std::string tag = verify::mode_tag(s.time_stepping) + "dust above the bed of a drum at 0.1 rps, 1 s";
    check_clean(table, tag, o, s.T_floor);
    const auto& by = drum.counters().set_by;
    // The bed turns with the drum (at rest in its frame) and the dust holds < 1e-4: no cell with
    // material moves fast enough for the material-speed CFL (0.5 h/dt_max = 1.6 m/s) or its outflow
    // bound, and no step is repeated. Only the first step is set by the CFL condition: it counts the
    // sound speed (flow/time_step.hpp). The compaction bound (half the gap to Phi_rcp) is the bed's
    // own, which dust 1e-4 below nothing can reach: reported, not counted (the GSL bed settles onto
    // the discrete one in its first steps).
    const long by_material =
        by[static_cast<int>(StepBound::cfl)] + by[static_cast<int>(StepBound::outflow)] + by[static_cast<int>(StepBound::halved)];
    table.note(tag + ": steps set by the CFL " + std::to_string(by[static_cast<int>(StepBound::cfl)]) + ", outflow " +
               std::to_string(by[static_cast<int>(StepBound::outflow)]) + ", compaction " +
               std::to_string(by[static_cast<int>(StepBound::compaction)]) + ", halved " +
               std::to_string(by[static_cast<int>(StepBound::halved)]));
    table.at_most(tag + ": steps whose dt the CFL, outflow or a repeat set (of " + std::to_string(o.steps) + ")",
                  static_cast<double>(by_material), 1.0);
}

int main(int argc, char** argv) {
    const Material m = verify::flow_program(argc, argv).material;
    CheckTable table("Sect. 2.1 flow: stress cases (sharp interfaces, T = 0, Phi -> Phi_rcp, sudden rotation)");
    for (const TimeStepping mode : verify::kFlowModes) {
        FlowSettings s;
        s.time_stepping = mode;
        check_mode(table, m, s);
    }
    at_the_bound(table, m);
    dust_in_drum(table, m);
    return table.finish();
}
