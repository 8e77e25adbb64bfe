// Verification of drums of other cross-sections (drum/drum_shape.hpp, docs/drum_shapes.md): the
// same solver in a regular polygon instead of the circle of Sect. 4.2. Coarse grids, one thread.
//   1. Geometry: the cells' exact areas inside a square, a triangle and a circle sum to the
//      shapes' areas (closed forms); a half-full square's surface passes through the axis at every
//      angle (central symmetry).
//   2. A polygon of many sides is the circle's drum: the coupled drum (tumbler) in a 48-gon and in
//      the circle, same cells per diameter, agree in the metrics of summary.dat within the
//      circle's own change to a coarser and a finer grid (the staircases differ in a few wall cells).
//   3. A square drum at rest (rps = 0) holds the lithostatic bed of verify_flow_rest: each row
//      uniform across x, Phi(z) the GSL lithostatic profile of the same mass within that check's
//      tolerance at this cell size, and no more motion than the start's discretisation error allows.
//   4. A turning triangle (coupled drum, bidisperse, both senses of rotation): after every step
//      the amount of each phase at its start to round-off and 0 <= phi <= Phi; and the drum
//      turning clockwise from the mirrored phi_hat gives the mirrored fields.
//
// Run: build/verification/verify_drum_shapes [--data DIR]   (a few seconds)
#include "drum/bed.hpp"
#include "flow/flow_tables.hpp"
#include "harness/check_table.hpp"
#include "harness/flow_reference.hpp"
#include "harness/program.hpp"
#include "run/scene_file.hpp"
#include "scenes/tumbler.hpp"
#include "segregation/invariants.hpp"

#include <algorithm>
#include <array>
#include <cfloat>
#include <cmath>
#include <map>
#include <string>
#include <vector>

using namespace granseg;
using granseg::verify::CheckTable;

namespace {

// 1. Areas: sums of a few thousand exact cell areas, each rounded a few times: 1e-13 relative.
constexpr double kAreaTol = 1e-13;
// 2. Cells per diameter and run length of the many-sided polygon against the circle; the circle
//    again on every neighbouring grid from kCellsCoarse to kCellsFine gives each metric's grid
//    difference, its largest change from kCells, the tolerance. (Its changes to the neighbouring
//    grids scatter: one coarser and one finer grid alone can both land near kCells' value by chance
//    and understate what moving the wall's staircase by a few cells does.)
constexpr int kCells = 28, kCellsCoarse = 25, kCellsFine = 32, kSides = 48;
constexpr double kCompareTime = 2.0;
// 3. The square at rest: 50 cells per diameter (h = 2 mm, the cell size of verify_flow_rest's
//    loose columns, whose tolerance kLooseProfileTol = 4e-3 x 0.014 this takes), held for 0.5 s
//    at the default stepping. The bed starts from the drum's lithostatic bed (RK4 at the cell
//    centres), which differs from the solver's discrete (trapezoidal) balance by its second-order
//    error, less than kRestProfileTol: the bed may move by that much and no more. So the rows
//    may differ across x by at most kRestProfileTol (the walls hold the columns next to them while
//    the bed adjusts), and the momentum is bounded by that adjustment over the creep's relaxation
//    time, below 0.1 s (verify_flow_rest): |Phi u| <= kRestProfileTol x fill height / 0.1 s.
constexpr int kRestCells = 50;
constexpr double kRestTime = 0.5, kRestProfileTol = 4e-3 * 0.014, kRestFill = 0.04;
constexpr double kRestMomentum = kRestProfileTol * kRestFill / 0.1;
// 4. The triangle: phase masses to 1e-12 relative (verify_tumbler a: each step rounds every cell's
//    update once); bounds with only round-off clips (kBoundRoundOff). Mirror: the discretisation
//    is mirror-symmetric operation for operation except the order of its sums (loops in
//    increasing x) and the pressure solve, an iteration stopped at pressure_tolerance of the step's
//    mass change whose iterates are not mirror images: at the default 1e-2 the two senses differ
//    by ~1e-10 after one step, and the avalanches amplify that (printed as a note). With the
//    pressure solved to 1e-12 only the sums' rounding is left, ~1e-16 per step; 1e-12 bounds its
//    growth over the run's ~750 steps, even compounded (750 x 1e-16 x 1e4 of amplification),
//    and lies eight orders below the difference of the default solve after the run (1e-4 to 1e-3).
constexpr double kMassTol = 1e-12;
constexpr double kTriangleTime = 1.5, kTightPressure = 1e-12, kMirrorTol = 1e-12;
constexpr int kTriangleCells = 36;

std::string drum_keys(int cells, const std::string& shape) {
    return "[drum]\ncells_per_diameter = " + std::to_string(cells) + "\n" + shape;
}

/// A tumbler scene (coupled drum) from its [drum] and [initial] keys.
TumblerScene read_scene(const std::string& name, double t_end, const std::string& keys) {
    const std::string text = "[scene]\nkind = \"tumbler\"\n[run]\nt_end = " + verify::format(t_end) +
                             "\nangle_from = " + verify::format(t_end / 2) + "\nvtk = false\nframes = 0\n" + keys;
    const SceneFile file = SceneFile::parse(text, name);
    file.choice("scene", "kind", {"tumbler"});
    TumblerScene scene = read_tumbler(file);
    file.finish();
    return scene;
}

/// The last row of a run's summary.dat as name -> value.
std::map<std::string, double> summary(const OutputSet& files) {
    for (const auto& [name, content] : files.files())
        if (name == "summary.dat") return verify::last_row_of(content);
    return {};
}

void check_geometry(CheckTable& t) {
    const double R = 0.05;
    for (const DrumShape& shape : {DrumShape::circle(R), DrumShape::polygon(4, R, 0.0), DrumShape::polygon(3, R, 0.4)}) {
        const Grid g = drum_grid(shape, 40);
        double sum = 0.0;
        for (int k = 0; k < g.n[2]; ++k)
            for (int i = 0; i < g.n[0]; ++i) {
                const double x0 = g.origin[0] + i * g.h[0], z0 = g.origin[2] + k * g.h[2];
                sum += shape.area_in_rectangle(x0, z0, x0 + g.h[0], z0 + g.h[2]);
            }
        const int n = shape.sides();
        const double exact = n == 0 ? M_PI * R * R : 0.5 * n * R * R * std::sin(2 * M_PI / n);
        t.near_relative(
            "1. exact cell areas summed over the grid / area, " + (n == 0 ? std::string("circle") : std::to_string(n) + "-gon"),
            sum, exact, kAreaTol);
    }
    const DrumShape square = DrumShape::polygon(4, R, 0.0);
    double largest = 0.0;
    for (int step = 0; step < 90; ++step)
        largest = std::max(largest, std::fabs(square.surface_offset(0.5 * square.area(), step * M_PI / 90)));
    t.at_most("1. half-full square: largest |distance of the surface from the axis| over a turn (m)", largest, 1e-15);
}

void check_many_sides(CheckTable& t) {
    const auto run = [](int cells, const std::string& shape) {
        const TumblerScene scene = read_scene("verify_drum_shapes", kCompareTime, drum_keys(cells, shape));
        CoupledTumbler tumbler(scene.setup);
        return summary(run_coupled_tumbler(tumbler, scene.run));
    };
    const std::map<std::string, double> circle = run(kCells, ""),
                                        polygon = run(kCells, "shape = \"polygon\"\nsides = " + std::to_string(kSides) + "\n");
    const char* metrics[] = {"angle_mean_deg", "layer_mean", "segregation_index", "ring",
                             "periphery",      "axis",       "packing_contrast"};
    std::map<std::string, double> grid_difference;
    for (int cells = kCellsCoarse; cells <= kCellsFine; ++cells) {
        if (cells == kCells) continue;
        std::map<std::string, double> other = run(cells, "");
        for (const char* m : metrics) grid_difference[m] = std::max(grid_difference[m], std::fabs(other[m] - circle.at(m)));
    }
    for (const char* m : metrics)
        t.near(std::string("2. ") + std::to_string(kSides) + "-gon vs circle, " + m + " (tolerance: circle at " +
                   std::to_string(kCellsCoarse) + " to " + std::to_string(kCellsFine) + " vs " + std::to_string(kCells) +
                   " cells)",
               polygon.at(m), circle.at(m), grid_difference[m]);
}

void check_square_at_rest(CheckTable& t, const Material& m) {
    DrumSpec drum;
    drum.shape = DrumShapeKind::polygon, drum.sides = 4, drum.rps = 0.0;
    drum.cells_per_diameter = kRestCells;
    drum.fill_height = kRestFill;
    const Grid g = drum.grid();
    FlowSettings s;
    FlowSolver solver(g, m, s, drum.frame());
    const std::vector<double> zero(g.cells(), 0.0), T(g.cells(), s.T_floor);
    solver.set_state(drum_bed_at_rest(drum, g, m, s.phi_hat, s.T_floor), {zero, zero, zero}, T);
    const long double mass0 = verify::exact_mass(solver);
    while (solver.time() < kRestTime) solver.step(kRestTime);
    // Rows: spread across x; the column of inside cells (every column of a square is one).
    double spread = 0.0;
    std::vector<double> z, Phi;
    for (int k = 0; k < g.n[2]; ++k) {
        double lo = 1.0, hi = 0.0, sum = 0.0;
        int count = 0;
        for (int i = 0; i < g.n[0]; ++i) {
            const std::size_t c = g.index(i, 0, k);
            if (!g.is_inside(c)) continue;
            const double v = solver.Phi()[c];
            lo = std::min(lo, v), hi = std::max(hi, v), sum += v, ++count;
        }
        if (count == 0) continue;
        spread = std::max(spread, hi - lo);
        z.push_back(g.center(2, k)), Phi.push_back(sum / count);
    }
    double mass = 0.0;  // per unit area of the floor
    for (double v : Phi) mass += v * g.h[2];
    std::vector<double> height;  // above the floor, the first inside row's lower face
    const double floor = z.front() - 0.5 * g.h[2];
    for (double v : z) height.push_back(v - floor);
    double surface = 0.0;
    const PackingFit& p = m.packing;
    const std::vector<double> reference = verify::lithostatic_profile(m, s.T_floor, p.Phi_rcp(s.phi_hat), p.Phi_co(s.phi_hat),
                                                                      drum.gravity, mass, height, &surface);
    double error = 0.0;
    for (std::size_t k = 0; k < Phi.size() && height[k] + 0.5 * g.h[2] < surface; ++k)
        error = std::max(error, std::fabs(Phi[k] - reference[k]));
    t.note("3. square drum at rest: " + std::to_string(g.n[0]) + " x " + std::to_string(g.n[2]) + " cells, " +
           std::to_string(solver.steps()) + " steps to t = " + verify::format(kRestTime) + " s");
    t.at_most("3. square at rest: max |Phi - Phi_lithostatic (GSL)| below the surface cell", error, kRestProfileTol);
    t.at_most("3. square at rest: largest spread of Phi across a row", spread, kRestProfileTol);
    t.at_most("3. square at rest: largest |Phi u| (m/s)", verify::max_momentum(solver), kRestMomentum);
    t.at_most("3. square at rest: relative mass change",
              std::fabs(static_cast<double>((verify::exact_mass(solver) - mass0) / mass0)), kMassTol);
}

/// The amount of each phase (sum of phi and of Phi - phi).
std::array<double, 2> amounts(const CoupledTumbler& k) {
    std::vector<double> large(k.phi().size());
    for (std::size_t c = 0; c < large.size(); ++c) large[c] = k.flow().Phi()[c] - k.phi()[c];
    return {total_amount(k.grid(), k.phi()), total_amount(k.grid(), large)};
}

/// Largest |field - its mirror image| over the four fields (Phi, phi, u_x, u_z) of two states.
std::array<double, 4> mirror_differences(const Grid& g, const std::array<std::vector<double>, 4>& a,
                                         const std::array<std::vector<double>, 4>& b) {
    std::array<double, 4> worst{0, 0, 0, 0};
    const double sign[4] = {1, 1, -1, 1};  // u_x changes sign under x -> -x
    for (int k = 0; k < g.n[2]; ++k)
        for (int i = 0; i < g.n[0]; ++i) {
            const std::size_t c = g.index(i, 0, k), mirror = g.index(g.n[0] - 1 - i, 0, k);
            for (int f = 0; f < 4; ++f) worst[f] = std::max(worst[f], std::fabs(b[f][c] - sign[f] * a[f][mirror]));
        }
    return worst;
}

void check_triangle(CheckTable& t) {
    const std::string triangle = drum_keys(kTriangleCells, "shape = \"polygon\"\nsides = 3\nfill_height = 0.04\n");
    // A bidisperse bed, small particles on the left: not symmetric, so the mirror check can fail.
    const std::string sense[2] = {"rps = 0.25\n[initial]\nphi_hat = \"x < 0.004 ? 0.8 : 0.2\"\n",
                                  "rps = -0.25\n[initial]\nphi_hat = \"-x < 0.004 ? 0.8 : 0.2\"\n"};
    const std::string tight = "[flow]\npressure_tolerance = " + verify::format(kTightPressure) + "\n";
    std::array<std::vector<double>, 4> fields[2][2];  // [tolerance: default, tight][sense]
    Grid grid;
    for (int p = 0; p < 2; ++p)
        for (int r = 0; r < 2; ++r) {
            const TumblerScene scene = read_scene("verify_drum_shapes", kTriangleTime, triangle + sense[r] + (p ? tight : ""));
            CoupledTumbler tumbler(scene.setup);
            const std::array<double, 2> start = amounts(tumbler);
            const double all = start[0] + start[1];
            double small = 0, large = 0;
            long outside = 0;
            run_coupled_tumbler(tumbler, scene.run, [&](const CoupledTumbler& k) {
                const std::array<double, 2> now = amounts(k);
                small = std::max(small, std::fabs(now[0] - start[0]) / all),
                large = std::max(large, std::fabs(now[1] - start[1]) / all);
                for (std::size_t c = 0; c < k.phi().size(); ++c)
                    if (k.grid().is_inside(c)) outside += !(k.phi()[c] >= 0.0 && k.phi()[c] <= k.flow().Phi()[c]);
            });
            const std::string tag = std::string("4. triangle, ") + (r == 0 ? "counter-clockwise" : "clockwise") +
                                    (p ? ", pressure to " + verify::format(kTightPressure) : "") + ": ";
            t.note(tag + std::to_string(tumbler.flow().steps()) + " steps to t = " + verify::format(kTriangleTime) + " s");
            t.at_most(tag + "max change of the small phase / all material, every step", small, kMassTol);
            t.at_most(tag + "max change of the large phase / all material, every step", large, kMassTol);
            t.count(tag + "(cell, step) pairs with phi < 0 or phi > Phi", outside, 0);
            t.at_most(tag + "largest round-off clip (bulk, segregation)",
                      std::max(tumbler.largest_bulk_clip(), tumbler.largest_correction()), kBoundRoundOff);
            fields[p][r] = {tumbler.flow().Phi(), tumbler.phi(), tumbler.flow().u(0), tumbler.flow().u(2)};
            grid = tumbler.grid();
        }
    const char* names[4] = {"Phi", "phi", "u_x (m/s)", "u_z (m/s)"};
    const std::array<double, 4> loose = mirror_differences(grid, fields[0][0], fields[0][1]);
    const std::array<double, 4> exact = mirror_differences(grid, fields[1][0], fields[1][1]);
    t.note("4. mirror at the default pressure tolerance: max |Phi, phi, u_x, u_z - mirrored| = " + verify::format(loose[0]) +
           ", " + verify::format(loose[1]) + ", " + verify::format(loose[2]) + ", " + verify::format(loose[3]));
    for (int f = 0; f < 4; ++f)
        t.at_most(std::string("4. mirror, pressure to ") + verify::format(kTightPressure) + ": max |" + names[f] + " - mirrored|",
                  exact[f], kMirrorTol);
}

}  // namespace

int main(int argc, char** argv) {
    const auto [options, material] = verify::flow_program(argc, argv);
    (void)options;
    CheckTable t("Drums of other cross-sections: polygons against the circle, at rest, turning");
    check_geometry(t);
    check_square_at_rest(t, material);
    check_triangle(t);
    check_many_sides(t);
    return t.finish();
}
