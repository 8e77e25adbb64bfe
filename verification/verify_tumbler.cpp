// Verification of the whole model in the drum of Sect. 4.2 (scene kind tumbler: flow and
// segregation coupled, src/coupled/coupled_tumbler.hpp) on a coarse grid, 32 cells per diameter,
// single-threaded. Every run goes through the scene's reader and time loop (read_tumbler,
// run_coupled_tumbler). Walk-through: docs/sect4.2_tumbler.md.
//   1. The Sect. 4.2 set-up for 25 s (S = 1, packing feedback), watched after every step:
//      a. the amount of each phase (sum of phi and of Phi - phi) stays at its start to 1e-12
//         relative; 0 <= phi <= Phi in every cell after every step; the only clips are round-off;
//      c. in the flowing layer d_s is perpendicular to the velocity relative to the drum (angle
//         statistics), and d_s is the same computed from the lab-frame velocity gradient and
//         velocity as from the drum-frame ones the coupling uses;
//      d. (coarse) the pattern has the paper's sense: the ring where the layer feeds the bed holds
//         more small particles than the mixture, the periphery fewer (the full-resolution bounds
//         are bench_tumbler's);
//      and its files are the Fig. 7a-d data of `make verify` (DATA/tumbler).
//   2. b. S = 0 with packing feedback, 5 s: phi_hat stays uniform to 1e-12 after every step, and
//      Phi, u, T equal those of the flow solver run alone on the same drum (the tumbler-flow code
//      path: DrumSpec, drum_bed_at_rest, run_flow) to round-off.
//   3. e. The Fig. 7d contrast (packing_contrast.hpp) on a bed started in three vertical bands
//      (pure large, mixed, pure small), 5 s, with packing feedback on and off: on, mixed material
//      packs denser than pure material at equal depth, by the amount the packing law predicts at
//      the bins' pressure (GSL root finder on the closures, harness/flow_reference.hpp); off, the
//      contrast vanishes within the spread of Phi among cells of one kind at one depth.
// The pattern after 25 s at full resolution (check d) is part of `make bench` (bench_tumbler).
//
// Run: build/verification/verify_tumbler [--data DIR]   (about a minute)
#include "closures/closures.hpp"
#include "coupled/packing_contrast.hpp"
#include "direction/segregation_direction.hpp"
#include "drum/drum_state.hpp"
#include "flow/flow_loop.hpp"
#include "flow/flow_tables.hpp"
#include "harness/check_table.hpp"
#include "harness/flow_reference.hpp"
#include "harness/tolerances.hpp"
#include "run/scene_file.hpp"
#include "scenes/tumbler.hpp"
#include "segregation/invariants.hpp"

#include <Eigen/Geometry>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <string>
#include <vector>

using namespace granseg;
using granseg::verify::CheckTable;

namespace {

// Stated bounds and tolerances, each with its reason.
// a. Amounts: every step rounds each cell's update once (~1e-16 relative, random signs), so over
//    the run's steps (the listing's first line counts them) the drift stays orders of magnitude
//    below 1e-12.
constexpr double kMassTol = 1e-12;
// b. A uniform phi_hat = 1/2 is carried exactly (bulk_transport.hpp: the bulk step is the mass
//    balance scaled by 1/2), so the flow sees exactly the packing of tumbler-flow: 1e-12 leaves
//    room for rounding and flags any real difference (Phi ~ 0.6, u ~ 0.1 m/s, T ~ 1e-5 m^2/s^2).
constexpr double kUniformTol = 1e-12;
constexpr double kSameFlowTol = 1e-12;
// c. Direction. In a parallel shear flow d_s is exactly perpendicular to u (Sect. 2.3). In the
//    layer the streamlines converge and diverge along the surface: an extension rate eps next to
//    the shear rate gamma tilts the maximum-shear planes by (1/2) atan(2 eps/gamma) ~ eps/gamma ~
//    (layer thickness)/(surface length): the run's own layer (history.dat, layer_thickness) over
//    the chord of the 75 %-full drum, 8.7 cm, some 10 degrees (docs/sect4.2_tumbler.md, "What
//    verify_tumbler checks"); most flowing cells lie in the middle of the surface where eps is
//    smaller, so the median deviation from 90 degrees is at most that.
constexpr double kMedianDeviation = 10.0;  // degrees
// Frame: the lab gradient R (G + W) R^T differs from the drum one G by the rotation's spin W
// (antisymmetric: the strain rate, its eigenvectors and so d_s turn with R and nothing else).
// Forming R (G + W) R^T rounds its entries by a few DBL_EPSILON |G + W|, which turns the
// eigenvectors of the strain by at most that over the eigenvalue gap, the principal shear
// (Davis-Kahan); 16 DBL_EPSILON |G + W| / (principal shear) covers the few roundings.
constexpr double kFrameRoundings = 16.0;
// e. Fig. 7d. Off: |contrast| <= the pooled spread of Phi within a kind and a bin (the noise of a
//    bin mean is smaller; the spread also covers the pressure differences at equal depth between
//    the bands, the one thing besides the packing law that differs between them). On: the
//    contrast is at least kContrastSpreads (harness/tolerances.hpp) times that spread, and agrees
//    with the packing law's prediction at the bins' mean pressure to within the spread.
using verify::kContrastSpreads;

// d (coarse). Small particles sink through the flowing layer and leave it at its bottom, into the
//    streamlines of the ring; large ones ride on top and are laid down at the wall (Sect. 4.2,
//    docs/sect4.2_tumbler_kinematic.md section 3). On the coarse grid only the sense is stated:
//    ring above the mixture (1/2), periphery below it.
constexpr double kMixture = 0.5;

constexpr int kCells = 32;

/// A tumbler scene on the verification grid with extra keys.
TumblerScene read_scene(const std::string& name, double t_end, const std::string& extra) {
    const std::string text = "[scene]\nkind = \"tumbler\"\n[drum]\ncells_per_diameter = " + std::to_string(kCells) +
                             "\n[run]\nt_end = " + verify::format(t_end) + "\nangle_from = " + verify::format(t_end / 2) +
                             "\nvtk = false\n" + extra;
    const SceneFile file = SceneFile::parse(text, name);
    file.choice("scene", "kind", {"tumbler"});
    TumblerScene scene = read_tumbler(file);
    file.finish();
    return scene;
}

std::array<double, 2> amounts(const CoupledTumbler& t) {
    std::vector<double> large(t.phi().size());
    for (std::size_t c = 0; c < large.size(); ++c) large[c] = t.flow().Phi()[c] - t.phi()[c];
    return {total_amount(t.grid(), t.phi()), total_amount(t.grid(), large)};
}

/// Check a: runs `scene`, watching the phase amounts and the bounds after every step.
OutputSet run_watched(CheckTable& t, const TumblerScene& scene, CoupledTumbler& tumbler) {
    const std::array<double, 2> start = amounts(tumbler);
    double small = 0, large = 0;
    long outside = 0, steps = 0;
    const OutputSet files = run_coupled_tumbler(tumbler, scene.run, [&](const CoupledTumbler& k) {
        const std::array<double, 2> now = amounts(k);
        small = std::max(small, std::fabs(now[0] / start[0] - 1)), large = std::max(large, std::fabs(now[1] / start[1] - 1));
        for (std::size_t c = 0; c < k.phi().size(); ++c)
            if (k.grid().is_inside(c)) outside += !(k.phi()[c] >= 0.0 && k.phi()[c] <= k.flow().Phi()[c]);
        ++steps;
    });
    t.note(verify::format(steps) + " flow steps, " + verify::format(tumbler.split_segregation_steps()) +
           " segregation sub-steps (" + verify::format(tumbler.segregation_solver_steps()) + " steps of the segregation solver)");
    t.at_most("a. max relative change of the small phase (sum phi) over all steps", small, kMassTol);
    t.at_most("a. max relative change of the large phase (sum Phi - phi) over all steps", large, kMassTol);
    t.count("a. (cell, step) pairs with phi < 0 or phi > Phi after the step", outside, 0);
    t.note("a. before the clip: max(phi - Phi) " + verify::format(tumbler.max_excess()) + ", min phi " +
           verify::format(tumbler.min_phi()));
    t.at_most("a. largest round-off clip after the bulk step (absolute, Phi < 1)", tumbler.largest_bulk_clip(), kBoundRoundOff);
    t.at_most("a. largest round-off clip of the segregation sub-step", tumbler.largest_correction(), kBoundRoundOff);
    return files;
}

/// The 3x3 rotation by angle a about the y axis that turns drum-frame x-z components into lab ones.
Eigen::Matrix3d turn(double a) {
    Eigen::Matrix3d R;
    R << std::cos(a), 0, -std::sin(a), 0, 1, 0, std::sin(a), 0, std::cos(a);
    return R;
}

/// Check c on the final state.
void check_direction(CheckTable& t, const CoupledTumbler& tumbler, double bed_level) {
    const FlowSolver& f = tumbler.flow();
    const Grid& g = f.grid();
    const double omega = f.frame().omega, v_flow = tumbler.setup().drum.flowing_speed();
    const Eigen::Matrix3d R = turn(omega * f.time());
    Eigen::Matrix3d W = Eigen::Matrix3d::Zero();  // gradient of Omega x r: d(-omega z)/dz, d(omega x)/dx
    W(0, 2) = -omega, W(2, 0) = omega;
    DirectionOptions planar;
    planar.planar_xz = true;
    std::vector<double> deviation;
    double worst_frame = 0;
    long status_differs = 0, segregating = 0, inertial_differs = 0;
    for (std::size_t c = 0; c < g.cells(); ++c) {
        if (!g.is_inside(c) || !(f.Phi()[c] > bed_level)) continue;
        const Eigen::Vector3d d(tumbler.d_s(0)[c], 0.0, tumbler.d_s(2)[c]), u(f.u(0)[c], f.u(1)[c], f.u(2)[c]);
        Eigen::Matrix3d G;
        for (int b = 0; b < 3; ++b)
            for (int a = 0; a < 3; ++a) G(b, a) = f.velocity_gradient(b, a)[c];
        const SegregationDirection lab = segregation_direction(R * (G + W) * R.transpose(), R * u, planar);
        if (lab.segregates() != (d.squaredNorm() > 0)) ++status_differs;
        if (!lab.segregates() || d.squaredNorm() == 0) continue;
        ++segregating;
        const Eigen::Vector3d back = R.transpose() * lab.d_s;  // the angle from the cross product: acos loses half the digits
        const double angle = std::atan2(back.cross(d).norm(), std::fabs(back.dot(d)));
        worst_frame = std::max(worst_frame, angle / (DBL_EPSILON * (G + W).norm() / lab.principal_shear));
        // The lab velocity u + Omega x r instead of the velocity relative to the drum.
        const Eigen::Vector3d r(g.center(0, c % g.n[0]), 0.0, g.center(2, c / g.n[0]));
        const SegregationDirection inertial = segregation_direction(G + W, u + W * r, planar);
        inertial_differs += std::fabs(inertial.d_s.dot(d)) < std::cos(M_PI / 180);
        if (u.norm() > v_flow) deviation.push_back(90.0 - std::acos(std::min(1.0, std::fabs(d.dot(u)) / u.norm())) * 180 / M_PI);
    }
    std::sort(deviation.begin(), deviation.end());
    const auto quantile = [&](double q) {
        return deviation.empty() ? NAN : deviation[static_cast<std::size_t>(q * (deviation.size() - 1))];
    };
    t.note("c. 90 deg - angle(d_s, u_rel) in " + std::to_string(deviation.size()) + " flowing bed cells (|u_rel| > " +
           verify::format(v_flow) + " m/s): median " + verify::format(quantile(0.5)) + ", 90 % " + verify::format(quantile(0.9)) +
           ", max " + verify::format(quantile(1.0)) + " deg");
    t.at_most("c. median deviation of d_s from perpendicular to u_rel, flowing cells [deg]", quantile(0.5), kMedianDeviation);
    t.count("c. cells where lab and drum frame disagree on whether d_s exists", status_differs, 0);
    t.at_most("c. max angle(d_s lab frame, d_s drum frame) / (eps |G + W| / principal shear)", worst_frame, kFrameRoundings);
    t.note("c. with the lab velocity u + Omega x r instead of u_rel, d_s turns by more than 1 deg in " +
           std::to_string(inertial_differs) + " of " + std::to_string(segregating) + " segregating cells");
}

/// Check b: S = 0 with packing feedback against the flow solver alone on the same drum.
void check_no_segregation(CheckTable& t) {
    const double t_end = 5.0;
    const TumblerScene scene = read_scene("verify_tumbler_S0", t_end, "[segregation]\nS = 0\n");
    CoupledTumbler tumbler(scene.setup);
    double worst_hat = 0;
    CoupledRunOptions run = scene.run;
    run.frames = 0;
    run_coupled_tumbler(tumbler, run, [&](const CoupledTumbler& k) {
        const std::vector<double> hat = k.phi_hat();
        for (std::size_t c = 0; c < hat.size(); ++c)
            if (k.flow().Phi()[c] > 0.0) worst_hat = std::max(worst_hat, std::fabs(hat[c] - 0.5));
    });
    t.at_most("b. S = 0: max |phi_hat - 1/2| over cells with material, all steps", worst_hat, kUniformTol);

    const DrumSpec& drum = scene.setup.drum;
    const Grid grid = drum.grid();
    FlowSettings settings = scene.setup.flow;
    settings.phi_hat = 0.5;
    FlowSolver alone(grid, scene.setup.material, settings, drum.frame());
    const std::vector<double> zero(grid.cells(), 0.0), T(grid.cells(), settings.T_floor);
    alone.set_state(drum_bed_at_rest(drum, grid, scene.setup.material, 0.5, settings.T_floor), {zero, zero, zero}, T);
    run_flow(alone, t_end, "tumbler-flow");
    double dPhi = 0, du = 0, dT = 0;
    for (std::size_t c = 0; c < grid.cells(); ++c) {
        dPhi = std::max(dPhi, std::fabs(alone.Phi()[c] - tumbler.flow().Phi()[c]));
        for (int b = 0; b < 3; ++b) du = std::max(du, std::fabs(alone.u(b)[c] - tumbler.flow().u(b)[c]));
        dT = std::max(dT, std::fabs(alone.T()[c] - tumbler.flow().T()[c]));
    }
    t.count("b. S = 0: flow steps of the coupled run minus those of the flow alone", tumbler.flow().steps() - alone.steps(), 0);
    t.at_most("b. S = 0: max |Phi - Phi(flow alone)| at t = 5 s", dPhi, kSameFlowTol);
    t.at_most("b. S = 0: max |u - u(flow alone)| at t = 5 s [m/s]", du, kSameFlowTol);
    t.at_most("b. S = 0: max |T - T(flow alone)| at t = 5 s [m^2/s^2]", dT, kSameFlowTol);
}

/// The packing law's contrast at equal pressure: per depth bin, Phi at the bin's mean pressure for
/// each cell's own phi_hat (GSL), mixed minus pure, weighted like packing_contrast.
double predicted_contrast(const CoupledTumbler& tumbler, const PackingContrastOptions& o) {
    // The same cells and classes as packing_contrast, grouped by pressure instead of depth: the
    // packing law alone, with no difference of pressure between the kinds.
    const FlowSolver& f = tumbler.flow();
    const Material& m = tumbler.setup().material;
    const std::vector<double> hat = tumbler.phi_hat();
    double p_sum = 0;
    long n = 0;
    std::vector<std::size_t> mixed, pure;
    for (std::size_t c = 0; c < hat.size(); ++c) {
        if (!f.grid().is_inside(c) || !(f.Phi()[c] > o.bed_level) || std::hypot(f.u(0)[c], f.u(2)[c]) > o.v_flow) continue;
        const bool is_mixed = hat[c] > o.mixed_lo && hat[c] < o.mixed_hi, is_pure = hat[c] < o.pure || hat[c] > 1 - o.pure;
        if (!is_mixed && !is_pure) continue;
        (is_mixed ? mixed : pure).push_back(c);
        const auto lim = f.packing(c);
        p_sum += evaluate_closures_at(m, f.Phi()[c], f.T()[c], lim[0], lim[1]).p, ++n;
    }
    const double p = p_sum / n;  // the mean pressure of the resting bed's classified cells
    const auto mean_Phi = [&](const std::vector<std::size_t>& cells) {
        double sum = 0;
        for (std::size_t c : cells) {
            const double rcp = m.packing.Phi_rcp(hat[c]), co = m.packing.Phi_co(hat[c]);
            sum += verify::Phi_of_pressure(m, p, f.T()[c], rcp, co);
        }
        return sum / cells.size();
    };
    return mean_Phi(mixed) - mean_Phi(pure);
}

/// Check e: the Fig. 7d contrast with packing feedback on and off.
void check_packing_contrast(CheckTable& t) {
    const std::string bands = "[initial]\nphi_hat = \"x < -0.0125 ? 0 : (x > 0.0125 ? 1 : 0.5)\"\n";
    PackingContrast result[2];
    double predicted = 0;
    for (int on = 1; on >= 0; --on) {
        const TumblerScene scene =
            read_scene("verify_tumbler_bands", 5.0, bands + "[coupling]\npacking_feedback = " + (on ? "true" : "false") + "\n");
        CoupledTumbler tumbler(scene.setup);
        CoupledRunOptions run = scene.run;
        run.frames = 0;
        run_coupled_tumbler(tumbler, run);
        PackingContrastOptions o;
        o.bed_level = scene.run.regions.bed_level, o.v_flow = scene.setup.drum.flowing_speed(),
        o.bin = scene.setup.drum.diameter / 20;
        const DrumState d = drum_state(tumbler.flow(), o.bed_level, 0.8 * scene.setup.drum.radius(), o.v_flow);
        result[on] = packing_contrast(tumbler, d.surface_angle_deg, o);
        if (on) predicted = predicted_contrast(tumbler, o);
        t.note(std::string("e. packing feedback ") + (on ? "on" : "off") + ": contrast " + verify::format(result[on].contrast) +
               ", spread " + verify::format(result[on].spread) + " over " + std::to_string(result[on].bins) + " bins (" +
               std::to_string(result[on].mixed) + " mixed, " + std::to_string(result[on].pure) + " pure cells)");
    }
    t.at_least("e. on: contrast / spread", result[1].contrast / result[1].spread, kContrastSpreads);
    t.near("e. on: contrast vs the packing law at equal pressure", result[1].contrast, predicted, result[1].spread);
    t.at_most("e. off: |contrast| / spread", std::fabs(result[0].contrast) / result[0].spread, 1.0);
}

}  // namespace

int main(int argc, char** argv) {
    const auto [options, material] = verify::flow_program(argc, argv);
    (void)material;
    CheckTable t("Sect. 4.2 tumbler, flow and segregation coupled, " + std::to_string(kCells) + " cells per diameter");

    const TumblerScene scene = read_scene("verify_tumbler", 25.0, "");
    CoupledTumbler tumbler(scene.setup);
    const OutputSet files = run_watched(t, scene, tumbler);
    for (const auto& [name, content] : files.files()) write_file_atomically(options.data_dir + "/tumbler/" + name, content);
    check_direction(t, tumbler, scene.run.regions.bed_level);
    const PatternMetrics pattern = pattern_metrics(tumbler.grid(), tumbler.phi(), tumbler.flow().Phi(), scene.run.regions,
                                                   std::vector<double>(tumbler.grid().cells(), kMixture));
    t.note("d. pattern at t = 25 s: index " + verify::format(pattern.index) + ", ring " + verify::format(pattern.ring) +
           ", periphery " + verify::format(pattern.periphery) + ", core " + verify::format(pattern.core));
    t.at_least("d. small-particle fraction of the ring - the mixture's", pattern.ring - kMixture, 0.0);
    t.at_most("d. small-particle fraction of the periphery - the mixture's", pattern.periphery - kMixture, 0.0);
    check_no_segregation(t);
    check_packing_contrast(t);
    return t.finish();
}
