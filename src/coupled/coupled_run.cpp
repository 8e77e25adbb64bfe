#include "coupled/coupled_run.hpp"

#include "core/error.hpp"
#include "core/format.hpp"
#include "core/threads.hpp"
#include "coupled/coupled_tables.hpp"
#include "coupled/material_points.hpp"
#include "coupled/packing_contrast.hpp"
#include "drum/drum_state.hpp"
#include "drum/layer_regions.hpp"
#include "flow/flow_tables.hpp"
#include "run/run_loop.hpp"
#include "segregation/invariants.hpp"

#include <cmath>
#include <cstdio>
#include <optional>

namespace granseg {

namespace {

/// Amount of each phase over the drum: sum of phi and of Phi - phi times the cell volume.
std::array<double, 2> phase_amounts(const CoupledTumbler& t) {
    const std::vector<double>& Phi = t.flow().Phi();
    std::vector<double> large(Phi.size());
    for (std::size_t c = 0; c < Phi.size(); ++c) large[c] = Phi[c] - t.phi()[c];
    return {total_amount(t.grid(), t.phi()), total_amount(t.grid(), large)};
}

std::string numbered(const char* pattern, int n) {
    char name[64];
    std::snprintf(name, sizeof name, pattern, n);
    return name;
}

/// What a coupled run measures at a history sample; the last sample's values also go into the
/// summary.
struct CoupledMeasures {
    double small_change = 0, large_change = 0, surface_angle = 0, axis = 0;
    double tracer_core = NAN, points_core = NAN;
    PatternMetrics metrics;
    PackingContrast contrast;
    LayerRegionShares own;
    /// The columns of the drum's own regions (layer_regions.hpp) and of the tracer's and the
    /// points' shares of its core, the same in history.dat and summary.dat.
    TableRow own_region_columns() const {
        return {{"r_core_layer", own.r_core},       {"core_layer", own.core}, {"ring_layer", own.ring},
                {"periphery_layer", own.periphery}, {"axis_layer", own.axis}, {"tracer_core_layer", tracer_core},
                {"points_core_layer", points_core}};
    }
    void checkpoint(StateIO& io) {
        io("small_change", small_change)("large_change", large_change)("surface_angle", surface_angle)("axis", axis);
        io("tracer_core", tracer_core)("points_core", points_core)("metrics", metrics)("contrast", contrast)("own", own);
    }
};

/// The files of a coupled run as it goes: the history sampled every kDrumHistoryInterval (with the
/// invariants checked there), VTK snapshots, animation frames, and at the end the summary.
class CoupledRecord {
public:
    CoupledRecord(CoupledTumbler& tumbler, const CoupledRunOptions& options);
    /// Records what is due at the tumbler's time.
    void sample();
    /// Moves the material points (if any) with the flow's velocities over the step dt.
    void carry_points(double dt);
    /// The files: initial_lab.dat, snapshots and frames, history.dat, summary.dat, fields_lab.dat.
    OutputSet finish(const RunTime& cost);
    /// Saves or restores (run/state_io.hpp) what the record has taken so far; the rest is set-up.
    void checkpoint(StateIO& io) {
        io("record.hat0", hat0_)("record.amount0", amount0_)("record.amount_all", amount_all_)("record.out", out_);
        io("record.history", history_)("record.angle", angle_)("record.layer", layer_)("record.bounds", bounds_);
        io("record.last", last_)("record.snapshot", snapshot_)("record.frame", frame_)("record.next_history", next_history_);
        io("record.next_snapshot", next_snapshot_)("record.next_frame", next_frame_);
        if (points_) io("record.points", *points_);
    }

private:
    bool due(double next) const;
    /// A history row; throws InvariantError if a phase's amount drifted or phi left [0, Phi].
    void record_history();
    /// Both phases' amounts now and (in last_) their changes since t = 0 relative to all
    /// material; checks them.
    std::array<double, 2> check_amounts();
    /// Pattern metrics, axis share, Fig. 7d contrast and the drum's own regions (with the tracer
    /// and the material points) with a flowing layer `thickness` thick now.
    void measure_pattern(double thickness);
    DataTable summary(const RunTime& cost) const;

    CoupledTumbler& tumbler_;
    const CoupledRunOptions& options_;
    const FlowSolver& flow_;
    const DrumSpec& drum_;
    const DrumShape shape_;
    const double level_, v_flow_;
    std::vector<double> hat0_;  // phi_hat at the start
    std::array<double, 2> amount0_;
    // Both phases' changes are measured against the whole amount of material: round-off follows
    // the bulk fluxes, and a phase may start empty (phi_hat = 0 or 1 everywhere).
    double amount_all_;
    const LayerRegions own_regions_;
    PackingContrastOptions contrast_options_;
    std::optional<MaterialPoints> points_;
    OutputSet out_;
    DataTable history_;
    TimeAverage angle_, layer_;  // time averages from angle_from
    BoundsMonitor bounds_;
    CoupledMeasures last_;
    int snapshot_ = 0, frame_ = 0;
    double next_history_, next_snapshot_, next_frame_;  // from the start
    const double frame_every_;                          // t_end/frames of a run from t = 0 (or from the time it starts at)
};

CoupledRecord::CoupledRecord(CoupledTumbler& tumbler, const CoupledRunOptions& options)
    : tumbler_(tumbler),
      options_(options),
      flow_(tumbler.flow()),
      drum_(tumbler.setup().drum),
      shape_(drum_.cross_section()),
      level_(options.regions.bed_level),
      v_flow_(drum_.flowing_speed()),
      hat0_(tumbler.phi_hat()),
      amount0_(phase_amounts(tumbler)),
      amount_all_(amount0_[0] + amount0_[1]),
      own_regions_(tumbler.grid(), closest_surface_distance(drum_), drum_.radius(), kAxisShare * drum_.diameter),
      angle_(options.run.angle_from),
      layer_(options.run.angle_from),
      next_history_(flow_.time()),
      next_snapshot_(flow_.time()),
      next_frame_(flow_.time()),
      frame_every_(options.frames > 0 ? (options.run.t_end - flow_.time()) / options.frames : INFINITY) {
    out_.add("initial_lab.dat", coupled_field_table(tumbler));
    contrast_options_.bed_level = level_, contrast_options_.v_flow = v_flow_, contrast_options_.bin = drum_.diameter / 20;
    if (tumbler.setup().tracer0) {  // marked by the tracer's share at their lab positions at the start
        const auto mark = [&, t = flow_.time()](double x, double z) {
            const auto lab = flow_.frame().to_lab_position(t, x, z);
            return tumbler.setup().tracer0(lab[0], lab[1]);
        };
        points_.emplace(tumbler.grid(), flow_.Phi(), level_, mark);
    }
    history_.comment(
        "tumbler: masses = sum of phi and of Phi - phi times the cell volume (changes since t = 0 "
        "relative to the whole amount at t = 0, sum of Phi); "
        "index, ring, periphery, core: pattern metrics (pattern_metrics.hpp) of the bed, Phi > " +
        format_number(level_) + "; surface angle: fit of the Phi = " + format_number(level_) +
        " contour within 0.8 R of the axis (a polygon: inside it scaled by 0.8; drum frame); flowing = |u_rel| > " +
        format_number(v_flow_) +
        " m/s; layer_thickness: area of the flowing bed over the surface's chord (m); axis: small-particle "
        "share within " +
        format_number(kAxisShare) +
        " D of the axis; packing_contrast: Fig. 7d "
        "(packing_contrast.hpp); *_layer: the drum's own regions (layer_regions.hpp), r_core_layer = d - the "
        "layer's thickness (its mean over t >= angle_from once there, else the present one), cells weighted by "
        "their exact area inside each region; tracer_core_layer: the passive tracer's share tau/Phi of the core "
        "(NaN without a tracer); points_core_layer: of the material points (four per bed cell at t = 0, carried "
        "through the velocity relative to the drum, material_points.hpp) within the core, the share that "
        "started where the tracer's share is >= 1/2 (NaN without a tracer)");
}

bool CoupledRecord::due(double next) const { return flow_.time() >= next - 1e-12 || flow_.time() >= options_.run.t_end; }

void CoupledRecord::sample() {
    const bool vtk = options_.run.vtk && due(next_snapshot_);
    if (!due(next_history_) && !vtk && !due(next_frame_)) return;
    if (due(next_history_)) record_history();
    if (vtk) {
        next_snapshot_ += options_.run.snapshot_every;
        out_.add(numbered("vtk/tumbler_%04d.vtk", snapshot_++), coupled_vtk(tumbler_));
    }
    if (due(next_frame_)) {
        next_frame_ += frame_every_;
        out_.add(numbered("frames/frame_%03d.dat", frame_++), coupled_composition(tumbler_, level_));
    }
}

void CoupledRecord::carry_points(double dt) {
    if (points_) points_->advance(flow_.u(0), flow_.u(2), dt);
}

void CoupledRecord::record_history() {
    next_history_ += kDrumHistoryInterval;
    const std::array<double, 2> amount = check_amounts();
    const DrumState d = drum_state(flow_, level_, 0.8 * drum_.radius(), v_flow_, &shape_);
    last_.surface_angle = d.surface_angle_deg;
    const double thickness = flowing_layer_thickness(d, shape_);
    angle_.add(flow_.time(), last_.surface_angle);
    layer_.add(flow_.time(), thickness);
    measure_pattern(thickness);
    const CoupledMeasures& m = last_;
    TableRow row{{"t", flow_.time()},
                 {"steps", static_cast<double>(flow_.steps())},
                 {"mass_small", amount[0]},
                 {"mass_large", amount[1]},
                 {"segregation_index", m.metrics.index},
                 {"surface_angle_deg", m.surface_angle},
                 {"ring", m.metrics.ring},
                 {"periphery", m.metrics.periphery},
                 {"core", m.metrics.core},
                 {"mass_small_change", m.small_change},
                 {"mass_large_change", m.large_change},
                 {"flowing_fraction", d.flowing_fraction},
                 {"max_speed", d.max_speed},
                 {"substeps", static_cast<double>(tumbler_.split_segregation_steps())},
                 {"dt", flow_.last_dt()},
                 {"layer_thickness", thickness},
                 {"axis", m.axis},
                 {"packing_contrast", m.contrast.contrast}};
    history_.row(row.add(m.own_region_columns()));
}

std::array<double, 2> CoupledRecord::check_amounts() {
    const double Phi_max = 1.0;  // Phi < Phi_rcp < 1 (closures)
    const std::array<double, 2> amount = phase_amounts(tumbler_);
    last_.small_change = (amount[0] - amount0_[0]) / amount_all_;
    last_.large_change = (amount[1] - amount0_[1]) / amount_all_;
    bounds_.observe(tumbler_.grid(), tumbler_.phi(), flow_.Phi());
    check_segregation_invariants("tumbler", bounds_, tumbler_.largest_correction(), amount0_[0], amount[0], amount_all_,
                                 kAmountTolerance, true, Phi_max);
    if (!(std::fabs(last_.large_change) <= kAmountTolerance))
        throw InvariantError("tumbler: the amount of large particles changed by " + format_number(last_.large_change, 3) +
                             " (relative to all material) by t = " + format_number(flow_.time()) + " s");
    return amount;
}

void CoupledRecord::measure_pattern(double thickness) {
    const Grid& grid = tumbler_.grid();
    last_.metrics = pattern_metrics(grid, tumbler_.phi(), flow_.Phi(), options_.regions, hat0_);
    last_.axis = disc_share(grid, tumbler_.phi(), flow_.Phi(), kAxisShare * drum_.diameter, level_);
    last_.contrast = packing_contrast(tumbler_, last_.surface_angle, contrast_options_);
    const double delta = layer_.samples() > 0 ? layer_.mean() : thickness;
    last_.own = own_regions_.shares(tumbler_.phi(), flow_.Phi(), delta, level_);
    if (!tumbler_.tracer().empty()) last_.tracer_core = own_regions_.shares(tumbler_.tracer(), flow_.Phi(), delta, level_).core;
    if (points_) last_.points_core = points_->marked_share_within(last_.own.r_core);
}

DataTable CoupledRecord::summary(const RunTime& cost) const {
    const CoupledMeasures& m = last_;
    TableRow row{{"t_end", flow_.time()},
                 {"steps", static_cast<double>(flow_.steps())},
                 {"substeps", static_cast<double>(tumbler_.split_segregation_steps())},
                 {"segregation_steps", static_cast<double>(tumbler_.segregation_solver_steps())},
                 {"angle_mean_deg", angle_.mean()},
                 {"angle_std_deg", angle_.std_dev()},
                 {"angle_samples", static_cast<double>(angle_.samples())},
                 {"mass_small_change", m.small_change},
                 {"mass_large_change", m.large_change},
                 {"segregation_index", m.metrics.index},
                 {"ring", m.metrics.ring},
                 {"periphery", m.metrics.periphery},
                 {"core", m.metrics.core},
                 {"initial_mixture", tumbler_.initial_mixture()},
                 {"packing_feedback", tumbler_.setup().packing_feedback ? 1.0 : 0.0},
                 {"packing_contrast", m.contrast.contrast},
                 {"packing_spread", m.contrast.spread},
                 {"contrast_bins", static_cast<double>(m.contrast.bins)},
                 {"largest_bulk_clip", tumbler_.largest_bulk_clip()},
                 {"largest_segregation_clip", tumbler_.largest_correction()},
                 {"seconds_flow", tumbler_.timers().flow},
                 {"seconds_bulk", tumbler_.timers().bulk},
                 {"seconds_segregation", tumbler_.timers().segregation},
                 {"seconds_feedback", tumbler_.timers().feedback},
                 {"inside_cells", static_cast<double>(tumbler_.grid().inside_cells())}};
    append_flow_work(flow_, row);
    row.add({{"layer_mean", layer_.mean()}, {"layer_std", layer_.std_dev()}, {"axis", m.axis}});
    row.add(m.own_region_columns());
    append_run_time(cost, row);
    const PatternRegions& r = options_.regions;
    DataTable summary;
    summary.comment(
        "angle: mean over t >= " + format_number(options_.run.angle_from) + " s; pattern metrics at t_end (regions r_core " +
        format_number(r.r_core) + ", r_ring " + format_number(r.r_ring) + ", r_periphery " + format_number(r.r_periphery) +
        " m); layer: mean and standard deviation of the flowing layer's thickness (m) over the angle's "
        "samples; axis: small-particle share within " +
        format_number(kAxisShare) +
        " D of the axis at t_end; *_layer: as history.dat at t_end; packing contrast (Fig. 7d): packing_contrast.hpp, bins of " +
        format_number(contrast_options_.bin) +
        " m; clips: largest round-off corrections of phi; seconds: wall time of the step's parts (flow, bulk "
        "transport, segregation sub-steps, closures from phi_hat); flow work: flow_output.hpp append_flow_work; wall_seconds, "
        "cpu_seconds (all threads), threads: the run's cost");
    summary.row(row);
    return summary;
}

OutputSet CoupledRecord::finish(const RunTime& cost) {
    out_.add("history.dat", history_);
    out_.add("summary.dat", summary(cost));
    out_.add("fields_lab.dat", coupled_field_table(tumbler_));
    return std::move(out_);
}

}  // namespace

PatternRegions coupled_regions(const DrumSpec& drum, double bed_level) {
    PatternRegions r = drum_regions(closest_surface_distance(drum), kLayerShare * drum.diameter, drum.radius());
    r.bed_level = bed_level;
    r.shape = drum.cross_section();
    return r;
}

OutputSet run_coupled_tumbler(CoupledTumbler& tumbler, const CoupledRunOptions& options, const CoupledStepObserver& observer,
                              RunCheckpoints* checkpoints) {
    const FlowSolver& flow = tumbler.flow();
    CoupledRecord record(tumbler, options);
    RunLoop loop;
    loop.label = "tumbler", loop.t_end = options.run.t_end, loop.checkpoints = checkpoints;
    loop.state = [&](StateIO& io) { io("tumbler", tumbler)("record", record); };
    loop.time = [&] { return flow.time(); };
    loop.steps = [&] { return flow.steps(); };
    loop.step = [&] { record.carry_points(tumbler.step(options.run.t_end)); };
    loop.longest_step = [&] { return flow.settings().dt_max; };
    loop.begin = [&](bool resumed) {
        if (!resumed) record.sample();
    };
    if (observer) loop.observers.push_back([&] { observer(tumbler); });
    loop.observers.push_back([&] { record.sample(); });
    loop.threads = run_threads(tumbler.grid().cells());
    return record.finish(run_loop(loop));
}

}  // namespace granseg
