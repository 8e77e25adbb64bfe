// The tumbler-flow scene (Sect. 4.2 without segregation) on a coarse grid, 25 s: 32 cells per
// diameter, 75 % fill, 0.1 rps, run through its scene file so that the figure comes from the same
// code path as the full run (bench_tumbler, 100 cells per diameter). Checked:
//   - the run completes (no NaN, no broken invariant) and the mass is conserved to round-off;
//   - rolling regime (Froude number Omega^2 R/g = 2e-3, inside the rolling range 1e-4 .. 1e-2 of
//     Mellmann 2001): after the first avalanche the surface flows continuously, the kinetic energy
//     staying within a factor 100 of its largest value (in the slumping regime it falls by orders
//     of magnitude between avalanches, 1e5 in the stick-slip runs of docs/history.md, flow solver),
//     and the flow is localised at the surface: the material 5 cm
//     or more below the free surface moves relative to the drum at less than 10 % of the speed
//     of the top centimetre;
//   - the dynamic angle of repose (mean surface angle over 10..25 s) is not below the model's
//     friction angle atan(mu) = atan(sqrt(2 eta0 eps0/3)) less the coarse grid's error of the
//     critical angle (verify_flow_incline: 0.7 degrees at 16 cells per layer depth; 1 degree here).
// Both modes run the same drum with the same checks (the semi-implicit one at its own dt_max, 2 ms:
// 12,500 steps).
// Writes DIR/flow_tumbler/{fields_lab,fields_drum,history,summary}.dat for figures/fig_flow_tumbler.gp.
//
// Run: build/verification/verify_flow_tumbler [--data DIR]
#include "closures/material.hpp"
#include "harness/check_table.hpp"
#include "harness/flow_reference.hpp"
#include "harness/program.hpp"
#include "scenes/scene_kind.hpp"

#include <array>
#include <cfloat>
#include <cmath>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

using namespace granseg;
using granseg::verify::CheckTable;
using granseg::verify::ProgramOptions;

namespace {

constexpr double kOmega = 2.0 * M_PI * 0.1, kRadius = 0.05;
constexpr double kAngleMargin = 1.0;     // degrees, see above
constexpr double kRollingRange = 1e-2;   // min/max kinetic energy after the first avalanche
constexpr double kFirstAvalanche = 3.0;  // s, the first avalanche is over (at ~1.3 s)
constexpr double kCoreDepth = 0.05;      // m below the free surface
constexpr double kCoreShare = 0.1;       // of the top centimetre's speed

/// Runs the 32-cell drum for 25 s in `mode` through its scene file into dir (the figure reads the
/// explicit run's files).
void run_drum(const std::string& dir, TimeStepping mode) {
    const std::string scene =
        "[scene]\nkind = \"tumbler-flow\"\n[drum]\ncells_per_diameter = 32\n"
        "[run]\nt_end = 25\nangle_from = 10\nvtk = false\n[flow]\ntime_stepping = \"" +
        choice_name(kTimeSteppings, mode) + "\"\n";
    const std::string path = dir + ".toml";
    { std::ofstream(path) << scene; }
    run_scene_file(path, dir);
}

/// Largest relative mass change over the run and min/max kinetic energy after the first avalanche.
std::array<double, 2> mass_and_rolling(const std::vector<std::vector<double>>& history) {
    double mass_change = 0.0, ke_min = INFINITY, ke_max = 0.0;
    for (const auto& r : history) {  // t steps angle points flowing max_speed ke mass mass_change dt
        mass_change = std::max(mass_change, std::fabs(r[8]));
        if (r[0] >= kFirstAvalanche) ke_min = std::min(ke_min, r[6]), ke_max = std::max(ke_max, r[6]);
    }
    return {mass_change, ke_min / ke_max};
}

/// Every check of the drum in one mode (check names prefixed with the mode's tag).
void check_mode(CheckTable& table, const ProgramOptions& options, const Material& m, TimeStepping mode) {
    const std::string tag = verify::mode_tag(mode), dir = options.data_dir + "/flow_tumbler" + verify::mode_suffix(mode);
    run_drum(dir, mode);
    const auto history = verify::read_rows(dir + "/history.dat");
    const auto [mass_change, rolling] = mass_and_rolling(history);
    const double steps = history.back()[1];
    table.at_most(tag + "relative mass change over " + verify::format(steps) + " steps", mass_change, steps * DBL_EPSILON);
    table.at_least(tag + "rolling: min / max kinetic energy after " + verify::format(kFirstAvalanche) + " s", rolling,
                   kRollingRange);

    // Fields in the lab frame (gravity along -z): x z Phi u_x u_y u_z T p inside. The lab velocity
    // of a point turning with the drum is Omega x r, so the speed relative to the drum is
    // |u_lab - Omega x r|. Depth is measured from the bed's highest point along the normal of the
    // surface line at its last fitted angle.
    const double angle = history.back()[2] * M_PI / 180.0, nx = -std::sin(angle), nz = std::cos(angle);
    const auto fields = verify::read_rows(dir + "/fields_lab.dat");
    double top = -INFINITY;
    for (const auto& r : fields)
        if (r[8] > 0.5 && r[2] > 0.3) top = std::max(top, r[0] * nx + r[1] * nz);
    double surface = 0.0, core = 0.0;
    for (const auto& r : fields) {
        if (r[8] < 0.5 || r[2] < 0.3) continue;  // inside the drum, in the bed
        const double depth = top - (r[0] * nx + r[1] * nz);
        const double speed = std::hypot(r[3] + kOmega * r[1], r[5] - kOmega * r[0]);
        if (depth < 0.01) surface = std::max(surface, speed);
        if (depth >= kCoreDepth) core = std::max(core, speed);
    }
    table.note(tag + "speed relative to the drum: top centimetre " + verify::format(surface) + " m/s, 5 cm or deeper " +
               verify::format(core) + " m/s (wall speed " + verify::format(kOmega * kRadius) + " m/s)");
    table.at_most(tag + "localised flow: max speed 5 cm deep / top centimetre", core / surface, kCoreShare);

    const auto summary = verify::read_rows(dir + "/summary.dat");  // t_end steps angle_mean angle_std samples mass_change
    const double friction = std::atan(m.shear_friction()) * 180.0 / M_PI;
    table.note(tag + "dynamic angle of repose " + verify::format(summary[0][2]) + " +- " + verify::format(summary[0][3]) +
               " deg (" + verify::format(summary[0][4]) + " samples over 10..25 s); friction angle " + verify::format(friction) +
               " deg");
    table.at_least(tag + "dynamic angle of repose - friction angle (deg)", summary[0][2] - friction, -kAngleMargin);
}

}  // namespace

int main(int argc, char** argv) {
    return verify::run_flow_modes(verify::flow_program(argc, argv), "Sect. 4.2 tumbler-flow, 32 cells per diameter, 25 s",
                                  check_mode);
}
