// Verification (a) of the flow solver (Sect. 2.1, eqs. 8, 9, 14): a bed at rest under gravity.
//
// A column (and a 2-D box with side walls) starts with a uniform Phi, not in balance, at rest,
// and settles; so do loose beds (Phi below Phi_co, where the yield pressure p_y vanishes and
// nothing carries a load): columns anywhere in [Phi_co - 0.05, Phi_co), a loose layer on a dense
// bed, and a loose box, which must compact to the same balance (docs/flow_solver.md Sect. 2, forces,
// assumption F7). Checked against independent expectations:
//   - Phi(z) converges to the lithostatic balance dp/dz = -Phi |g| (p from eqs. 15-19), integrated
//     by GSL odeiv2 for the same mass (harness/flow_reference.cpp), with the error falling at the
//     second order the trapezoidal discrete balance of the hydrostatic reconstruction implies;
//   - the momentum decays to round-off level (the scheme is well balanced);
//   - the mass is unchanged to round-off (a conservation law; no flux through walls);
//   - in the box, Phi does not depend on x and the horizontal momentum stays at round-off.
// Every check runs in both time-stepping modes (explicit, semi-implicit) with the same tolerance.
// Writes flow_rest_profiles.dat and flow_rest_history.dat (explicit mode; the semi-implicit
// mode adds _semi_implicit) for figures/fig_flow_rest.gp.
//
// Run: build/verification/verify_flow_rest [--data DIR]   (a few seconds)
#include "closures/closures.hpp"
#include "flow/faces/semi_implicit_faces.hpp"
#include "flow/flow_solver.hpp"
#include "harness/check_table.hpp"
#include "harness/flow_reference.hpp"
#include "harness/program.hpp"

#include <cfloat>
#include <cmath>
#include <cstdio>
#include <functional>

using namespace granseg;
using granseg::verify::CheckTable;

namespace {

constexpr double kHeight = 0.06, kBedTop = 0.04, kGravity = 9.81;
// The settling creep relaxes on the time eta/(Phi c^2) with eta ~ eta0 p/sqrt(T_floor)
// (docs/flow_solver.md); with T_floor = 1e-8 m^2/s^2 that is below 0.1 s, so 12 s take the
// momentum from its initial 5e-3 m/s to round-off. T_floor enters the balance only through
// p_k = Phi g T (a relative 1e-8).
constexpr double kTFloor = 1e-8, kSettle = 12.0;
// A state already in balance is kept for 2 s (some 10^4 steps). The columns and the box run with
// steps of at most 1 ms and the pressure solved to 1e-6 of the step's mass change, so that the
// balance holds to kRowRoundOff: at rest the predicted mass change is the rounding left where
// gravity and the pressure gradient cancel (it grows as dt^2), and the Newton steps taken on it
// each cost tens of ulps of p in their round trip through the equation of state. The defaults
// (2 ms, 1e-2) are held to their own level, kDefaultRowRoundOff, by a column and a box settled and
// kept at them (semi-implicit mode).
constexpr double kBalanced = 2.0;
/// The largest step and the pressure tolerance of a settling run.
struct Stepping {
    double dt_max, pressure_tolerance;
};
const Stepping kBalancedStepping{1e-3, 1e-6};
const Stepping kDefaultStepping{FlowSettings{}.dt_max, FlowSettings{}.pressure_tolerance};
// Round-off level of the momentum: 1e-13 of the settling scale Phi sqrt(|g| H) (0.37 m/s), i.e.
// a few hundred units of double-precision resolution, room for the rounding every face adds to
// the discrete balance each step.
constexpr double kMomentumRoundOff = 1e-13 * 0.6 * 0.6262;  // 0.6262 = sqrt(9.81 * 0.04)
// The discrete balance is the trapezoidal rule p_k - p_(k+1) = (Phi_k + Phi_(k+1)) |g| h/2 (flow/faces/hllc.hpp),
// second order: successive halvings of h must reduce the error by 2^kOrderMin at least
// (1.7 leaves room for the pre-asymptotic coarsest grid).
constexpr double kOrderMin = 1.7;
// A balanced state is a fixed point up to the rounding of each update: Phi may move by a few
// hundred units of 2^-52 at most.
constexpr double kRowRoundOff = 256 * DBL_EPSILON;
// At the default step (2 ms) the predicted mass change at rest, the rounding left where gravity
// and the pressure gradient cancel, is 4 times that at 1 ms (it grows as dt^2), and so is what the
// Newton steps taken on it move: 4 kRowRoundOff. (The pressure tolerance plays no part: at rest
// its share of the mass change is far below the solve's round-off floor.)
constexpr double kDefaultRowRoundOff = 4 * kRowRoundOff;
// The finest error must resolve the lithostatic compaction (Phi_bottom - Phi_co ~ 0.014) to 0.1%.
constexpr double kProfileTol = 1e-3 * 0.014;

// Loose starts settle over a longer way (a compaction of up to 8 %): checked at nz = 30, where the
// second-order balance allows 4 times the error of nz = 60 (kProfileTol).
constexpr int kLooseCells = 30;
constexpr double kLooseProfileTol = 4 * kProfileTol;

/// Initial Phi of a bed as a function of the height z (m) and the bed's Phi_co.
using Profile = std::function<double(double z, double Phi_co)>;

struct Run {
    std::vector<double> z, Phi;  // column: per cell; box: mean over x
    double spread = 0.0;         // box: largest difference of Phi across a row
    double momentum = 0.0, mass_change = 0.0, steps = 0.0;
};

/// A bed at rest up to kBedTop (cell averages of `profile`, taken at the cell centre), not in balance.
std::vector<double> bed(int nz, double Phi_co, const Profile& profile) {
    const double h = kHeight / nz;
    std::vector<double> Phi(nz);
    for (int k = 0; k < nz; ++k)
        Phi[k] = profile((k + 0.5) * h, Phi_co) * std::max(0.0, std::min((k + 1) * h, kBedTop) - k * h) / h;
    return Phi;
}

/// Settles the bed Phi (one value per row) in a box of nx columns for t_end seconds, steps of at
/// most stepping.dt_max and the pressure solved to stepping.pressure_tolerance.
Run settle(const Material& m, TimeStepping mode, int nx, const std::vector<double>& initial, double t_end, DataTable* history,
           const Stepping& stepping) {
    const int nz = static_cast<int>(initial.size());
    Grid g = Grid::plane_xz(nx, nz, 0.0, 0.0, kHeight / nz * nx, kHeight);
    FlowSettings s;
    s.time_stepping = mode;
    s.T_floor = kTFloor;
    s.dt_max = stepping.dt_max, s.pressure_tolerance = stepping.pressure_tolerance;
    FlowSolver solver(g, m, s, Frame{});
    std::vector<double> Phi(g.cells()), T(g.cells(), kTFloor), zero(g.cells(), 0.0);
    for (int k = 0; k < nz; ++k)
        for (int i = 0; i < nx; ++i) Phi[g.index(i, 0, k)] = initial[k];
    solver.set_state(Phi, {zero, zero, zero}, T);
    const long double mass0 = verify::exact_mass(solver);
    double next = 0.0;
    Run r;
    while (solver.time() < t_end) {
        solver.step(t_end);
        if (history && solver.time() >= next) {
            history->row({{"t", solver.time()}, {"max_momentum", verify::max_momentum(solver)}});
            next += 0.05;
        }
    }
    for (int k = 0; k < nz; ++k) {
        double sum = 0.0, lo = 1.0, hi = 0.0;
        for (int i = 0; i < nx; ++i) {
            const double v = solver.Phi()[g.index(i, 0, k)];
            sum += v, lo = std::min(lo, v), hi = std::max(hi, v);
        }
        r.z.push_back(g.center(2, k));
        r.Phi.push_back(sum / nx);
        r.spread = std::max(r.spread, hi - lo);
    }
    r.momentum = verify::max_momentum(solver);
    r.mass_change = static_cast<double>((verify::exact_mass(solver) - mass0) / mass0);
    r.steps = static_cast<double>(solver.steps());
    return r;
}

/// Largest |Phi - Phi_lithostatic| below the cell holding the surface (GSL reference of equal mass).
double profile_error(const Material& m, const Run& r, DataTable& profiles, int nz) {
    const double x = FlowSettings{}.phi_hat, h = kHeight / nz;
    double mass = 0.0, surface = 0.0, worst = 0.0;
    for (double v : r.Phi) mass += v * h;
    const std::vector<double> ref =
        verify::lithostatic_profile(m, kTFloor, m.packing.Phi_rcp(x), m.packing.Phi_co(x), kGravity, mass, r.z, &surface);
    for (std::size_t k = 0; k < r.z.size(); ++k) {
        profiles.row({{"nz", static_cast<double>(nz)}, {"z", r.z[k]}, {"Phi", r.Phi[k]}, {"Phi_reference", ref[k]}});
        if (r.z[k] + 1.5 * h < surface) worst = std::max(worst, std::fabs(r.Phi[k] - ref[k]));
    }
    profiles.blank();
    profiles.blank();
    return worst;
}

/// The round-off bound of a sum updated `steps` times: each update rounds each cell once.
double mass_bound(double steps) { return steps * DBL_EPSILON; }

/// Every check of this program in one time-stepping mode.
/// The largest |Phi - Phi_start| over the rows of the bed (Phi_start at least kDust Phi_co). The
/// dust above the surface is no balanced state: nothing carries it, it drains onto the bed at a
/// pace proportional to what it holds, so an absolute bound on its change would measure how much
/// dust the settling left there; its largest relative change is a note.
double bed_change(CheckTable& table, const std::string& tag, const std::vector<double>& Phi, const std::vector<double>& Phi_start,
                  double Phi_co) {
    double bed = 0.0, dust = 0.0;
    for (std::size_t k = 0; k < Phi_start.size(); ++k) {
        const double change = std::fabs(Phi[k] - Phi_start[k]);
        if (!is_dust(Phi_start[k], Phi_co))
            bed = std::max(bed, change);
        else if (Phi_start[k] > 0.0)
            dust = std::max(dust, change / Phi_start[k]);
    }
    table.note(tag + "dust above the surface: largest relative change " + verify::format(dust));
    return bed;
}

void check_mode(CheckTable& table, const verify::ProgramOptions& options, const Material& m, TimeStepping mode) {
    DataTable history;
    DataTable profiles;
    std::vector<double> errors, column30;
    const int sizes[] = {15, 30, 60};
    const double Phi_co = m.packing.Phi_co(FlowSettings{}.phi_hat);
    // A uniform bed above Phi_co: Phi = Phi_co + 0.004 (p ~ 0.05 m^2/s^2).
    const Profile dense = [](double, double co) { return co + 0.004; };
    for (int nz : sizes) {
        const Run r = settle(m, mode, 1, bed(nz, Phi_co, dense), kSettle, nz == 60 ? &history : nullptr, kBalancedStepping);
        if (nz == 30) column30 = r.Phi;
        errors.push_back(profile_error(m, r, profiles, nz));
        const std::string tag = verify::mode_tag(mode) + "column nz = " + std::to_string(nz) + ": ";
        table.note(tag + "max |Phi - Phi_lithostatic(GSL)| below the surface cell = " + verify::format(errors.back()));
        table.at_most(tag + "max |Phi u| after 12 s (m/s)", r.momentum, kMomentumRoundOff);
        table.at_most(tag + "relative mass change, " + verify::format(r.steps) + " steps", std::fabs(r.mass_change),
                      mass_bound(r.steps));
    }
    for (std::size_t i = 1; i < errors.size(); ++i)
        table.at_least(
            verify::mode_tag(mode) + "observed order, nz = " + std::to_string(sizes[i - 1]) + " -> " + std::to_string(sizes[i]),
            std::log2(errors[i - 1] / errors[i]), kOrderMin);
    table.at_most(verify::mode_tag(mode) + "column nz = 60: max |Phi - Phi_lithostatic|", errors.back(), kProfileTol);

    // A box with side walls, started from the settled nz = 30 column in every column: the walls
    // and the x direction must keep a balanced state at rest (well balanced at walls). (Settling
    // from a uniform state, the no-slip walls leave the partly filled surface row slightly uneven,
    // and below the yield stress the model bed is a liquid of viscosity eta0 p/sqrt(T_floor) that
    // levels only over many seconds; the columns above test the approach to balance.)
    const Run box = settle(m, mode, 6, column30, kBalanced, nullptr, kBalancedStepping);
    const double change = bed_change(table, verify::mode_tag(mode) + "box 6 x 30 (walls): ", box.Phi, column30, Phi_co);
    table.at_most(verify::mode_tag(mode) + "box 6 x 30 (walls): max |Phi - settled column| in the bed after 2 s", change,
                  kRowRoundOff);
    table.at_most(verify::mode_tag(mode) + "box 6 x 30 (walls): spread of Phi across rows", box.spread, kRowRoundOff);
    table.at_most(verify::mode_tag(mode) + "box 6 x 30 (walls): max |Phi u| after 2 s (m/s)", box.momentum, kMomentumRoundOff);
    table.at_most(verify::mode_tag(mode) + "box 6 x 30 (walls): relative mass change", std::fabs(box.mass_change),
                  mass_bound(box.steps));
    if (mode == TimeStepping::semi_implicit) {  // the explicit step's dt is set by the sound speed
        const Run column = settle(m, mode, 1, bed(30, Phi_co, dense), kSettle, nullptr, kDefaultStepping);
        const Run kept = settle(m, mode, 6, column.Phi, kBalanced, nullptr, kDefaultStepping);
        const std::string tag = verify::mode_tag(mode) + "default stepping: box 6 x 30 (walls): ";
        const double moved = bed_change(table, tag, kept.Phi, column.Phi, Phi_co);
        table.at_most(tag + "max |Phi - settled column| in the bed after 2 s", moved, kDefaultRowRoundOff);
        table.at_most(tag + "spread of Phi across rows", kept.spread, kDefaultRowRoundOff);
        table.at_most(tag + "max |Phi u| after 2 s (m/s)", kept.momentum, kMomentumRoundOff);
    }

    // Loose beds (Phi < Phi_co, no yield pressure) must compact to the same lithostatic balance.
    // The starts span [Phi_co - 0.05, Phi_co); the box has no-slip side walls.
    const struct {
        const char* name;
        int nx;
        Profile profile;
    } loose[] = {
        {"loose column, Phi = Phi_co - 0.05", 1, [](double, double co) { return co - 0.05; }},
        {"loose column, Phi_co - 0.005 (bottom) .. Phi_co - 0.05 (top)", 1,
         [](double z, double co) { return co - 0.005 - 0.045 * z / kBedTop; }},
        {"loose layer Phi_co - 0.03 on a dense bed", 1,
         [](double z, double co) { return z < 0.5 * kBedTop ? co + 0.004 : co - 0.03; }},
        {"loose box 6 x 30 (walls), Phi = Phi_co - 0.02", 6, [](double, double co) { return co - 0.02; }},
    };
    for (const auto& start : loose) {
        const Run r = settle(m, mode, start.nx, bed(kLooseCells, Phi_co, start.profile), kSettle, nullptr, kDefaultStepping);
        const std::string tag = verify::mode_tag(mode) + start.name + ": ";
        table.at_most(tag + "max |Phi - Phi_lithostatic(GSL)|" + (start.nx > 1 ? " (row means)" : ""),
                      profile_error(m, r, profiles, kLooseCells), kLooseProfileTol);
        // In the box the no-slip walls leave the surface row uneven, and the bed below yield levels
        // as a liquid of viscosity eta0 p/sqrt(T_floor) over tens of seconds (see the balanced box
        // above): its momentum is a creep, not round-off, and is only reported.
        if (start.nx > 1)
            table.note(tag + "levelling creep after 12 s: max |Phi u| = " + verify::format(r.momentum) +
                       " m/s, spread of Phi across a row " + verify::format(r.spread));
        else
            table.at_most(tag + "max |Phi u| after 12 s (m/s)", r.momentum, kMomentumRoundOff);
        table.at_most(tag + "relative mass change", std::fabs(r.mass_change), mass_bound(r.steps));
    }
    verify::write_data(options, "flow_rest_profiles" + verify::mode_suffix(mode) + ".dat", profiles);
    verify::write_data(options, "flow_rest_history" + verify::mode_suffix(mode) + ".dat", history);
}

}  // namespace

int main(int argc, char** argv) {
    const verify::FlowProgram program = verify::flow_program(argc, argv);
    return verify::run_flow_modes(program, "Sect. 2.1 flow (a): bed at rest under gravity", check_mode);
}
