#include "kinematic/kinematic_run.hpp"

#include "core/error.hpp"
#include "core/format.hpp"

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

/// The sample and frame times of a run from t0 to t_end: every (t_end - t0)/samples and
/// (t_end - t0)/frames, the last of each t_end itself.
struct SampleTimes {
    double t0, t_end;
    int samples, frames;
    double sample(int n) const { return n == samples ? t_end : t0 + (t_end - t0) * n / samples; }
    double frame(int n) const { return n == frames ? t_end : t0 + (t_end - t0) * n / frames; }
};

/// A resumed run continues on the sample and frame times of this run: the last ones the checkpoint
/// recorded must be this run's (an extension to a later t_end keeps their spacing: t_end/samples
/// and t_end/frames as in the run that wrote it). InputError otherwise.
void check_continuation(const std::string& file, const KinematicRunResult& result, const SampleTimes& times, int next_sample,
                        int next_frame) {
    const auto check = [&](const char* key, double recorded, double here, double spacing) {
        if (recorded != here)
            throw InputError(file + ": [output] " + key + ": the checkpoint's last one is at t = " + format_exact(recorded) +
                             " s, this scene's at t = " + format_exact(here) + " s (allowed: the checkpoint's spacing, " +
                             format_exact(spacing) + " s, up to the new t_end)");
    };
    const auto& h = result.history;
    if (h.size() >= 2) check("samples", h.back().t, times.sample(next_sample - 1), h[1].t - h[0].t);
    const auto& f = result.frames;
    if (!f.empty()) check("frames", f.back().t, times.frame(next_frame - 1), f.size() >= 2 ? f[1].t - f[0].t : f[0].t - h[0].t);
}

/// What KinematicTumbler::step calls after its bulk step, with phi at that point.
using BulkObserver = std::function<void(const std::vector<double>& phi)>;

/// What a kinematic run records as it goes: steps that land on the sample and frame times, the
/// pattern metrics at each sample time with the invariants checked there, and phi_hat at each
/// frame time.
class KinematicRecord {
public:
    KinematicRecord(KinematicTumbler& tumbler, const KinematicRunOptions& options, KinematicRunResult& result)
        : tumbler_(tumbler),
          options_(options),
          result_(result),
          Phi_(tumbler.Phi()),
          Phi_max_(*std::max_element(Phi_.begin(), Phi_.end())),
          times_{tumbler.time(), options.t_end, options.samples, options.frames} {
        result.phi_hat_initial = composition_field(tumbler.grid(), tumbler.phi(), Phi_);
        result.mass_start = total_amount(tumbler.grid(), tumbler.phi());
    }
    bool done() const { return next_sample_ > options_.samples; }
    /// A fresh run's first record, or a resumed run's check that it continues this one.
    void begin(bool resumed, const RunCheckpoints* checkpoints) {
        if (resumed)
            check_continuation(checkpoints->path(), result_, times_, next_sample_, next_frame_);
        else
            record(times_.t0);
    }
    /// One step of the tumbler, shortened to land on the next sample or frame time.
    void step(const BulkObserver& after_bulk) {
        const double remaining = target() - tumbler_.time();
        lands_ = remaining <= tumbler_.time_step();
        tumbler_.step(lands_ ? remaining : tumbler_.time_step(), after_bulk);
    }
    /// The frame and the sample the last step landed on.
    void land() {
        if (!lands_) return;
        const double at = target();
        if (t_frame() == at && next_frame_ <= options_.frames) {
            result_.frames.push_back({at, composition_field(tumbler_.grid(), tumbler_.phi(), Phi_)});
            ++next_frame_;
        }
        if (t_sample() != at) return;
        record(at);
        result_.after_segregation.observe(tumbler_.grid(), tumbler_.phi(), Phi_);  // finite values; the clip keeps the bounds
        check_segregation_invariants("tumbler-kinematic", result_.after_segregation, tumbler_.largest_correction(),
                                     result_.mass_start, total_amount(tumbler_.grid(), tumbler_.phi()), result_.mass_start,
                                     kAmountTolerance, true, Phi_max_);
        ++next_sample_;
    }
    double Phi_max() const { return Phi_max_; }
    void checkpoint(StateIO& io) { io("result", result_)("next_sample", next_sample_)("next_frame", next_frame_); }

private:
    // The next sample and frame times; a run without frames has none: the sample time stands in.
    double t_sample() const { return times_.sample(next_sample_); }
    double t_frame() const { return next_frame_ <= options_.frames ? times_.frame(next_frame_) : t_sample(); }
    double target() const { return std::min(t_sample(), t_frame()); }
    void record(double t) {
        result_.history.push_back(
            {t, pattern_metrics(tumbler_.grid(), tumbler_.phi(), Phi_, options_.regions, result_.phi_hat_initial)});
    }

    KinematicTumbler& tumbler_;
    const KinematicRunOptions& options_;
    KinematicRunResult& result_;
    const std::vector<double>& Phi_;
    const double Phi_max_;
    const SampleTimes times_;
    int next_sample_ = 1, next_frame_ = 1;
    bool lands_ = false;  // the last step ended on the next sample or frame time
};

}  // namespace

KinematicRunResult run_kinematic_tumbler(KinematicTumbler& tumbler, const KinematicRunOptions& options,
                                         const KinematicStepObserver& observer, RunCheckpoints* checkpoints) {
    if (!(options.t_end > tumbler.time()) || options.samples < 1 || options.frames < 0)
        throw InputError("tumbler run: needs t_end > t, samples >= 1, frames >= 0");
    KinematicRunResult result;
    KinematicRecord record(tumbler, options, result);
    BoundsMonitor step_bulk;
    std::vector<double> phi_after_bulk;  // kept only for an observer
    const BulkObserver after_bulk = [&](const std::vector<double>& phi) {
        step_bulk = BoundsMonitor{};
        step_bulk.observe(tumbler.grid(), phi, tumbler.Phi());
        if (observer) phi_after_bulk.assign(phi.begin(), phi.end());
    };
    // Steps land on the sample and frame times, so the state at t_end is on the path of a longer
    // run with the same spacing: no state is kept before the last step (no longest_step).
    RunLoop loop;
    loop.label = "tumbler-kinematic", loop.t_end = options.t_end, loop.checkpoints = checkpoints;
    loop.state = [&](StateIO& io) {
        io("kinematic", tumbler);
        record.checkpoint(io);
    };
    loop.time = [&] { return tumbler.time(); };
    loop.steps = [&] { return tumbler.steps(); };
    loop.done = [&] { return record.done(); };
    loop.begin = [&](bool resumed) { record.begin(resumed, checkpoints); };
    loop.step = [&] { record.step(after_bulk); };
    loop.observers.push_back([&] {
        check_bulk_bounds(step_bulk, record.Phi_max(), tumbler.time());
        merge(result.after_bulk, step_bulk);
        if (observer) observer(tumbler, step_bulk, phi_after_bulk);
    });
    loop.observers.push_back([&] { record.land(); });
    run_loop(loop);
    result.mass_end = total_amount(tumbler.grid(), tumbler.phi());
    return result;
}

PatternRegions default_regions(const RollingDrumFlow& flow) {
    return drum_regions(flow.surface_distance(), flow.parameters().layer_thickness, flow.radius());
}

}  // namespace granseg
