#include "harness/fig7_report.hpp"

#include "core/output.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <sstream>

namespace granseg::verify {

namespace {

const char* const kSeries[] = {"default", "explicit", "dt", "tracer"};
// An observed order outside [1/2, 2] times the formal order says the grids are not in the
// asymptotic range: the extrapolation is reported but flagged, and its GCI formed with a limited
// order and Fs = 3 (grid_convergence.hpp).

int series_code(const std::string& s) {
    for (int i = 0; i < 4; ++i)
        if (s == kSeries[i]) return i;
    return -1;
}

/// The range rule for values whose abscissae do not increase (a dt study whose step bounds held
/// dt): no order, the whole range as the uncertainty; all NaN if a value is undefined (a contrast
/// without depth bins holding both kinds of cell).
GridConvergence range_of(const std::vector<double>& f) {
    GridConvergence g;
    const double nan = std::numeric_limits<double>::quiet_NaN();
    g.condition = Convergence::undetermined, g.R = g.p = g.f_ext = g.asymptotic = g.fs = nan;
    g.lo = *std::min_element(f.begin(), f.end()), g.hi = *std::max_element(f.begin(), f.end());
    g.uncertainty = g.hi - g.lo;
    if (!std::all_of(f.begin(), f.end(), [](double v) { return std::isfinite(v); })) g.lo = g.hi = g.uncertainty = nan;
    return g;
}

Fig7Estimate estimate(int q, const std::string& series, const std::vector<const Fig7Result*>& runs, bool dt_axis) {
    Fig7Estimate e;
    e.quantity = q, e.series = series;
    const std::size_t n = std::min<std::size_t>(runs.size(), 3);
    for (std::size_t i = 0; i < n; ++i) {
        e.h.push_back(dt_axis ? runs[i]->dt_mean : runs[i]->h);
        e.f.push_back(runs[i]->value[q]);
        e.se = std::max(e.se, runs[i]->sampling[q]);
    }
    const bool increasing = std::is_sorted(e.h.begin(), e.h.end()) && std::adjacent_find(e.h.begin(), e.h.end()) == e.h.end();
    const bool defined = std::all_of(e.f.begin(), e.f.end(), [](double v) { return std::isfinite(v); });
    if (!increasing || !defined)
        e.g = range_of(e.f);
    else if (n == 3)
        e.g = three_grid_convergence({e.h[0], e.h[1], e.h[2]}, {e.f[0], e.f[1], e.f[2]}, 1.25, kFormalOrder);
    else
        e.g = two_grid_convergence({e.h[0], e.h[1]}, {e.f[0], e.f[1]}, kFormalOrder);
    for (std::size_t i = 0; i + 1 < n; ++i) e.noise = e.noise || std::fabs(e.f[i + 1] - e.f[i]) < 2.0 * e.se;
    return e;
}

/// A table cell: the number, or a dash where it is not defined.
std::string cell(double v, int digits = 4) { return std::isnan(v) ? "–" : fig7_number(v, digits); }

std::string condition_text(const Fig7Estimate& e) {
    std::string s = convergence_name(e.g.condition);
    if (e.g.condition == Convergence::monotone && e.g.p_gci != e.g.p)
        s += ", p far from " + fig7_number(kFormalOrder) + ": GCI with p = " + fig7_number(e.g.p_gci, 3) + ", Fs = 3";
    if (e.noise) s += ", within noise";
    return s;
}

std::string series_text(const Fig7Estimate& e, const Fig7Analysis& a) {
    if (e.series == "dt") return "default, dt_max x 0.5 / 1 / 2 at " + std::to_string(a.runs(Fig7Kind::dt, false)[0]->run.cells) + " cells";
    if (e.series == "tracer") return "tracer in the core (S = 0)";
    return e.series + " time stepping";
}

}  // namespace

std::string fig7_number(double v, int digits) {
    if (std::isnan(v)) return "nan";
    char s[32];
    std::snprintf(s, sizeof s, "%.*g", digits, v);
    return s;
}

const Fig7Estimate* Fig7Analysis::find(int quantity, const std::string& series) const {
    for (const Fig7Estimate& e : estimates)
        if (e.quantity == quantity && e.series == series) return &e;
    return nullptr;
}

std::vector<const Fig7Result*> Fig7Analysis::runs(Fig7Kind kind, bool explicit_steps) const {
    std::vector<const Fig7Result*> out;
    for (const Fig7Result& r : results)
        if (r.run.kind == kind && r.run.explicit_steps == explicit_steps) out.push_back(&r);
    std::sort(out.begin(), out.end(), [&](const Fig7Result* a, const Fig7Result* b) {
        return kind == Fig7Kind::dt ? a->run.dt_factor < b->run.dt_factor : a->run.cells > b->run.cells;
    });
    return out;
}

const Fig7Result& Fig7Analysis::finest() const { return *runs(Fig7Kind::grid, false).front(); }

double Fig7Analysis::reference(int q) const {
    const Fig7Estimate* e = find(q, "default");
    return e->g.condition == Convergence::monotone ? e->g.f_ext : e->f[0];
}

double Fig7Analysis::reference_uncertainty(int q) const { return find(q, "default")->g.uncertainty; }

std::string Fig7Analysis::reference_note(int q) const {
    return find(q, "default")->g.condition == Convergence::monotone
               ? "the default series' extrapolated value"
               : "the finest default run (" + convergence_name(find(q, "default")->g.condition) + ": no extrapolation)";
}

Fig7Analysis analyse_fig7(std::vector<Fig7Result> results, const Fig7Options& o) {
    Fig7Analysis a;
    a.results = std::move(results);
    const auto grid_default = a.runs(Fig7Kind::grid, false), grid_explicit = a.runs(Fig7Kind::grid, true);
    std::vector<const Fig7Result*> dt;
    if (o.dt_study) {
        const auto changed = a.runs(Fig7Kind::dt, false);  // dt_max x 0.5, x 2
        const int n = changed[0]->run.cells;
        const auto middle = std::find_if(grid_default.begin(), grid_default.end(), [&](const Fig7Result* r) { return r->run.cells == n; });
        dt = {changed[0], *middle, changed[1]};
    }
    for (int q = 0; q < kFig7Quantities; ++q) {
        a.estimates.push_back(estimate(q, "default", grid_default, false));
        if (grid_explicit.size() >= 2) a.estimates.push_back(estimate(q, "explicit", grid_explicit, false));
        if (!dt.empty()) a.estimates.push_back(estimate(q, "dt", dt, true));
    }
    const auto tracer = a.runs(Fig7Kind::tracer, false);
    const int core = 5;  // fig7_quantities(): the core's share, for the tracer its retained share
    if (tracer.size() >= 2) a.estimates.push_back(estimate(core, "tracer", tracer, false));
    return a;
}

void write_fig7_convergence(const Fig7Analysis& a, const Fig7Options& o) {
    const auto& quantities = fig7_quantities();
    std::vector<std::string> columns{"kind", "explicit", "cells", "h_mm", "dt_factor", "dt_mean_ms", "steps", "wall_s", "cpu_s"};
    for (const Fig7Quantity& q : quantities) columns.push_back(q.name), columns.push_back(std::string(q.name) + "_se");
    DataTable runs(columns);
    runs.comment("bench_fig7_convergence: one row per run; kind 0 grid, 1 dt, 2 tracer, 3 floor (T_floor " +
                 fig7_number(o.T_floor_low) + "), 4 tracer at that floor; explicit 1 for the explicit time stepping; "
                 "dt_mean = t_end/steps; wall and CPU (all threads) time on " + std::to_string(o.threads) + " threads; each quantity (angle deg, layer mm) "
                 "and its sampling error (_se: standard error of the time average over t >= " + fig7_number(o.average_from) +
                 " s, or the jitter over the last " + fig7_number(o.jitter_window) + " s of a value at t_end = " +
                 fig7_number(o.t_end) + " s)");
    for (const Fig7Result& r : a.results) {
        std::vector<double> row{static_cast<double>(r.run.kind), r.run.explicit_steps ? 1.0 : 0.0, static_cast<double>(r.run.cells),
                                1e3 * r.h, r.run.dt_factor, 1e3 * r.dt_mean, r.steps, r.wall, r.cpu};
        for (int q = 0; q < kFig7Quantities; ++q) row.push_back(r.value[q]), row.push_back(r.sampling[q]);
        runs.row(row);
    }
    write_file_atomically(o.data_dir + "/fig7_runs.dat", runs.str());

    DataTable conv({"quantity", "series", "runs", "x1", "f1", "f_ext", "gci", "lo", "hi", "condition", "R", "p", "asymptotic",
                    "se", "noise"});
    conv.comment("bench_fig7_convergence: quantity 0..7 = angle layer index ring periphery core contrast axis; series 0 default "
                 "(h), 1 explicit (h), 2 dt (default, mean dt), 3 tracer (core); x1 = finest h (mm) or dt (ms); gci = the "
                 "uncertainty of f1 (GCI when monotone or two grids, else half the range if oscillatory, the range if "
                 "divergent or undetermined); condition 0 monotone, 1 oscillatory, 2 divergent, 3 undetermined, 4 two grids; "
                 "se: largest sampling error of the runs; noise 1: a difference between runs below 2 se");
    std::ostringstream md;
    md << "| quantity | series | values, fine to coarse | R | condition | p | extrapolated | GCI (or range rule) | range | "
          "sampling error |\n|---|---|---|---|---|---|---|---|---|---|\n";
    for (const Fig7Estimate& e : a.estimates) {
        const GridConvergence& g = e.g;
        conv.row({static_cast<double>(e.quantity), static_cast<double>(series_code(e.series)), static_cast<double>(e.f.size()),
                  1e3 * e.h[0], e.f[0], g.f_ext, g.uncertainty, g.lo, g.hi, static_cast<double>(g.condition), g.R, g.p,
                  g.asymptotic, e.se, e.noise ? 1.0 : 0.0});
        const Fig7Quantity& q = quantities[e.quantity];
        std::string values;
        for (double f : e.f) values += (values.empty() ? "" : ", ") + fig7_number(f);
        const std::string label = e.series == "tracer" ? "core: share of its t = 0 material" : q.label;
        md << "| " << label << (std::string(q.unit) == "-" ? "" : " (" + std::string(q.unit) + ")") << " | " << series_text(e, a)
           << " | " << values << " | " << cell(g.R, 3) << " | " << condition_text(e) << " | " << cell(g.p, 3) << " | "
           << cell(g.f_ext) << " | " << cell(g.uncertainty, 3) << " | " << cell(g.lo) << " – " << cell(g.hi) << " | "
           << cell(e.se, 2) << " |\n";
    }
    std::string cells, explicit_cells;
    for (int n : o.cells) cells += (cells.empty() ? "" : ", ") + std::to_string(n);
    for (int n : o.explicit_cells) explicit_cells += (explicit_cells.empty() ? "" : ", ") + std::to_string(n);
    md << "\nWritten by `bench_fig7_convergence`: " << cells << " cells per diameter (default time stepping), "
       << (explicit_cells.empty() ? "none" : explicit_cells) << " (explicit), t_end = " << fig7_number(o.t_end)
       << " s, angle and layer averaged over t >= " << fig7_number(o.average_from)
       << " s, the other quantities at t_end (sampling error: their jitter over the last " << fig7_number(o.jitter_window)
       << " s). GCI: Fs = 1.25 with three grids, 3 with two (order " << fig7_number(kFormalOrder)
       << " assumed) and with three grids whose observed order is far from it.\n";
    write_file_atomically(o.data_dir + "/fig7_convergence.dat", conv.str());
    write_file_atomically(o.data_dir + "/fig7_convergence.md", md.str());
}

}  // namespace granseg::verify
