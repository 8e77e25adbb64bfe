#include "study/dt_study.hpp"

#include "coupled/coupled_tumbler.hpp"
#include "harness/table_provenance.hpp"
#include "run/output.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <sstream>
#include <tuple>

namespace granseg::verify {

namespace {

/// NAME of a run: PART_TRANSPORT_nCELLS_STEP, STEP dtDT or "default" ("feedback_muscl_n50_dt0.002").
std::string run_name(bool feedback, const std::string& transport, int cells, const std::string& step) {
    return std::string(feedback ? "feedback" : "nofeedback") + "_" + transport + "_n" + std::to_string(cells) + "_" + step;
}
std::string run_name(bool feedback, const std::string& transport, int cells, double dt) {
    char step[40];
    std::snprintf(step, sizeof step, "dt%g", dt);
    return run_name(feedback, transport, cells, step);
}

/// A table cell: the number, or a dash where it is not defined.
std::string dt_cell(double v, int digits = 4) { return std::isfinite(v) ? fig7_number(v, digits) : "–"; }

/// The value and its time error at the default step as a table cell: "error" for a converging
/// series, "< bound (condition)" where no limit is formed.
std::string error_cell(const DtEstimate& d, int digits) {
    if (std::isfinite(d.error))
        return fig7_number(d.error, digits) +
               (d.e.g.condition == Convergence::two_grids ? " (order 1 assumed)" : " (p " + dt_cell(d.e.g.p, 2) + ")");
    return "< " + dt_cell(d.bound, digits) + " (" + convergence_name(d.e.g.condition) + ")";
}

int transport_code(const std::string& t) { return t == "muscl" ? 0 : 1; }

/// The cost runs' dt_max (--cost-dt-max), ascending, once each.
std::vector<double> cost_steps(const DtStudyOptions& o) {
    std::vector<double> steps = o.cost_dt_max;
    std::sort(steps.begin(), steps.end());
    steps.erase(std::unique(steps.begin(), steps.end()), steps.end());
    return steps;
}

}  // namespace

bool at_default_step(const Fig7Result& r) { return std::isnan(r.run.acoustic_courant_max); }

const std::vector<int>& dt_study_quantities() {
    static const std::vector<int> q{kAngle, kLayer, kIndex, kRing, kCore, kContrast, kAxis};
    return q;
}

std::string part_name(bool feedback) { return feedback ? "feedback" : "no feedback"; }

std::vector<Fig7Run> plan_dt_runs(const DtStudyOptions& o) {
    std::vector<Fig7Run> runs;
    // A series run and a cost run: dt_max as given, at the flow solver's acoustic Courant number
    // (the coupled drum's smaller default would set the larger steps); a default run: the scene's.
    const auto add = [&](const DtGrid& g, const std::string& t, bool feedback, double dt, bool default_step) {
        const std::string name = default_step ? run_name(feedback, t, g.cells, "default") : run_name(feedback, t, g.cells, dt);
        Fig7Run r{name, Fig7Kind::dt, false, g.cells, dt / g.dt_max.front(), t, dt};
        r.packing_feedback = feedback;
        if (!default_step) r.acoustic_courant_max = FlowSettings{}.acoustic_courant_max;
        for (const Fig7Run& earlier : runs)
            if (earlier.name == r.name) return;
        runs.push_back(r);
    };
    for (const DtGrid& g : o.grids)
        for (const std::string& t : o.run.transports)
            for (bool feedback : o.feedback)
                for (double dt : g.dt_max) add(g, t, feedback, dt, false);
    if (std::find(o.feedback.begin(), o.feedback.end(), true) == o.feedback.end()) return runs;
    for (const DtGrid& g : o.grids)
        for (const std::string& t : o.run.transports) {
            for (double dt : cost_steps(o)) add(g, t, true, dt, false);
            add(g, t, true, kCoupledDtMax, true);
        }
    return runs;
}

std::vector<DtEstimate> analyse_dt(const std::vector<Fig7Result>& results, const DtStudyOptions& o) {
    std::vector<DtEstimate> out;
    for (const DtGrid& g : o.grids)
        for (const std::string& t : o.run.transports)
            for (bool feedback : o.feedback) {
                std::vector<const Fig7Result*> series;  // smallest dt first (fine to coarse)
                for (const Fig7Result& r : results)
                    if (r.run.cells == g.cells && r.run.transport == t && r.run.packing_feedback == feedback &&
                        !at_default_step(r) && std::find(g.dt_max.begin(), g.dt_max.end(), r.run.dt_max) != g.dt_max.end())
                        series.push_back(&r);
                std::sort(series.begin(), series.end(),
                          [](const Fig7Result* a, const Fig7Result* b) { return a->dt_mean < b->dt_mean; });
                // A run whose mean step is within 1 % of a finer run's adds no point to the fit.
                series.erase(std::unique(series.begin(), series.end(),
                                         [](const Fig7Result* fine, const Fig7Result* coarse) {
                                             return coarse->dt_mean < 1.01 * fine->dt_mean;
                                         }),
                             series.end());
                if (series.size() < 2) continue;
                for (int q : dt_study_quantities()) {
                    if (q == kContrast && !feedback) continue;  // without feedback Phi does not follow phi_hat
                    DtEstimate d;
                    d.feedback = feedback, d.transport = t, d.cells = g.cells;
                    d.e = fig7_estimate(q, part_name(feedback) + " " + t, series, true);
                    d.at_default = d.e.f.back();
                    const Convergence c = d.e.g.condition;
                    const bool limit = (c == Convergence::monotone || c == Convergence::two_grids) && std::isfinite(d.e.g.f0);
                    d.error = limit ? d.at_default - d.e.g.f0 : std::numeric_limits<double>::quiet_NaN();
                    d.bound = limit ? std::fabs(d.error) : d.e.g.hi - d.e.g.lo;
                    out.push_back(d);
                }
            }
    return out;
}

void write_dt_study(const std::vector<Fig7Result>& results, const std::vector<DtEstimate>& estimates, const DtStudyOptions& o) {
    DataTable runs;
    runs.comment(
        "bench_time_step: one row per run of a series or of the cost runs (the default step's: time_step_cost.dat); "
        "transport 0 muscl, 1 donor-cell; se: sampling errors (time averages: "
        "standard error of the mean over t >= " +
        fig7_number(o.run.average_from) + " s; values at t_end: jitter over the last " + fig7_number(o.run.jitter_window) +
        " s)");
    // Per series largest dt_max first, so that a figure's lines run along dt_max.
    std::vector<const Fig7Result*> sorted;
    for (const Fig7Result& r : results)
        if (!at_default_step(r)) sorted.push_back(&r);
    std::stable_sort(sorted.begin(), sorted.end(), [](const Fig7Result* a, const Fig7Result* b) {
        return std::make_tuple(a->run.cells, a->run.transport, a->run.packing_feedback, -a->run.dt_max) <
               std::make_tuple(b->run.cells, b->run.transport, b->run.packing_feedback, -b->run.dt_max);
    });
    for (const Fig7Result* run : sorted) {
        const Fig7Result& r = *run;
        TableRow row{{"feedback", r.run.packing_feedback ? 1.0 : 0.0},
                     {"transport", static_cast<double>(transport_code(r.run.transport))},
                     {"cells", static_cast<double>(r.run.cells)},
                     {"dt_max", r.run.dt_max},
                     {"dt_mean", r.dt_mean},
                     {"dt_max_share", r.dt_max_share},
                     {"steps", r.steps},
                     {"wall_seconds", r.wall},
                     {"cpu_seconds", r.cpu}};
        for (int q : dt_study_quantities()) {
            const std::string name = fig7_quantities()[q].name;
            row.add(q == kLayer ? "layer_mm" : name, r.value[q]).add(name + "_se", r.sampling[q]);
        }
        runs.row(row);
    }
    write_file_atomically(o.run.data_dir + "/time_step_runs.dat", runs.str());

    DataTable points;
    points.comment(
        "bench_time_step: per series (feedback, transport 0 muscl / 1 donor-cell, cells) and quantity (index into "
        "fig7_quantities: 0 angle, 1 layer, 2 index, 3 ring, 5 core, 6 contrast, 7 axis) the runs' values against "
        "their mean time step, with the fit's limit f0 and order p (NaN where none); one gnuplot block per series");
    for (const DtEstimate& d : estimates) {
        for (std::size_t i = 0; i < d.e.h.size(); ++i)
            points.row({{"feedback", d.feedback ? 1.0 : 0.0},
                        {"transport", static_cast<double>(transport_code(d.transport))},
                        {"cells", static_cast<double>(d.cells)},
                        {"quantity", static_cast<double>(d.e.quantity)},
                        {"dt_mean", d.e.h[i]},
                        {"value", d.e.f[i]},
                        {"se", d.e.se[i]},
                        {"f0", d.e.g.f0},
                        {"p", d.e.g.p}});
        points.blank(), points.blank();  // a gnuplot block per series
    }
    write_file_atomically(o.run.data_dir + "/time_step.dat", points.str());

    // The markdown table: per series the value at the default step and its time error.
    std::ostringstream md;
    md << "| part | transport | cells | quantity | values, largest dt_max first | sampling error | condition | limit (dt → 0) "
          "| time error at the largest dt_max |\n|---|---|---|---|---|---|---|---|---|\n";
    for (const DtEstimate& d : estimates) {
        const Fig7Quantity& q = fig7_quantities()[d.e.quantity];
        const int digits = d.e.quantity == kAngle ? 4 : 3;
        std::string values;
        for (auto it = d.e.f.rbegin(); it != d.e.f.rend(); ++it)
            values += (values.empty() ? "" : ", ") + dt_cell(*it, digits + 1);
        md << "| " << part_name(d.feedback) << " | " << d.transport << " | " << d.cells << " | " << q.name << " (" << q.unit
           << ") | " << values << " | " << dt_cell(d.e.se_max, 2) << " | " << convergence_name(d.e.g.condition) << " | "
           << dt_cell(d.e.g.f0, digits + 1) << " | " << error_cell(d, 2) << " |\n";
    }
    std::string dts;
    for (const DtGrid& g : o.grids) {
        std::string list;
        for (double dt : g.dt_max) list += (list.empty() ? "" : ", ") + fig7_number(1e3 * dt);
        dts += (dts.empty() ? "" : "; ") + std::to_string(g.cells) + " cells: " + list + " ms";
    }
    md << "\ndt_max " << dts << "; t_end " << fig7_number(o.run.t_end)
       << " s, averages over t >= " << fig7_number(o.run.average_from) << " s. Written by bench_time_step.\n";
    write_generated_table(o.run.data_dir + "/time_step.md", md.str(), kDrumStudyParts);
}

std::vector<DtCost> dt_costs(const std::vector<Fig7Result>& results, const std::vector<DtEstimate>& estimates,
                             const DtStudyOptions& o) {
    std::vector<DtCost> out;
    for (const DtGrid& g : o.grids)
        for (const std::string& t : o.run.transports) {
            std::vector<const Fig7Result*> runs;  // the cost runs by dt_max, then the default step's
            for (double dt : cost_steps(o))
                for (const Fig7Result& r : results)
                    if (r.run.cells == g.cells && r.run.transport == t && r.run.packing_feedback && r.run.dt_max == dt &&
                        !at_default_step(r))
                        runs.push_back(&r);
            for (const Fig7Result& r : results)
                if (r.run.cells == g.cells && r.run.transport == t && at_default_step(r)) runs.push_back(&r);
            for (const Fig7Result* run : runs) {
                DtCost c;
                c.run = run;
                bool estimated = false;
                for (const DtEstimate& d : estimates) {
                    if (!d.feedback || d.cells != g.cells || d.transport != t) continue;
                    const int q = d.e.quantity;
                    const double v = c.run->value[q];
                    estimated = true;
                    c.error[q] = std::isfinite(d.error) ? v - d.e.g.f0 : std::numeric_limits<double>::quiet_NaN();
                    c.bound[q] = std::isfinite(d.error) ? std::fabs(c.error[q]) : std::max(d.e.g.hi, v) - std::min(d.e.g.lo, v);
                }
                if (estimated) out.push_back(c);
            }
        }
    return out;
}

void write_dt_costs(const std::vector<DtCost>& costs, const DtStudyOptions& o) {
    static const int shown[] = {kAngle, kIndex, kCore, kAxis};
    DataTable dat;
    dat.comment(
        "bench_time_step: error against cost, one row per run of the full model (feedback); transport 0 muscl, 1 "
        "donor-cell; acoustic_share: share of the steps the acoustic bound set; NAME_error: value less its series' "
        "limit (NaN where the series forms none), NAME_bound: |error| or the range of the series and the run; "
        "acoustic_courant_max: the run's bound on c dt/h; default_step 1: the coupled drum's default step");
    std::ostringstream md;
    md << "| transport | cells | dt_max (ms) | acoustic Courant number at most | mean step (ms) | steps | set by the acoustic "
          "bound | CPU s";
    for (int q : shown) md << " | " << fig7_quantities()[q].name << " error";
    md << " |\n|---|---|---|---|---|---|---|---|---|---|---|---|\n";
    for (const DtCost& c : costs) {
        const Fig7Result& r = *c.run;
        const bool default_step = at_default_step(r);
        const double courant = default_step ? kCoupledAcousticCourantMax : r.run.acoustic_courant_max;
        TableRow row{{"transport", static_cast<double>(transport_code(r.run.transport))},
                     {"cells", static_cast<double>(r.run.cells)},
                     {"dt_max", r.run.dt_max},
                     {"dt_mean", r.dt_mean},
                     {"steps", r.steps},
                     {"acoustic_share", r.acoustic_share},
                     {"cpu_seconds", r.cpu}};
        md << "| " << r.run.transport << " | " << r.run.cells << " | " << fig7_number(1e3 * r.run.dt_max) << " | "
           << fig7_number(courant) << (default_step ? " (the default step)" : "") << " | " << fig7_number(1e3 * r.dt_mean, 3)
           << " | " << fig7_number(r.steps, 5) << " | " << fig7_number(100 * r.acoustic_share, 3) << " % | "
           << fig7_number(r.cpu, 4);
        for (int q : shown) {
            const std::string name = fig7_quantities()[q].name;
            row.add(name + "_error", c.error[q]).add(name + "_bound", c.bound[q]);
            md << " | " << (std::isfinite(c.error[q]) ? fig7_number(c.error[q], 2) : "< " + dt_cell(c.bound[q], 2));
        }
        md << " |\n";
        dat.row(row.add("acoustic_courant_max", courant).add("default_step", default_step ? 1.0 : 0.0));
    }
    md << "\nErrors: the value less its series' dt → 0 limit (time_step.md), \"< x\" where the series forms no limit (its "
          "range and the run's). t_end "
       << fig7_number(o.run.t_end) << " s; CPU seconds of one thread. Written by bench_time_step.\n";
    write_file_atomically(o.run.data_dir + "/time_step_cost.dat", dat.str());
    write_generated_table(o.run.data_dir + "/time_step_cost.md", md.str(), kDrumStudyParts);
}

}  // namespace granseg::verify
