#include "tumbler/coupled_run.hpp"

#include "core/error.hpp"
#include "core/format.hpp"
#include "core/progress.hpp"
#include "core/threads.hpp"
#include "flow_run/flow_output.hpp"
#include "segregation/invariants.hpp"
#include "tumbler/coupled_tables.hpp"
#include "tumbler/layer_regions.hpp"
#include "tumbler/material_points.hpp"
#include "tumbler/packing_contrast.hpp"
#include "tumbler/tumbler_run.hpp"

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

}  // namespace

PatternRegions coupled_regions(const DrumSpec& drum, double bed_level) {
    PatternRegions r = drum_regions(closest_surface_distance(drum), kLayerShare * drum.diameter, drum.radius());
    r.bed_level = bed_level;
    r.shape = drum.cross_section();
    return r;
}

OutputSet run_coupled_tumbler(CoupledTumbler& tumbler, const CoupledRunOptions& options,
                              const CoupledStepObserver& observer) {
    const DrumSpec& drum = tumbler.setup().drum;
    const DrumShape shape = drum.cross_section();
    const FlowSolver& flow = tumbler.flow();
    const Grid& grid = tumbler.grid();
    const double t_end = options.run.t_end, level = options.regions.bed_level, v_flow = drum.flowing_speed();
    const double Phi_max = 1.0;  // Phi < Phi_rcp < 1 (closures)
    OutputSet out;
    out.add("initial_lab.dat", coupled_field_table(tumbler));
    const std::vector<double> hat0 = tumbler.phi_hat();
    const std::array<double, 2> amount0 = phase_amounts(tumbler);
    // Both phases' changes are measured against the whole amount of material: round-off follows
    // the bulk fluxes, and a phase may start empty (phi_hat = 0 or 1 everywhere).
    const double amount_all = amount0[0] + amount0[1];

    DataTable history({"t", "steps", "mass_small", "mass_large", "segregation_index", "surface_angle_deg", "ring",
                       "periphery", "core", "mass_small_change", "mass_large_change", "flowing_fraction", "max_speed",
                       "substeps", "dt", "layer_thickness", "axis", "packing_contrast", "r_core_layer", "core_layer",
                       "ring_layer", "periphery_layer", "axis_layer", "tracer_core_layer",
                       "points_core_layer"});
    history.comment("tumbler: masses = sum of phi and of Phi - phi times the cell volume (changes since t = 0 "
                    "relative to the whole amount at t = 0, sum of Phi); "
                    "index, ring, periphery, core: pattern metrics (pattern_metrics.hpp) of the bed, Phi > " +
                    format_number(level) + "; surface angle: fit of the Phi = " + format_number(level) +
                    " contour within 0.8 R of the axis (a polygon: inside it scaled by 0.8; drum frame); flowing = |u_rel| > " + format_number(v_flow) +
                    " m/s; layer_thickness: area of the flowing bed over the surface's chord (m); axis: small-particle "
                    "share within " + format_number(kAxisShare) + " D of the axis; packing_contrast: Fig. 7d "
                    "(packing_contrast.hpp); *_layer: the drum's own regions (layer_regions.hpp), r_core_layer = d - the "
                    "layer's thickness (its mean over t >= angle_from once there, else the present one), cells weighted by "
                    "their exact area inside each region; tracer_core_layer: the passive tracer's share tau/Phi of the core "
                    "(NaN without a tracer); points_core_layer: of the material points (four per bed cell at t = 0, carried "
                    "through the velocity relative to the drum, material_points.hpp) within the core, the share that "
                    "started where the tracer's share is >= 1/2 (NaN without a tracer)");
    PackingContrastOptions contrast_options;
    contrast_options.bed_level = level, contrast_options.v_flow = v_flow, contrast_options.bin = drum.diameter / 20;
    TimeAverage angle(options.run.angle_from), layer(options.run.angle_from);  // time averages from angle_from
    BoundsMonitor bounds;
    double small_change = 0, large_change = 0, surface_angle = 0, axis = 0;
    const LayerRegions own_regions(grid, closest_surface_distance(drum), drum.radius(), kAxisShare * drum.diameter);
    LayerRegionShares own;
    double tracer_core = NAN, points_core = NAN;
    std::optional<MaterialPoints> points;
    if (tumbler.setup().tracer0) points.emplace(grid, flow.Phi(), level, tumbler.setup().tracer0);
    PatternMetrics metrics;
    PackingContrast contrast;
    int snapshot = 0, frame = 0;
    double next_history = 0.0, next_snapshot = 0.0, next_frame = 0.0;
    const double frame_every = options.frames > 0 ? t_end / options.frames : INFINITY;
    const auto due = [&](double next) { return flow.time() >= next - 1e-12 || flow.time() >= t_end; };
    const auto sample = [&] {
        if (!due(next_history) && !(options.run.vtk && due(next_snapshot)) && !due(next_frame)) return;
        tumbler.synchronise();
        if (due(next_history)) {
            next_history += kDrumHistoryInterval;
            const std::array<double, 2> amount = phase_amounts(tumbler);
            small_change = (amount[0] - amount0[0]) / amount_all, large_change = (amount[1] - amount0[1]) / amount_all;
            bounds.observe(grid, tumbler.phi(), flow.Phi());
            check_segregation_invariants("tumbler", bounds, tumbler.largest_correction(), amount0[0], amount[0],
                                         amount_all, kTumblerMassTolerance, true, Phi_max);
            if (!(std::fabs(large_change) <= kTumblerMassTolerance))
                throw InvariantError("tumbler: the amount of large particles changed by " + format_number(large_change, 3) +
                                     " (relative to all material) by t = " + format_number(flow.time()) + " s");
            const DrumState d = drum_state(flow, level, 0.8 * drum.radius(), v_flow, &shape);
            surface_angle = d.surface_angle_deg;
            const double thickness = flowing_layer_thickness(d, shape);
            angle.add(flow.time(), surface_angle);
            layer.add(flow.time(), thickness);
            metrics = pattern_metrics(grid, tumbler.phi(), flow.Phi(), options.regions, hat0);
            axis = disc_share(grid, tumbler.phi(), flow.Phi(), kAxisShare * drum.diameter, level);
            contrast = packing_contrast(tumbler, surface_angle, contrast_options);
            const double delta = layer.samples() > 0 ? layer.mean() : thickness;
            own = own_regions.shares(tumbler.phi(), flow.Phi(), delta, level);
            if (!tumbler.tracer().empty()) tracer_core = own_regions.shares(tumbler.tracer(), flow.Phi(), delta, level).core;
            if (points) points_core = points->marked_share_within(own.r_core);
            history.row({flow.time(), static_cast<double>(flow.steps()), amount[0], amount[1], metrics.index, surface_angle,
                         metrics.ring, metrics.periphery, metrics.core, small_change, large_change, d.flowing_fraction,
                         d.max_speed, static_cast<double>(tumbler.segregation_substeps()), flow.last_dt(), thickness, axis,
                         contrast.contrast, own.r_core, own.core, own.ring, own.periphery, own.axis, tracer_core,
                         points_core});
        }
        if (options.run.vtk && due(next_snapshot)) {
            next_snapshot += options.run.snapshot_every;
            out.add(numbered("vtk/tumbler_%04d.vtk", snapshot++), coupled_vtk(tumbler));
        }
        if (due(next_frame)) {
            next_frame += frame_every;
            out.add(numbered("frames/frame_%03d.dat", frame++), coupled_composition(tumbler, level));
        }
    };
    sample();
    Progress progress("tumbler", t_end);
    while (flow.time() < t_end) {
        const double dt = tumbler.step(t_end);
        if (points) points->advance(flow.u(0), flow.u(2), dt);
        if (observer) observer(tumbler);
        sample();
        progress.update(flow.time());
    }
    const RunTime cost = progress.finish(run_threads(grid.cells()));
    std::vector<std::string> columns{"t_end", "steps", "substeps", "segregation_steps", "angle_mean_deg", "angle_std_deg",
                                     "angle_samples", "mass_small_change", "mass_large_change", "segregation_index", "ring",
                                     "periphery", "core", "initial_mixture", "packing_feedback", "packing_contrast",
                                     "packing_spread", "contrast_bins", "largest_bulk_clip", "largest_segregation_clip",
                                     "seconds_flow", "seconds_bulk", "seconds_segregation", "seconds_feedback", "inside_cells"};
    std::vector<double> values{flow.time(), static_cast<double>(flow.steps()), static_cast<double>(tumbler.segregation_substeps()),
                               static_cast<double>(tumbler.segregation_steps()), angle.mean(), angle.std_dev(),
                               static_cast<double>(angle.samples()), small_change, large_change, metrics.index, metrics.ring,
                               metrics.periphery, metrics.core, tumbler.initial_mixture(),
                               tumbler.setup().packing_feedback ? 1.0 : 0.0, contrast.contrast, contrast.spread,
                               static_cast<double>(contrast.bins), tumbler.largest_bulk_clip(), tumbler.largest_correction(),
                               tumbler.timers().flow, tumbler.timers().bulk, tumbler.timers().segregation, tumbler.timers().feedback,
                               static_cast<double>(grid.inside_cells())};
    append_flow_work(flow, columns, values);
    for (const char* c : {"layer_mean", "layer_std", "axis", "r_core_layer", "core_layer", "ring_layer", "periphery_layer", "axis_layer",
                          "tracer_core_layer", "points_core_layer"})
        columns.push_back(c);
    for (double v : {layer.mean(), layer.std_dev(), axis, own.r_core, own.core, own.ring, own.periphery, own.axis, tracer_core,
                      points_core})
        values.push_back(v);
    append_run_time(cost, columns, values);
    DataTable summary(columns);
    summary.comment("angle: mean over t >= " + format_number(options.run.angle_from) +
                    " s; pattern metrics at t_end (regions r_core " + format_number(options.regions.r_core) + ", r_ring " +
                    format_number(options.regions.r_ring) + ", r_periphery " + format_number(options.regions.r_periphery) +
                    " m); layer: mean and standard deviation of the flowing layer's thickness (m) over the angle's "
                    "samples; axis: small-particle share within " + format_number(kAxisShare) +
                    " D of the axis at t_end; *_layer: as history.dat at t_end; packing contrast (Fig. 7d): packing_contrast.hpp, bins of " + format_number(contrast_options.bin) +
                    " m; clips: largest round-off corrections of phi; seconds: wall time of the step's parts (flow, bulk "
                    "transport, segregation sub-steps, closures from phi_hat); flow work: flow_output.hpp append_flow_work; wall_seconds, cpu_seconds (all threads), threads: the run's cost");
    summary.row(values);
    out.add("history.dat", history);
    out.add("summary.dat", summary);
    out.add("fields_lab.dat", coupled_field_table(tumbler));
    return out;
}

}  // namespace granseg
