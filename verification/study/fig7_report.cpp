#include "study/fig7_report.hpp"

#include "harness/table_provenance.hpp"
#include "run/output.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <sstream>

namespace granseg::verify {

namespace {

// Series codes of fig7_convergence.dat (the figure scripts read them): the reference transport's
// grid series, explicit, dt at the finest grid, tracer, the second transport's grid series, dt at
// the coarsest grid.
int series_code(const std::string& s, const Fig7Analysis& a) {
    if (s == a.reference_series) return 0;
    const char* const fixed[] = {"", "explicit", "dt finest", "tracer", "", "dt coarsest", "points"};
    for (int i = 1; i < 7; ++i)
        if (s == fixed[i]) return i;
    return 4;
}

/// Runs that allow no study (abscissae that do not increase: a dt study whose step bounds held
/// dt; or an undefined value: a contrast without depth bins holding both kinds of cell): no order,
/// the whole range as the uncertainty (NaN if a value is undefined).
GridConvergence range_of(const std::vector<double>& f) {
    GridConvergence g;
    const double nan = std::numeric_limits<double>::quiet_NaN();
    g.condition = Convergence::undetermined, g.grids = static_cast<int>(f.size());
    g.p = g.f0 = g.p_u = g.fs = g.eps = g.sigma = g.e_a = g.e_ext = g.chi2 = g.chi2_limit = g.data_range = nan;
    g.lo = *std::min_element(f.begin(), f.end()), g.hi = *std::max_element(f.begin(), f.end());
    g.uncertainty = g.hi - g.lo;
    if (!std::all_of(f.begin(), f.end(), [](double v) { return std::isfinite(v); })) g.lo = g.hi = g.uncertainty = nan;
    return g;
}

}  // namespace

Fig7Estimate fig7_estimate(int q, const std::string& series, const std::vector<const Fig7Result*>& runs, bool dt_axis) {
    Fig7Estimate e;
    e.quantity = q, e.series = series;
    for (const Fig7Result* r : runs) {
        // The points series: the material points' retained share in place of the core quantity.
        const bool points = series == "points";
        const double f = points ? r->points : r->value[q], se = points ? r->points_sampling : r->sampling[q];
        e.h.push_back(dt_axis ? r->dt_mean : r->h);
        e.f.push_back(f), e.se.push_back(se);
        if (std::isfinite(se)) e.se_max = std::max(e.se_max, se);
    }
    const bool increasing = std::is_sorted(e.h.begin(), e.h.end()) && std::adjacent_find(e.h.begin(), e.h.end()) == e.h.end();
    const bool defined = std::all_of(e.f.begin(), e.f.end(), [](double v) { return std::isfinite(v); });
    const Fig7Quantity& quantity = fig7_quantities()[q];
    e.g = increasing && defined ? grid_convergence(e.h, e.f, e.se, kFormalOrder, Bounds{quantity.lower, quantity.upper})
                                : range_of(e.f);
    return e;
}

namespace {

/// A table cell: the number, or a dash where it is not defined.
std::string cell(double v, int digits = 6) { return std::isnan(v) ? "–" : fig7_number(v, digits); }

std::string condition_text(const Fig7Estimate& e) {
    std::string s = convergence_name(e.g.condition);
    if (e.g.condition == Convergence::monotone && !(e.g.sigma < e.g.data_range)) s += ", poor fit (sigma >= data range)";
    return s;
}

std::string flags_text(const Fig7Estimate& e) {
    if (!e.g.outside_bounds) return "";
    const Fig7Quantity& q = fig7_quantities()[e.quantity];
    return "limit outside [" + fig7_number(q.lower) + ", " + fig7_number(q.upper) + "]: fit used outside its range";
}

std::string series_text(const Fig7Estimate& e, const Fig7Analysis& a) {
    if (e.series == "tracer") return "tracer in the core (full model)";
    if (e.series == "points") return "material points in the core (no numerical diffusion)";
    if (e.series == "explicit") return "explicit time stepping";
    if (e.series.rfind("dt ", 0) == 0) {
        const int n =
            e.series == "dt finest" ? a.finest().run.cells : a.runs(Fig7Kind::grid, false, a.reference_series).back()->run.cells;
        std::string factors;
        for (const Fig7Result* r : a.dt_runs(n)) factors += (factors.empty() ? "" : " / ") + fig7_number(r->run.dt_factor);
        return a.reference_series + ", dt x " + factors + " at " + std::to_string(n) + " cells";
    }
    return e.series + ", dt ~ h";
}

/// The direction refinement moves a series (fine to coarse values): "lowers it", "raises it", or
/// "" where the differences change sign.
std::string refinement_trend(const Fig7Estimate& e) {
    bool up = true, down = true;
    for (std::size_t i = 0; i + 1 < e.f.size(); ++i) up = up && e.f[i] > e.f[i + 1], down = down && e.f[i] < e.f[i + 1];
    return up ? "each refinement raises it" : down ? "each refinement lowers it" : "";
}

/// The verdict on a quantity from its reference series; where the series does not converge, the
/// direction refinement moves it (the sign of the finest value's bias, where it has one).
std::string verdict(const Fig7Estimate& e) {
    const GridConvergence& g = e.g;
    const std::string trend = refinement_trend(e);
    switch (g.condition) {
        case Convergence::monotone:
            return g.outside_bounds ? "limit outside the physical range: not established"
                                    : "converges (p = " + fig7_number(g.p, 3) + "), limit " + fig7_number(g.f0);
        case Convergence::within_noise:
            return "grid differences within the sampling errors: no trend resolved";
        case Convergence::two_grids:
            return "two grids: order assumed";
        default:
            return "not converged (" + convergence_name(g.condition) + (trend.empty() ? "" : "; " + trend) + "): range " +
                   fig7_number(g.lo) + " – " + fig7_number(g.hi);
    }
}

/// DIR/fig7_summary.md: per quantity the value at the paper's grid (100 cells per diameter, or the
/// finest), the limit, the band of the finest run and the verdict (the full table:
/// fig7_convergence.md).
void write_fig7_summary(const Fig7Analysis& a, const Fig7Options& o) {
    constexpr int kPaperCells = 100;
    const auto grid = a.runs(Fig7Kind::grid, false, a.reference_series);
    const auto paper = std::find_if(grid.begin(), grid.end(), [](const Fig7Result* r) { return r->run.cells == kPaperCells; });
    const Fig7Result& shown = paper != grid.end() ? **paper : a.finest();
    const int fine = a.finest().run.cells;
    std::ostringstream md;
    md << "| quantity | at " << shown.run.cells << " cells | its distance to the limit | at " << fine << " cells | band of the "
       << fine << "-cell value | its range | limit | verdict |\n|---|---|---|---|---|---|---|---|\n";
    for (int q = 0; q < kFig7Quantities; ++q) {
        const Fig7Quantity& quantity = fig7_quantities()[q];
        const Fig7Estimate& e = *a.find(q, a.reference_series);
        const bool limit = e.g.condition == Convergence::monotone && !e.g.outside_bounds;
        const auto [lo, hi] = a.band_range(q);
        md << "| " << quantity.label << (std::string(quantity.unit) == "-" ? "" : " (" + std::string(quantity.unit) + ")")
           << " | " << fig7_number(shown.value[q]) << " ± " << fig7_number(shown.sampling[q], 2) << " | "
           << (limit ? fig7_number(shown.value[q] - e.g.f0, 3) : "–") << " | " << fig7_number(a.finest().value[q]) << " | "
           << fig7_number(a.band(q), 3) << " | " << fig7_number(lo, 4) << " – " << fig7_number(hi, 4) << " | "
           << (limit ? fig7_number(e.g.f0) : "–") << " | " << verdict(e) << " |\n";
    }
    md << "\nWritten by `bench_fig7_convergence`: the " << a.reference_series << " transport, dt_max "
       << fig7_number(1e3 * o.dt_ref)
       << " ms × 50/cells; ± after a value: its sampling error; distance: the value minus the limit (its bias, where the series "
          "converges); band: the finest value's grid uncertainty (the series' U) plus its time-step uncertainty (the time-step "
          "study at the finest grid, at this run's step), and its range the band clipped to the quantity's physical range. Every "
          "series and number: `fig7_convergence.md`.\n";
    write_generated_table(o.data_dir + "/fig7_summary.md", md.str(), kDrumStudyParts);
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

std::vector<const Fig7Result*> Fig7Analysis::runs(Fig7Kind kind, bool explicit_steps, const std::string& transport) const {
    std::vector<const Fig7Result*> out;
    for (const Fig7Result& r : results)
        if (r.run.kind == kind && r.run.explicit_steps == explicit_steps && (transport.empty() || r.run.transport == transport))
            out.push_back(&r);
    std::sort(out.begin(), out.end(), [&](const Fig7Result* a, const Fig7Result* b) { return a->run.cells > b->run.cells; });
    return out;
}

std::vector<const Fig7Result*> Fig7Analysis::dt_runs(int cells) const {
    std::vector<const Fig7Result*> out;
    for (const Fig7Result& r : results)
        if ((r.run.kind == Fig7Kind::dt || (r.run.kind == Fig7Kind::grid && r.run.transport == reference_series)) &&
            r.run.cells == cells)
            out.push_back(&r);
    std::sort(out.begin(), out.end(),
              [](const Fig7Result* a, const Fig7Result* b) { return a->run.dt_factor < b->run.dt_factor; });
    return out;
}

const Fig7Result& Fig7Analysis::finest() const { return *runs(Fig7Kind::grid, false, reference_series).front(); }

const Fig7Result& Fig7Analysis::loosest_run() const {
    const Fig7Result* loosest = nullptr;
    for (const Fig7Result& r : results)
        if (!r.run.explicit_steps && (!loosest || r.dt_max_share < loosest->dt_max_share)) loosest = &r;
    return *loosest;
}

const Fig7Result& Fig7Analysis::reference_run() const { return *dt_runs(finest().run.cells).front(); }

double Fig7Analysis::band(int q) const {
    // The finest grid run is the dt study's run with the largest step, its last.
    const Fig7Estimate* dt = find(q, "dt finest");
    return find(q, reference_series)->g.uncertainty + (dt ? uncertainty_at(dt->g, dt->h, dt->f, dt->h.size() - 1) : 0.0);
}

double Fig7Analysis::reference_band(int q) const {
    // The reference run is the dt study's run with the smallest step, its first.
    const Fig7Estimate* dt = find(q, "dt finest");
    return find(q, reference_series)->g.uncertainty + (dt ? dt->g.uncertainty : 0.0);
}

std::pair<double, double> Fig7Analysis::band_range(int q) const {
    const Fig7Quantity& quantity = fig7_quantities()[q];
    const double f1 = finest().value[q];
    return {std::max(quantity.lower, f1 - band(q)), std::min(quantity.upper, f1 + band(q))};
}

std::pair<double, double> clipped_band(const Fig7Estimate& e) {
    const Fig7Quantity& quantity = fig7_quantities()[e.quantity];
    const double f1 = e.f.front(), U = e.g.uncertainty;
    return {std::max(quantity.lower, f1 - U), std::min(quantity.upper, f1 + U)};
}

double check_uncertainty(const Fig7Estimate& e) { return e.g.outside_bounds ? e.g.hi - e.g.lo : e.g.uncertainty; }

Fig7Analysis analyse_fig7(std::vector<Fig7Result> results, const Fig7Options& o) {
    Fig7Analysis a;
    a.results = std::move(results);
    a.reference_series = o.transports.front();
    const auto grid_explicit = a.runs(Fig7Kind::grid, true);
    for (int q = 0; q < kFig7Quantities; ++q) {
        for (const std::string& t : o.transports)
            a.estimates.push_back(fig7_estimate(q, t, a.runs(Fig7Kind::grid, false, t), false));
        if (grid_explicit.size() >= 2) a.estimates.push_back(fig7_estimate(q, "explicit", grid_explicit, false));
        if (o.dt_study) {
            a.estimates.push_back(fig7_estimate(q, "dt coarsest", a.dt_runs(o.cells.front()), true));
            a.estimates.push_back(fig7_estimate(q, "dt finest", a.dt_runs(o.cells.back()), true));
        }
    }
    const auto tracer = a.runs(Fig7Kind::tracer, false);
    const int core = 5;  // fig7_quantities(): the core's share, for the tracer its retained share
    if (tracer.size() >= 2) a.estimates.push_back(fig7_estimate(core, "tracer", tracer, false));
    if (tracer.size() >= 2) a.estimates.push_back(fig7_estimate(core, "points", tracer, false));
    return a;
}

void write_fig7_convergence(const Fig7Analysis& a, const Fig7Options& o) {
    const auto& quantities = fig7_quantities();
    DataTable runs;
    runs.comment(
        "bench_fig7_convergence: one row per run; kind 0 grid, 1 dt, 2 tracer, 3 floor (T_floor " + fig7_number(o.T_floor_low) +
        ", the model with the tracer); tracer runs: the core columns hold the tracer's retained share; explicit 1 for the "
        "explicit time stepping; "
        "dt_mean = t_end/steps; transport: index in --transports (-1 explicit); dt_max_share: share of the steps whose dt dt_max "
        "set; points, points_se: tracer runs' material points' retained share of the core; wall and CPU (all threads) time on " +
        std::to_string(o.threads) +
        " threads; each quantity (angle deg, layer mm) "
        "and its sampling error (_se: standard error of the time average over t >= " +
        fig7_number(o.average_from) + " s, or the jitter over the last " + fig7_number(o.jitter_window) +
        " s of a value at t_end = " + fig7_number(o.t_end) + " s)");
    for (const Fig7Result& r : a.results) {
        TableRow row{{"kind", static_cast<double>(r.run.kind)},
                     {"explicit", r.run.explicit_steps ? 1.0 : 0.0},
                     {"cells", static_cast<double>(r.run.cells)},
                     {"h_mm", 1e3 * r.h},
                     {"dt_factor", r.run.dt_factor},
                     {"dt_mean_ms", 1e3 * r.dt_mean},
                     {"steps", r.steps},
                     {"wall_s", r.wall},
                     {"cpu_s", r.cpu}};
        for (int q = 0; q < kFig7Quantities; ++q)
            row.add(quantities[q].name, r.value[q]).add(std::string(quantities[q].name) + "_se", r.sampling[q]);
        const auto t = std::find(o.transports.begin(), o.transports.end(), r.run.transport);
        row.add({{"transport", r.run.explicit_steps ? -1.0 : static_cast<double>(t - o.transports.begin())},
                 {"dt_max_ms", 1e3 * r.run.dt_max},
                 {"dt_max_share", r.dt_max_share},
                 {"points", r.points},
                 {"points_se", r.points_sampling}});
        runs.row(row);
    }
    write_file_atomically(o.data_dir + "/fig7_runs.dat", runs.str());

    DataTable conv;
    conv.comment(
        "bench_fig7_convergence: quantity 0..7 = angle layer index ring periphery core contrast axis; series 0 the "
        "reference transport (h), 1 explicit (h), 2 dt at the finest grid (mean dt), 3 tracer (core), 4 the second "
        "transport (h), 5 dt at the coarsest grid, 6 material points (core); x1 = finest h (mm) or dt (ms); condition 0 "
        "monotone, 1 oscillatory, 2 divergent, 3 within noise, 4 two grids, 5 undetermined; p, f0: least-squares "
        "fit f = f0 + alpha h^p weighted by 1/se^2; p_u, fs: Roy's order and factor of safety; sigma: standard "
        "deviation of the fit at p_u; U: uncertainty of f1 (harness/grid_convergence.hpp); e_a = |f1 - f2|/|f1|, "
        "e_ext = |f0 - f1|/|f0|; chi2 of a constant and its 95 % quantile; outside 1: f0 outside the physical range; "
        "band_lo, band_hi: f1 -+ U clipped to the physical range");
    std::ostringstream md;
    md << "| quantity | series | values, fine to coarse | largest sampling error | condition | p | Fs (p_u) | limit f0 | "
          "U of the finest | its range | e_a | e_ext | flag |\n|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";
    for (const Fig7Estimate& e : a.estimates) {
        const GridConvergence& g = e.g;
        const auto [band_lo, band_hi] = clipped_band(e);
        conv.row({{"quantity", static_cast<double>(e.quantity)},
                  {"series", static_cast<double>(series_code(e.series, a))},
                  {"runs", static_cast<double>(e.f.size())},
                  {"x1", 1e3 * e.h[0]},
                  {"f1", e.f[0]},
                  {"se_max", e.se_max},
                  {"condition", static_cast<double>(g.condition)},
                  {"p", g.p},
                  {"f0", g.f0},
                  {"p_u", g.p_u},
                  {"fs", g.fs},
                  {"sigma", g.sigma},
                  {"U", g.uncertainty},
                  {"e_a", g.e_a},
                  {"e_ext", g.e_ext},
                  {"chi2", g.chi2},
                  {"chi2_95", g.chi2_limit},
                  {"lo", g.lo},
                  {"hi", g.hi},
                  {"outside", g.outside_bounds ? 1.0 : 0.0},
                  {"band_lo", band_lo},
                  {"band_hi", band_hi}});
        const Fig7Quantity& q = quantities[e.quantity];
        std::string values;
        for (double f : e.f) values += (values.empty() ? "" : ", ") + fig7_number(f);
        const std::string label = e.series == "tracer" || e.series == "points" ? "core: share of its t = 0 material" : q.label;
        md << "| " << label << (std::string(q.unit) == "-" ? "" : " (" + std::string(q.unit) + ")") << " | " << series_text(e, a)
           << " | " << values << " | " << cell(e.se_max, 3) << " | " << condition_text(e) << " | " << cell(g.p, 4) << " | "
           << (std::isnan(g.fs) ? "–" : fig7_number(g.fs, 3) + " (" + fig7_number(g.p_u, 4) + ")") << " | " << cell(g.f0) << " | "
           << cell(g.uncertainty, 4) << " | " << cell(band_lo, 4) << " – " << cell(band_hi, 4) << " | " << cell(g.e_a, 3) << " | "
           << cell(g.e_ext, 3) << " | " << flags_text(e) << " |\n";
    }
    std::string cells, explicit_cells;
    for (int n : o.cells) cells += (cells.empty() ? "" : ", ") + std::to_string(n);
    for (int n : o.explicit_cells) explicit_cells += (explicit_cells.empty() ? "" : ", ") + std::to_string(n);
    std::string transports;
    for (const std::string& t : o.transports) transports += (transports.empty() ? "" : ", ") + t;
    const Fig7Result* loosest = &a.loosest_run();
    md << "\nWritten by `bench_fig7_convergence`: " << cells << " cells per diameter (transports " << transports << ", dt_max "
       << fig7_number(1e3 * o.dt_ref) << " ms × 50/cells; dt_max set " << fig7_number(100 * loosest->dt_max_share, 4)
       << " % or more of every run's steps, least in " << loosest->run.name << "), "
       << (explicit_cells.empty() ? "none" : explicit_cells) << " (explicit), t_end = " << fig7_number(o.t_end)
       << " s, angle and layer averaged over t >= " << fig7_number(o.average_from)
       << " s, the other quantities at t_end (sampling error: their jitter over the last " << fig7_number(o.jitter_window)
       << " s). Least-squares fit over all grids weighted by the sampling errors (Eca & Hoekstra 2014); no order "
       << "where the values agree with a constant within their sampling errors (chi^2, 95 %); Fs and p_u by Roy's rule "
       << "against the formal order " << fig7_number(kFormalOrder) << " (Fs = 1.25 within 10 %, else 3); two grids: "
       << "order " << fig7_number(kFormalOrder) << " assumed, Fs = 3.\n";
    write_file_atomically(o.data_dir + "/fig7_convergence.dat", conv.str());
    write_generated_table(o.data_dir + "/fig7_convergence.md", md.str(), kDrumStudyParts);
    write_fig7_summary(a, o);
}

}  // namespace granseg::verify
