// Verification of the coupled drum's time stepping (docs/sect4.2_tumbler.md, "Time step"): the
// whole time error at the default step, flow and coupling together, and the part the coupling
// adds, on a drum small enough for make verify. The drum of Sect. 4.2 on kCells cells per diameter
// for kEnd seconds, with S0 = kS (five times the paper's) so that the pattern, and with it the
// packing feedback, develops within those seconds; every run goes through the scene's reader and
// time loop.
//   Runs: packing feedback on and off, each at the coupled drum's default dt_max (kCoupledDtMax)
//   and at half of it. On this grid two acoustic times h/c (kCoupledAcousticCourantMax) are longer
//   than dt_max, so dt_max sets the default step (on the paper's drum finer than about 40 cells
//   the acoustic bound does: bench_time_step measures that step).
//   The whole time error: for a scheme of order p the error of q at dt is
//   (q(dt) - q(dt/2)) / (1 - 2^-p); with p = 1, the coupled step's formal order (Lie splitting;
//   the shares converge at about second order here and in bench_time_step), the estimate is
//   2 |q(dt) - q(dt/2)|, an upper bound for any p >= 1. It is checked on the full model (feedback
//   on) against the accuracy asked of the default step (kAngleTol, kShareTol).
//   The coupling's part: without packing feedback the flow does not see phi
//   (tests/coupled/coupled_tumbler.cpp), so the difference between the two parts' changes,
//   Delta = (q_fb(dt) - q_fb(dt/2)) - (q_nf(dt) - q_nf(dt/2)), is what the coupling adds, 2 |Delta|
//   at most.
// Checks, on the angle of repose (mean over t >= kEnd/2), the share of small particles in the
// drum's own core (r < d - layer) and within 0.05 D of the axis (both at kEnd).
// Writes time_step_small.dat (the four runs) to DATA.
//
// Run: build/verification/verify_tumbler_time_step [--data DIR]   (about half a minute)
#include "direction/segregation_velocity.hpp"
#include "harness/check_table.hpp"
#include "harness/named_table.hpp"
#include "harness/program.hpp"
#include "run/output.hpp"
#include "run/scene_file.hpp"
#include "scenes/tumbler.hpp"

#include <cmath>
#include <string>
#include <vector>

using namespace granseg;
using granseg::verify::CheckTable;

namespace {

constexpr int kCells = 26;                // cells per diameter: the smallest tumbler grid (C4) but one
constexpr double kEnd = 5.0;              // s
constexpr double kS = 5.0;                // s^2/m, S0 of eq. (46)
constexpr double kDtMax = kCoupledDtMax;  // the coupled drum's default step

// Tolerances: the accuracy asked of the default step on the paper's drum (bench_time_step), 0.2 deg
// of the dt -> 0 limit for the angle and 0.01 for the shares, here on a drum that segregates five
// times as fast, whose splitting error is the larger. The flow solver's step (2 ms) fails the shares'
// bound here (core 0.019, axis 0.027 by this estimate; docs/history.md); a segregation sub-step
// that covers its own stretch of time instead of the flow's step (the multi-rate split the drum
// once used) fails all three.
constexpr double kAngleTol = 0.2;   // deg
constexpr double kShareTol = 0.01;  // of the small-particle share

struct Quantities {
    double angle, core, axis;
};

/// The drum with packing feedback on or off at dt_max = dt, run through the scene's code path.
Quantities run_drum(bool feedback, double dt) {
    const std::string text = "[scene]\nkind = \"tumbler\"\n[drum]\ncells_per_diameter = " + std::to_string(kCells) +
                             "\n[run]\nt_end = " + verify::format(kEnd) + "\nangle_from = " + verify::format(kEnd / 2) +
                             "\nvtk = false\nframes = 0\n[segregation]\nS = " + verify::format(kS) +
                             "\n[coupling]\npacking_feedback = " + (feedback ? "true" : "false") +
                             "\n[flow]\ndt_max = " + verify::format(dt) + "\n";
    const SceneFile file = SceneFile::parse(text, "verify_tumbler_time_step");
    file.choice("scene", "kind", {"tumbler"});
    const TumblerScene scene = read_tumbler(file);
    file.finish();
    CoupledTumbler tumbler(scene.setup);
    const OutputSet out = run_coupled_tumbler(tumbler, scene.run);
    for (const auto& [path, content] : out.files())
        if (path == "summary.dat") {
            const verify::NamedTable s = verify::parse_named(content, "summary.dat");
            return {s.at(s.last(), "angle_mean_deg"), s.at(s.last(), "core_layer"), s.at(s.last(), "axis_layer")};
        }
    throw InvariantError("verify_tumbler_time_step: the run wrote no summary.dat");
}

}  // namespace

int main(int argc, char** argv) {
    const verify::ProgramOptions options = verify::parse_program_options(argc, argv);
    CheckTable t("Sect. 4.2: the coupled drum's time error at the default step (" + std::to_string(kCells) +
                 " cells, S0 = " + verify::format(kS) + " " + kSegregationRateUnit + ", " + verify::format(kEnd) + " s)");
    DataTable data;
    data.comment("verify_tumbler_time_step: the drum of Sect. 4.2 at " + std::to_string(kCells) +
                 " cells per diameter, S0 = " + verify::format(kS) + " " + kSegregationRateUnit + ", t_end " +
                 verify::format(kEnd) + " s; angle: mean over t >= " + verify::format(kEnd / 2) +
                 " s (deg); core, axis: small-particle shares at t_end (the drum's own regions)");
    Quantities q[2][2];  // [feedback][0: dt, 1: dt/2]
    for (int fb = 0; fb < 2; ++fb)
        for (int k = 0; k < 2; ++k) {
            const double dt = k == 0 ? kDtMax : 0.5 * kDtMax;
            q[fb][k] = run_drum(fb == 1, dt);
            data.row({{"feedback", static_cast<double>(fb)},
                      {"dt_max", dt},
                      {"angle", q[fb][k].angle},
                      {"core", q[fb][k].core},
                      {"axis", q[fb][k].axis}});
        }
    verify::write_data(options, "time_step_small.dat", data);
    const auto whole_error = [&](double Quantities::*field) { return 2.0 * std::fabs(q[1][0].*field - q[1][1].*field); };
    const auto coupling_error = [&](double Quantities::*field) {
        const double delta = (q[1][0].*field - q[1][1].*field) - (q[0][0].*field - q[0][1].*field);
        return 2.0 * std::fabs(delta);
    };
    t.note("flow alone (no feedback), dt -> dt/2: angle " + verify::format(q[0][0].angle) + " -> " +
           verify::format(q[0][1].angle) + " deg, core " + verify::format(q[0][0].core) + " -> " + verify::format(q[0][1].core) +
           ", axis " + verify::format(q[0][0].axis) + " -> " + verify::format(q[0][1].axis));
    t.note("full model, dt -> dt/2: angle " + verify::format(q[1][0].angle) + " -> " + verify::format(q[1][1].angle) +
           " deg, core " + verify::format(q[1][0].core) + " -> " + verify::format(q[1][1].core) + ", axis " +
           verify::format(q[1][0].axis) + " -> " + verify::format(q[1][1].axis));
    const std::string at = " at dt_max " + verify::format(1e3 * kDtMax) + " ms";
    t.at_most("time error of the angle" + at + " (deg)", whole_error(&Quantities::angle), kAngleTol);
    t.at_most("time error of the core's small-particle share" + at, whole_error(&Quantities::core), kShareTol);
    t.at_most("time error of the share near the axis" + at, whole_error(&Quantities::axis), kShareTol);
    t.at_most("coupling's part of the angle's time error (deg)", coupling_error(&Quantities::angle), kAngleTol);
    t.at_most("coupling's part of the core share's time error", coupling_error(&Quantities::core), kShareTol);
    t.at_most("coupling's part of the axis share's time error", coupling_error(&Quantities::axis), kShareTol);
    return t.finish();
}
