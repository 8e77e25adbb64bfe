#include "tumbler/tumbler_run.hpp"

#include "core/error.hpp"
#include "core/format.hpp"
#include "core/progress.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <string>

namespace granseg {

namespace {

/// Throws InvariantError if phi left [0, Phi] by more than round-off after the bulk step (the
/// segregation sub-step's excursions are checked through its round-off guard).
void check_bulk_bounds(const BoundsMonitor& b, double Phi_max, double t) {
    const double allowance = kBoundRoundOff * Phi_max;
    if (b.nonfinite > 0) throw InvariantError("tumbler-kinematic: non-finite phi after the bulk step at t = " + format_number(t));
    if (b.max_excess > allowance || b.min_phi < -allowance)
        throw InvariantError("tumbler-kinematic: the bulk step left 0 <= phi <= Phi at t = " + format_number(t) +
                             " (max phi - Phi " + format_number(b.max_excess, 3) + ", min phi " + format_number(b.min_phi, 3) +
                             ")");
}

/// Folds the extremes of one step into those of the run.
void merge(BoundsMonitor& run, const BoundsMonitor& step) {
    if (step.max_excess > run.max_excess) run.max_excess = step.max_excess, run.where_excess = step.where_excess;
    if (step.min_phi < run.min_phi) run.min_phi = step.min_phi, run.where_min = step.where_min;
    run.nonfinite += step.nonfinite;
}

/// A resumed run continues on the sample and frame times of this run: the last ones the checkpoint
/// recorded must be this run's (an extension to a later t_end keeps their spacing: t_end/samples
/// and t_end/frames as in the run that wrote it). InputError otherwise.
void check_continuation(const std::string& file, const TumblerRunResult& result, int next_sample,
                        const std::function<double(int)>& sample_time, int next_frame,
                        const std::function<double(int)>& frame_time) {
    const auto check = [&](const char* key, double recorded, double here, double spacing) {
        if (recorded != here)
            throw InputError(file + ": [output] " + key + ": the checkpoint's last one is at t = " + format_exact(recorded) +
                             " s, this scene's at t = " + format_exact(here) + " s (allowed: the checkpoint's spacing, " +
                             format_exact(spacing) + " s, up to the new t_end)");
    };
    const auto& h = result.history;
    if (h.size() >= 2) check("samples", h.back().t, sample_time(next_sample - 1), h[1].t - h[0].t);
    const auto& f = result.frames;
    if (!f.empty()) check("frames", f.back().t, frame_time(next_frame - 1), f.size() >= 2 ? f[1].t - f[0].t : f[0].t - h[0].t);
}

}  // namespace

TumblerRunResult run_kinematic_tumbler(KinematicTumbler& tumbler, const TumblerRunOptions& options,
                                       const TumblerStepObserver& observer, RunCheckpoints* checkpoints) {
    if (!(options.t_end > tumbler.time()) || options.samples < 1 || options.frames < 0)
        throw InputError("tumbler run: needs t_end > t, samples >= 1, frames >= 0");
    const Grid& grid = tumbler.grid();
    const std::vector<double>& Phi = tumbler.Phi();
    const double Phi_max = *std::max_element(Phi.begin(), Phi.end());
    TumblerRunResult result;
    result.phi_hat_initial = composition_field(grid, tumbler.phi(), Phi);
    result.mass_start = total_amount(grid, tumbler.phi());
    const auto record = [&](double t) {
        result.history.push_back({t, pattern_metrics(grid, tumbler.phi(), Phi, options.regions, result.phi_hat_initial)});
    };
    const double t0 = tumbler.time(), span = options.t_end - t0;
    int next_sample = 1, next_frame = 1;
    // Steps land on the sample and frame times, so the state at t_end is on the path of a longer
    // run with the same spacing: no state is kept before the last step (longest step 0).
    RunCheckpoints& saves = checkpoints_or_none(checkpoints);
    const RunState state = [&](StateIO& io) {
        io("kinematic", tumbler)("result", result)("next_sample", next_sample)("next_frame", next_frame);
    };
    const auto sample_time = [&](int n) { return n == options.samples ? options.t_end : t0 + span * n / options.samples; };
    const auto frame_time = [&](int n) { return n == options.frames ? options.t_end : t0 + span * n / options.frames; };
    if (!saves.resume(options.t_end, state))
        record(t0);
    else
        check_continuation(saves.path(), result, next_sample, sample_time, next_frame, frame_time);
    Progress progress("tumbler-kinematic", options.t_end, tumbler.time());
    BoundsMonitor step_bulk;
    std::vector<double> phi_after_bulk;  // kept only for an observer
    const auto after_bulk = [&](const std::vector<double>& phi) {
        step_bulk = BoundsMonitor{};
        step_bulk.observe(grid, phi, Phi);
        if (observer) phi_after_bulk.assign(phi.begin(), phi.end());
    };
    while (next_sample <= options.samples) {
        const double t_sample = sample_time(next_sample);
        const double t_frame = next_frame <= options.frames ? frame_time(next_frame) : t_sample;
        const double target = std::min(t_sample, t_frame), remaining = target - tumbler.time();
        const bool lands = remaining <= tumbler.time_step();  // this step ends at the target
        tumbler.step(lands ? remaining : tumbler.time_step(), after_bulk);
        check_bulk_bounds(step_bulk, Phi_max, tumbler.time());
        merge(result.after_bulk, step_bulk);
        if (observer) observer(tumbler, step_bulk, phi_after_bulk);
        if (lands && t_frame == target && next_frame <= options.frames) {
            result.frames.push_back({target, composition_field(grid, tumbler.phi(), Phi)});
            ++next_frame;
        }
        if (lands && t_sample == target) {
            record(target);
            result.after_segregation.observe(grid, tumbler.phi(), Phi);  // finite values; the clip keeps the bounds
            check_segregation_invariants("tumbler-kinematic", result.after_segregation, tumbler.largest_correction(),
                                         result.mass_start, total_amount(grid, tumbler.phi()), result.mass_start,
                                         kTumblerMassTolerance, true, Phi_max);
            ++next_sample;
        }
        progress.update(tumbler.time());
        saves.after_step(tumbler.time(), tumbler.steps(), state);
    }
    saves.finish(tumbler.time(), tumbler.steps(), state);
    progress.finish();
    result.mass_end = total_amount(grid, tumbler.phi());
    return result;
}

PatternRegions default_regions(const RollingDrumFlow& flow) {
    return drum_regions(flow.surface_distance(), flow.parameters().layer_thickness, flow.radius());
}

}  // namespace granseg
