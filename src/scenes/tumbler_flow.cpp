// Scene kind "tumbler-flow": the rotating drum of Sect. 4.2 without segregation (keys:
// docs/scenes.md). The drum is at rest in the rotating frame; the bed starts at rest in the
// lithostatic balance with a flat surface at the fill height and T at its floor
// (docs/assumptions.md F8), and the drum starts turning at t = 0. Also the [drum] and [run]
// readers shared with the coupled scene kind "tumbler".
#include "scenes/flow_scenes.hpp"

#include "core/format.hpp"
#include "drum/drum_state.hpp"
#include "flow/flow_loop.hpp"
#include "flow/flow_tables.hpp"
#include "scenes/drum_keys.hpp"
#include "scenes/material_section.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

namespace granseg {

namespace {

/// Cells across a polygon drum's inscribed circle, at least: the circle's own minimum, 8 cells
/// across the diameter (the smallest [drum] cells_per_diameter).
constexpr double kMinInscribedCells = 8.0;

/// The files of a tumbler-flow run as it goes: the history sampled every kDrumHistoryInterval, VTK
/// snapshots, and at the end the summary and the fields.
class FlowDrumRecord {
public:
    FlowDrumRecord(const FlowSolver& solver, const DrumSpec& drum, const DrumRun& run, double Phi_level)
        : solver_(solver),
          drum_(drum),
          run_(run),
          shape_(drum.cross_section()),
          Phi_level_(Phi_level),
          v_flow_(drum.flowing_speed()),
          mass0_(solver.mass()),
          angle_(run.angle_from),
          layer_(run.angle_from) {
        history_.comment("tumbler-flow: rotating-frame diagnostics; surface = Phi " + format_number(Phi_level_) +
                         " contour within 0.8 R of the axis (a polygon: inside it scaled by 0.8); flowing = |u| > " +
                         format_number(v_flow_) + " m/s; layer_thickness: area of the flowing bed over the surface's chord (m)");
    }

    /// Records what is due at the solver's time: a history row, a VTK snapshot.
    void sample() {
        if (due(next_history_)) record_history();
        if (run_.vtk && due(next_snapshot_)) {
            next_snapshot_ += run_.snapshot_every;
            char name[64];
            std::snprintf(name, sizeof name, "vtk/tumbler_%04d.vtk", snapshot_++);
            out_.add(name, flow_vtk(solver_));
        }
    }

    /// Saves or restores (run/state_io.hpp) what the record has taken so far; the rest is set-up.
    void checkpoint(StateIO& io) {
        io("record.mass0", mass0_)("record.angle", angle_)("record.layer", layer_)("record.history", history_)("record.out",
                                                                                                               out_);
        io("record.snapshot", snapshot_)("record.next_history", next_history_)("record.next_snapshot", next_snapshot_);
    }

    /// The files: snapshots, history.dat, summary.dat, fields_lab.dat, fields_drum.dat.
    OutputSet finish(const RunTime& cost) {
        out_.add("history.dat", history_);
        out_.add("summary.dat", summary(cost));
        out_.add("fields_lab.dat", flow_field_table(solver_, true));
        out_.add("fields_drum.dat", flow_field_table(solver_, false));
        return std::move(out_);
    }

private:
    bool due(double next) const { return solver_.time() >= next - 1e-12 || solver_.time() >= run_.t_end; }

    void record_history() {
        next_history_ += kDrumHistoryInterval;
        const FlowSolver& s = solver_;
        const DrumState d = drum_state(s, Phi_level_, 0.8 * drum_.radius(), v_flow_, &shape_);
        const double thickness = flowing_layer_thickness(d, shape_);
        angle_.add(s.time(), d.surface_angle_deg);
        layer_.add(s.time(), thickness);
        history_.row({{"t", s.time()},
                      {"steps", static_cast<double>(s.steps())},
                      {"surface_angle_deg", d.surface_angle_deg},
                      {"surface_points", static_cast<double>(d.surface_points)},
                      {"flowing_fraction", d.flowing_fraction},
                      {"max_speed", d.max_speed},
                      {"kinetic_energy", d.kinetic_energy},
                      {"mass", s.mass()},
                      {"mass_change", s.mass() / mass0_ - 1.0},
                      {"dt", s.last_dt()},
                      {"layer_thickness", thickness}});
    }

    DataTable summary(const RunTime& cost) const {
        const FlowSolver& s = solver_;
        TableRow values{{"t_end", s.time()},
                        {"steps", static_cast<double>(s.steps())},
                        {"angle_mean_deg", angle_.mean()},
                        {"angle_std_deg", angle_.std_dev()},
                        {"samples", static_cast<double>(angle_.samples())},
                        {"mass_change", s.mass() / mass0_ - 1.0},
                        {"layer_mean", layer_.mean()},
                        {"layer_std", layer_.std_dev()},
                        {"inside_cells", static_cast<double>(s.grid().inside_cells())}};
        append_flow_work(s, values);
        append_run_time(cost, values);
        DataTable summary;
        summary.comment("dynamic angle of repose: mean of the surface angle over t >= " + format_number(run_.angle_from) +
                        " s; layer: mean thickness of the flowing layer (m) over the same "
                        "samples; mass_change relative; inside_cells: cells of the drum; steps_X: steps whose dt the bound X "
                        "set (docs/flow_solver.md, stage step_size); pressure_solves, newton, krylov, temperature_iterations: "
                        "the solves' iteration counts; seconds_S: wall-clock seconds of each stage S of the step; wall_seconds, "
                        "cpu_seconds (all threads), threads: the run's cost");
        summary.row(values);
        return summary;
    }

    const FlowSolver& solver_;
    const DrumSpec& drum_;
    const DrumRun& run_;
    const DrumShape shape_;
    const double Phi_level_, v_flow_;
    double mass0_;               // before the first sample
    TimeAverage angle_, layer_;  // time averages from angle_from
    DataTable history_;
    OutputSet out_;
    int snapshot_ = 0;
    double next_history_ = 0.0, next_snapshot_ = 0.0;
};

struct TumblerFlow : SceneJob {
    Material material;
    FlowSettings settings;
    DrumSpec drum;
    DrumRun run_options;

    explicit TumblerFlow(Material m) : material(std::move(m)) {}

    OutputSet run() override {
        FlowSolver solver(drum.grid(), material, settings, drum.frame());
        start_at_rest(solver);
        FlowDrumRecord record(solver, drum, run_options, surface_level(material, settings.phi_hat));
        const RunState state = [&](StateIO& io) { io("flow", solver)("record", record); };
        const RunTime cost = run_flow(
            solver, run_options.t_end, "tumbler-flow", [&] { record.sample(); }, checkpoints, state);
        return record.finish(cost);
    }

    /// The bed at rest in the lithostatic balance, T at its floor, the drum at rest in its frame.
    void start_at_rest(FlowSolver& solver) const {
        const Grid& grid = solver.grid();
        const std::vector<double> zero(grid.cells(), 0.0), T(grid.cells(), settings.T_floor);
        solver.set_state(drum_bed_at_rest(drum, grid, material, settings.phi_hat, settings.T_floor), {zero, zero, zero}, T);
    }
};

/// [drum] shape, sides, orientation; a polygon needs kMinInscribedCells across its inscribed circle.
void read_drum_shape(const SceneFile& scene, DrumSpec& d) {
    const std::string s = "drum";
    const bool polygon = scene.choice(s, "shape", {"circle", "polygon"}, "circle") == "polygon";
    if (!polygon) {
        for (const char* key : {"sides", "orientation"})
            if (scene.has(s, key)) scene.fail(s, key, "given for shape = \"circle\"", "only with shape = \"polygon\"");
        return;
    }
    d.shape = DrumShapeKind::polygon;
    d.sides = static_cast<int>(scene.integer(s, "sides", 3, 1000));
    d.orientation = scene.number(s, "orientation", Range::closed(-360, 360), d.orientation);
    const double across = d.cells_per_diameter * std::cos(M_PI / d.sides);  // cells across the inscribed circle
    if (across < kMinInscribedCells)
        scene.fail(s, "cells_per_diameter",
                   std::to_string(d.cells_per_diameter) + " cells leave " + format_number(across, 3) +
                       " across the polygon's inscribed circle, its smallest feature",
                   "cells_per_diameter >= " +
                       std::to_string(static_cast<int>(std::ceil(kMinInscribedCells / std::cos(M_PI / d.sides)))));
}

}  // namespace

DrumSpec read_drum(const SceneFile& scene) {
    const std::string s = "drum";
    DrumSpec d;
    d.diameter = scene.number(s, "diameter", Range::above(0), d.diameter);
    d.cells_per_diameter = static_cast<int>(scene.integer(s, "cells_per_diameter", 8, 2000, d.cells_per_diameter));
    read_drum_shape(scene, d);
    const DrumShape shape = d.cross_section();
    const double height = shape.highest() - shape.lowest(), h = d.diameter / d.cells_per_diameter;
    // The kinematic drum's names are accepted too: fill_fraction (of the height) and rotation_rate.
    d.fill_height = read_drum_key_or_other(scene, "fill_height", Range::open(0, height), 0.75 * height, "fill_fraction",
                                           Range::open(0, 1), [height](double fraction) { return fraction * height; });
    // A bed and a space above it, each at least two cells deep, so the surface has cells on both sides.
    if (!(d.fill_height >= 2 * h && height - d.fill_height >= 2 * h))
        scene.fail(s, "fill_height",
                   format_number(d.fill_height) + " m leaves " +
                       (d.fill_height < 2 * h ? "less than two cells of bed" : "less than two cells of space above the bed"),
                   format_number(2 * h) + " <= fill_height <= " + format_number(height - 2 * h) + " (two cells of " +
                       format_number(h) + " m below and above the surface)");
    d.rps = read_drum_key_or_other(scene, "rps", Range::closed(-100, 100), d.rps, "rotation_rate", Range::closed(-100, 100),
                                   [](double rps) { return rps; });
    d.axial_cells = static_cast<int>(scene.integer(s, "axial_cells", 1, 1000, 1));
    d.axial_length = scene.number(s, "axial_length", Range::above(0), d.axial_cells * d.diameter / d.cells_per_diameter);
    // The drum starts from the bed at rest in the lithostatic balance under g: without gravity
    // there is no bed (Phi(p = 0) = 0, an empty drum).
    d.gravity = scene.number(s, "gravity", Range::above(0), d.gravity);
    return d;
}

DrumRun read_drum_run(const SceneFile& scene) {
    DrumRun r;
    r.t_end = scene.number("run", "t_end", Range::above(0), r.t_end);
    r.snapshot_every = scene.number("run", "snapshot_every", Range::above(0), r.snapshot_every);
    // Default: 10 s (the first avalanches are over), or 0.4 t_end in shorter runs.
    r.angle_from = scene.number("run", "angle_from", Range::at_least(0), std::min(r.angle_from, 0.4 * r.t_end));
    r.vtk = scene.flag("run", "vtk", r.vtk);
    if (!(r.angle_from < r.t_end))
        scene.fail("run", "angle_from", format_number(r.angle_from) + " >= t_end", "angle_from < t_end");
    return r;
}

std::unique_ptr<SceneJob> prepare_tumbler_flow(const SceneFile& scene) {
    auto job = std::make_unique<TumblerFlow>(read_material(scene));
    job->settings = read_flow_settings(scene);
    job->drum = read_drum(scene);
    require_yield_pressure(scene, job->material);
    job->run_options = read_drum_run(scene);
    return job;
}

}  // namespace granseg
