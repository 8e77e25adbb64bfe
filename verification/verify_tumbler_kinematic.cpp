// Verification of segregation in the kinematic drum of Sect. 4.2 (scene kind tumbler-kinematic):
// runs the scene file of the figures, figures/tumbler_kinematic.toml (100 cells per diameter,
// 25 s), through the scene's own reader and time loop (read_tumbler_kinematic,
// run_kinematic_tumbler), watching every step.
//
// What is checked, and against what independent expectation (docs/sect4.2_tumbler_kinematic.md):
//   - conservation: the amount of small particles after every step equals the start to 1e-12
//     relative (divergence-free mass fluxes, zero flux through every wall face);
//   - bounds: 0 <= phi <= Phi in every bed cell after every bulk step and after every full step
//     (violations counted, beyond the round-off allowance), and the solver's round-off clip;
//   - direction: d_s in the layer within the stated angle of the surface normal, the sign that
//     sends small particles down into the bed, and no segregation outside the layer;
//   - the pattern after 25 s, as inequalities derived from the kinematics before running:
//     small particles in the ring below the layer's deepest point, large ones at the wall, a
//     segregation index well above the mixed value, and the core, which no streamline from the
//     layer reaches, changed only by the numerical diffusion of the bulk transport (a bound per
//     bulk scheme).
// Then the same scene with the other bulk scheme (FCT <-> donor cell), the same checks except the
// direction. Writes the scene's outputs (tumbler_*.dat) for figures/fig7{a,b,c}_*.gp.
//
// Run: build/verification/verify_tumbler_kinematic [--data DIR]   (reads
// figures/tumbler_kinematic.toml relative to the source tree the binary was built in)
#include "harness/check_table.hpp"
#include "harness/program.hpp"
#include "harness/tolerances.hpp"
#include "run/scene_file.hpp"
#include "scenes/tumbler_kinematic.hpp"
#include "segregation/invariants.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>

using namespace granseg;
using granseg::verify::CheckTable;
namespace fs = std::filesystem;

namespace {

// Stated bounds and tolerances, each with its reason.
// Mass: ~7000 steps of telescoping flux sums, each rounding by ~1e-16 relative.
constexpr double kMassTol = 1e-12;
// Direction (docs/sect2.3_direction.md, section 6): over the central half of the surface the
// layer thickness varies by at most 1 - sqrt(3/4) = 13 %, so the shear planes tilt by about
// atan(delta'(s)) plus the curvature of the streamlines, whose continuous supremum is 11.4 deg;
// 12 deg on the cell centres. Over the whole layer the median, 6 deg; towards the ends (delta -> 0)
// d_s follows the converging streamlines and is not bounded by the surface normal.
constexpr double kCentralAngleBound = 12.0;  // deg, |s| <= L/2
constexpr double kMedianAngleBound = 6.0;    // deg, whole layer
// Pattern after 25 s (2.5 revolutions). Derivation in docs/sect4.2_tumbler_kinematic.md, section 3:
// the layer sorts a passing streamline in delta0/|a| ~ 0.1 s, ten times faster than its passage
// (~1 s), so every streamline that has passed the layer is sorted: small ones to the inner
// (deeper) streamlines, large ones to the outer ones. Half of the circulating area is small; by
// area that is r < r_s ~ 0.035 m, so the ring r_core <= r < d lies wholly in the small half and
// the periphery r >= 0.8 R wholly in the large half. Margins: donor-cell diffusion smears the
// sorted bands over ~1 cm (below), a third of the band widths.
constexpr double kRingAtLeast = 0.75;      // small fraction of the ring (sorted: 1)
constexpr double kPeripheryAtMost = 0.25;  // small fraction of the periphery (sorted: 0)
// Index of a bed whose circulating part (86 % of the area) is sorted: sqrt(0.86) = 0.93; with
// the smeared bands at least half of it.
constexpr double kIndexAtLeast = 0.45;
// Core. No streamline of the core (r < r_core = d - delta0, the layer bottom's closest approach)
// enters the layer, so physically phi_hat stays at 0.5 there; numerically the bulk transport
// carries the ring's excess inwards across the circular streamlines.
//  donor cell: transport of solid-body rotation on a Cartesian grid diffuses across the flow with
//    D ~ 0.21 h |u| (the cross-stream part of (h/2) diag(|u_x|, |u_z|) averaged over the circle):
//    sqrt(2 D t) = 1.1 cm at r = r_core after 25 s. The innermost quarter, r < r_core/4, is 1.3 cm
//    (1.2 diffusion lengths) from the ring: the ring's excess (<= 0.5) arrives reduced by at least
//    erfc(1.3/(2 x 0.75)) ~ 0.2, i.e. a deviation <= 0.1.
//  FCT (the figures' scheme): the antidiffusion cancels the first-order diffusion wherever the
//    limiter does not act; the limiter acts at the ring's steep inner edge, a band of a few cells.
//    At r < r_core/2, 8 cells inside the edge, the field sees only the second-order (Lax-Wendroff)
//    error of a field that is 0.5 there, so we state 1e-3, a hundredth of the donor-cell
//    deviation there (0.5 erfc(0.85/1.5) ~ 0.2).
constexpr double kInnerCoreDonorCell = 0.1;  // |phi_hat - 0.5| for r < r_core/4
constexpr double kInnerCoreFct = 1e-3;       // |phi_hat - 0.5| for r < r_core/2
// Below the layer a = 0 (no shear): the segregation sub-step may change such a cell only by the
// solver's round-off clip (kBoundRoundOff Phi).

double degrees(double cosine) { return std::acos(std::min(1.0, std::fabs(cosine))) * 180 / M_PI; }

fs::path scene_path() {
    const fs::path beside =
        fs::canonical("/proc/self/exe").parent_path().parent_path().parent_path() / "figures/tumbler_kinematic.toml";
    return fs::exists(beside) ? beside : fs::path("figures/tumbler_kinematic.toml");
}

void check_direction(CheckTable& t, const KinematicTumbler& tumbler) {
    const Grid& g = tumbler.grid();
    const RollingDrumFlow& flow = tumbler.flow();
    const Eigen::Vector3d n = flow.normal();
    std::vector<double> angles;
    double central = 0, worst = 0;
    long wrong_sign = 0, silent = 0, outside = 0;
    for_each_bed_cell(g, [&](const BedCell& b) {
        const std::size_t c = b.c;
        const Eigen::Vector3d a(tumbler.frozen().a[0][c], 0.0, tumbler.frozen().a[2][c]);
        if (!tumbler.fields().in_layer[c]) {
            outside += a.squaredNorm() != 0.0;
            return;
        }
        if (a.squaredNorm() == 0.0) {
            ++silent;
            return;
        }
        // a = (S^sl): small particles move along -a; in the layer that must point into the bed.
        wrong_sign += a.dot(n) <= 0.0;
        const double angle = degrees(a.normalized().dot(n));
        angles.push_back(angle);
        worst = std::max(worst, angle);
        if (std::fabs(flow.surface_coordinates(b.x, b.z)[0]) <= flow.half_chord() / 2) central = std::max(central, angle);
    });
    std::sort(angles.begin(), angles.end());
    t.note("direction of a = S^sl in " + std::to_string(angles.size()) + " layer cells vs the surface normal: median " +
           verify::format(angles[angles.size() / 2]) + ", max " + verify::format(worst) + " deg (at the ends of the surface)");
    t.count("layer cells without segregation (a = 0)", silent, 0);
    t.count("layer cells where small particles would rise (a . n <= 0)", wrong_sign, 0);
    t.count("bed cells below the layer with a != 0", outside, 0);
    t.at_most("max angle(d_s, surface normal), |s| <= L/2 [deg]", central, kCentralAngleBound);
    t.at_most("median angle(d_s, surface normal), whole layer [deg]", angles[angles.size() / 2], kMedianAngleBound);
}

/// Mass-weighted phi_hat over the bed cells with r < radius.
double inner_composition(const KinematicTumbler& tumbler, double radius) {
    const Grid& g = tumbler.grid();
    double small = 0, all = 0;
    for_each_bed_cell(g, [&](const BedCell& b) {
        if (std::hypot(b.x, b.z) < radius) small += tumbler.phi()[b.c], all += tumbler.Phi()[b.c];
    });
    return small / all;
}

/// Runs `scene` on `tumbler` through the scene's time loop, watching every step, and records the
/// conservation and bound checks; `completed` is false if the loop stopped on an invariant.
KinematicRunResult run_watched(CheckTable& t, const TumblerKinematicScene& scene, KinematicTumbler& tumbler, bool& completed) {
    const double Phi = scene.setup.Phi, allowance = kBoundRoundOff * Phi;
    const double mass0 = total_amount(tumbler.grid(), tumbler.phi());
    double drift = 0;
    long bulk_violations = 0, step_violations = 0, still_segregated = 0;
    const auto observer = [&](const KinematicTumbler& k, const BoundsMonitor& bulk, const std::vector<double>& after_bulk) {
        bulk_violations += bulk.max_excess > allowance || bulk.min_phi < -allowance;
        drift = std::max(drift, std::fabs(total_amount(k.grid(), k.phi()) - mass0) / mass0);
        for (std::size_t c = 0; c < k.phi().size(); ++c) {
            if (!k.grid().is_inside(c)) continue;
            if (k.phi()[c] < 0.0 || k.phi()[c] > k.Phi()[c]) ++step_violations;
            // Eq. (63) with f = 0 on one side gives max(f_L <= 0, 0) = 0 (or min(0, f_R >= 0) = 0).
            if (k.frozen().a[0][c] == 0.0 && k.frozen().a[2][c] == 0.0 && std::fabs(k.phi()[c] - after_bulk[c]) > allowance)
                ++still_segregated;
        }
    };
    const auto start = std::chrono::steady_clock::now();
    KinematicRunResult result;
    completed = false;
    try {
        result = run_kinematic_tumbler(tumbler, scene.run, observer);
        completed = true;
    } catch (const std::exception& e) {  // the loop's own invariants (InvariantError)
        t.note(std::string("run stopped: ") + e.what());
        t.count("run completed", 0, 1);
        return result;
    }
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    t.note(std::to_string(tumbler.steps()) + " steps, dt = " + verify::format(tumbler.time_step()) + " s (bulk " +
           verify::format(tumbler.bulk_time_step()) + ", segregation " + verify::format(tumbler.segregation_time_step()) + "), " +
           verify::format(tumbler.cell_updates() / seconds) + " cell updates/s (run with checks, " + verify::format(seconds) +
           " s)");
    t.at_most("max relative change of sum(phi) over all steps", drift, kMassTol);
    t.count("steps whose bulk transport left [0, Phi] beyond round-off", bulk_violations, 0);
    t.count("(cell, step) pairs with phi < 0 or phi > Phi after the step", step_violations, 0);
    t.at_most("largest round-off clip of the segregation step / Phi", tumbler.largest_correction() / Phi, kBoundRoundOff);
    t.count("(cell, step) pairs: a cell with a = 0 changed by segregation beyond round-off", still_segregated, 0);
    return result;
}

/// The pattern after the run (section 3 of the walk-through).
void check_pattern(CheckTable& t, const TumblerKinematicScene& scene, const KinematicTumbler& tumbler,
                   const KinematicRunResult& result) {
    const PatternRegions& r = scene.run.regions;
    const PatternMetrics& end = result.history.back().metrics;
    t.note("pattern at t = " + verify::format(result.history.back().t) + " s; regions: core r < " + verify::format(r.r_core) +
           " m, ring " + verify::format(r.r_core) + " <= r < " + verify::format(r.r_ring) +
           " m, periphery r >= " + verify::format(r.r_periphery) + " m; core (all of it) " + verify::format(end.core));
    t.at_least("small-particle fraction of the ring", end.ring, kRingAtLeast);
    t.at_most("small-particle fraction of the periphery", end.periphery, kPeripheryAtMost);
    t.at_least("segregation index std(phi_hat)/sqrt(m(1-m))", end.index, kIndexAtLeast);
    if (scene.setup.bulk == BulkScheme::fct)
        t.near("|phi_hat - 0.5| in the inner core r < r_core/2 (FCT)", inner_composition(tumbler, r.r_core / 2) - 0.5, 0.0,
               kInnerCoreFct);
    else
        t.near("|phi_hat - 0.5| in the inner core r < r_core/4 (donor cell)", inner_composition(tumbler, r.r_core / 4) - 0.5, 0.0,
               kInnerCoreDonorCell);
}

}  // namespace

int main(int argc, char** argv) {
    const auto options = verify::parse_program_options(argc, argv);
    const fs::path path = scene_path();
    const SceneFile file = SceneFile::load(path.string());
    file.choice("scene", "kind", {"tumbler-kinematic"});
    (void)file.text("output", "dir", "");
    const TumblerKinematicScene scene = read_tumbler_kinematic(file);
    file.finish();
    CheckTable t("Kinematic tumbler (Sect. 4.2): " + path.filename().string() + ", " +
                 std::to_string(scene.setup.cells_per_diameter) + " cells per diameter, " + verify::format(scene.run.t_end) +
                 " s");

    t.note("the scene file as it is (bulk transport " + std::string(scene.setup.bulk == BulkScheme::fct ? "fct" : "donor-cell") +
           ")");
    KinematicTumbler tumbler(scene.setup);
    bool completed = false;
    const KinematicRunResult result = run_watched(t, scene, tumbler, completed);
    if (!completed) return t.finish();
    check_direction(t, tumbler);
    check_pattern(t, scene, tumbler, result);
    const OutputSet files = tumbler_kinematic_outputs(tumbler, result, scene.run);
    for (const auto& [name, content] : files.files()) write_file_atomically(options.data_dir + "/" + name, content);

    // The same scene with the other bulk scheme: the same invariants and pattern, and its own core bound.
    TumblerKinematicScene other = scene;
    other.setup.bulk = scene.setup.bulk == BulkScheme::fct ? BulkScheme::donor_cell : BulkScheme::fct;
    t.note("the same scene with bulk transport " + std::string(other.setup.bulk == BulkScheme::fct ? "fct" : "donor-cell"));
    KinematicTumbler second(other.setup);
    const KinematicRunResult second_result = run_watched(t, other, second, completed);
    if (completed) check_pattern(t, other, second, second_result);
    return t.finish();
}
