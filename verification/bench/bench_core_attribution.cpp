// What changes the composition of the drum's core (r < d - layer, summary column core_layer) in
// the paper's drum (verification/scenes/tumbler.toml), separated by runs: per grid
//   (i)   the full model;
//   (ii)  the same with the segregation switched off where the shear rate kappa_max - kappa_min is
//         at or below a threshold ([segregation] diagnostic_min_shear_rate): the slowly creeping
//         bed below the flowing layer no longer segregates, the layer still does; one run per
//         --thresholds value;
//   (iii) S = 0: the transport of the uniform mixture alone, a control that must keep the core
//         at the initial mixture (a uniform phi_hat stays uniform to round-off).
// Attribution of the core's share at t_end: segregation at or below the threshold (for a threshold
// at the flowing layer's bottom: in the creeping bed) = (i) - (ii); segregation above it and the
// transport of what it segregated into the core (by the creep and by the grid) = (ii) - (iii); what the
// grid changes = those at the finer grid minus those at the coarser; what the time step changes =
// those of (i), (ii) and (iii) at the first grid with dt_max times --dt-check minus those at dt_max.
// Sampling errors: the jitter of the core's share over the last --jitter-window before t_end
// (study/fig7_study.hpp), added in quadrature for a difference.
// Writes to DIR: core_attribution.dat (a row per run), core_attribution.md (ready for
// docs/generated/), core_profile.dat (run (i) at t_end along the vertical line through the axis:
// z, T, shear rate, phi_hat; a block per grid), and every run under core_attribution/ (its scene
// NAME.toml and its files NAME/); figures/bench_core_profile.gp plots the profile.
// The one check: (iii) keeps the core at the initial mixture.
//
// Run: build/bench/bench_core_attribution [--data DIR] [options]    (--help lists them)
//   the default (50 and 70 cells, 25 s, dt_max 0.5 ms, three thresholds, the time step halved at 50
//   cells) takes about 40 CPU-minutes;
//   a test of everything in a few minutes: --grids 26 --t-end 2 --average-from 1 --jitter-window 0.5
#include "core/error.hpp"
#include "coupled/coupled_tumbler.hpp"
#include "drum/drum.hpp"
#include "harness/check_table.hpp"
#include "harness/named_table.hpp"
#include "harness/program.hpp"
#include "harness/side_by_side.hpp"
#include "harness/table_provenance.hpp"
#include "run/output.hpp"
#include "study/fig7_report.hpp"
#include "study/fig7_study.hpp"
#include "study/study_options.hpp"

#include <boost/program_options.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <mutex>
#include <sstream>
#include <tuple>

using namespace granseg;
using namespace granseg::verify;
namespace po = boost::program_options;

namespace {

constexpr const char* kProgram = "bench_core_attribution";

// A uniform phi_hat stays uniform to round-off in each bulk step (coupled_tumbler.hpp); over some
// 10^5 steps the relative round-off of 1e-16 per step stays far below this.
constexpr double kControlTolerance = 1e-9;

enum class Part { full, creep_off, no_segregation };

struct AttributionOptions {
    Fig7Options run;
    std::vector<int> grids{50, 70};
    std::vector<double> thresholds{0.3, 0.1, 1.0};  // 1/s; the first is the reference
    double dt_max = 5e-4;                           // s
    double dt_check = 0.5;                          // dt_max factor of the time-step runs (0: none)
};

struct PlannedRun {
    Fig7Run run;
    Part part;
};

AttributionOptions parse(int argc, char** argv) {
    AttributionOptions o;
    o.run.study_dir = "core_attribution", o.run.program = kProgram;
    std::string grids = "50,70", thresholds = "0.3,0.1,1";
    po::options_description d("bench_core_attribution: what changes the composition of the drum's core");
    d.add_options()("help", "this list")("data", po::value(&o.run.data_dir)->default_value(o.run.data_dir), "output directory")(
        "grids", po::value(&grids)->default_value(grids), "cells per diameter, increasing")(
        "thresholds", po::value(&thresholds)->default_value(thresholds),
        "1/s, diagnostic_min_shear_rate of the runs (ii); the first is the reference")(
        "dt-max", po::value(&o.dt_max)->default_value(o.dt_max), "s, [flow] dt_max of every run")(
        "dt-check", po::value(&o.dt_check)->default_value(o.dt_check),
        "dt_max factor of (i), (ii), (iii) repeated at the first grid (0: none)");
    add_run_options(d, o.run);
    parse_study_command_line(kProgram, argc, argv, d, o.run);
    o.grids = cell_list(kProgram, "grids", grids);
    if (o.grids.empty()) bad_option(kProgram, "grids", "none", "one or more grids");
    o.thresholds = number_list(kProgram, "thresholds", thresholds, 0.0, 1e3);
    std::vector<double> sorted = o.thresholds;
    std::sort(sorted.begin(), sorted.end());
    if (sorted.empty() || std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end())
        bad_option(kProgram, "thresholds", "\"" + thresholds + "\"", "one or more distinct thresholds");
    if (!(o.dt_max > 0.0 && o.dt_max <= 1e-2)) bad_option(kProgram, "dt-max", fig7_number(o.dt_max), "0 < dt_max <= 0.01");
    if (!(o.dt_check >= 0.0 && o.dt_check < 1.0)) bad_option(kProgram, "dt-check", fig7_number(o.dt_check), "0 <= factor < 1");
    check_run_options(kProgram, o.run);
    return o;
}

std::string run_name(Part part, double threshold, int cells, const std::string& dt = "") {
    const std::string n = "_n" + std::to_string(cells) + dt;
    if (part == Part::full) return "full" + n;
    if (part == Part::no_segregation) return "S0" + n;
    return "creep_off_" + fig7_number(threshold) + n;
}

/// Per grid (i), (ii) at the reference threshold and (iii); then (ii) at the other thresholds; then
/// the first grid's (i), (ii), (iii) at the shorter step.
std::vector<PlannedRun> plan(const AttributionOptions& o) {
    std::vector<PlannedRun> runs;
    const auto add = [&](Part part, double threshold, int cells, double factor = 1.0) {
        const std::string dt = factor == 1.0 ? "" : "_dt" + fig7_number(factor * o.dt_max);
        Fig7Run r{run_name(part, threshold, cells, dt), Fig7Kind::grid, false, cells, factor, "muscl", factor * o.dt_max};
        if (part == Part::creep_off) r.min_shear_rate = threshold;
        if (part == Part::no_segregation) r.S = 0.0;
        runs.push_back({r, part});
    };
    for (int n : o.grids) add(Part::full, 0, n), add(Part::creep_off, o.thresholds.front(), n), add(Part::no_segregation, 0, n);
    for (std::size_t t = 1; t < o.thresholds.size(); ++t)
        for (int n : o.grids) add(Part::creep_off, o.thresholds[t], n);
    if (o.dt_check > 0.0)
        for (Part p : {Part::full, Part::creep_off, Part::no_segregation})
            add(p, o.thresholds.front(), o.grids.front(), o.dt_check);
    return runs;
}

/// The core's share and its sampling error.
struct Share {
    double v = NAN, se = NAN;
    Share operator-(const Share& b) const { return {v - b.v, std::hypot(se, b.se)}; }
    std::string cell() const { return fig7_number(v, 3) + " ± " + fig7_number(se, 2); }
};

Share core_of(const Fig7Result& r) { return {r.value[kCore], r.sampling[kCore]}; }

/// Run (i) at t_end along the vertical line through the axis (lab frame): the mean of the bed's
/// cells (Phi >= the scene's Phi_min, C2: where segregation acts) whose centres lie within half a
/// cell of x = 0, per height.
void append_profile(DataTable& table, const AttributionOptions& o, int cells) {
    const std::string dir = o.run.data_dir + "/" + o.run.study_dir + "/" + run_name(Part::full, 0, cells);
    const NamedTable fields = read_named(dir + "/fields_lab.dat"), summary = read_named(dir + "/summary.dat");
    const double h = fig7_scene_number("drum", "diameter", DrumSpec{}.diameter) / cells;
    const double Phi_min = fig7_scene_number("segregation", "Phi_min", CoupledTumblerSetup{}.Phi_min);
    struct Sum {
        double n = 0, T = 0, shear = 0, hat = 0;
    };
    std::map<long, Sum> line;  // by height in units of h/2
    for (const std::vector<double>& row : fields.rows) {
        if (fields.at(row, "inside") == 0 || !(fields.at(row, "Phi") >= Phi_min) ||
            std::fabs(fields.at(row, "x")) > 0.5 * h * (1 + 1e-6))
            continue;
        Sum& s = line[std::lround(2 * fields.at(row, "z") / h)];
        s.n += 1, s.T += fields.at(row, "T"), s.shear += fields.at(row, "shear_rate"), s.hat += fields.at(row, "phi_hat");
    }
    const double r_core = summary.at(summary.last(), "r_core_layer");
    for (const auto& [key, s] : line)
        table.row({{"cells", static_cast<double>(cells)},
                   {"z", 0.5 * h * key},
                   {"T", s.T / s.n},
                   {"shear_rate", s.shear / s.n},
                   {"phi_hat", s.hat / s.n},
                   {"r_core_layer", r_core}});
    table.blank(), table.blank();
}

void write_results(const std::vector<PlannedRun>& runs, const std::vector<Fig7Result>& results, const AttributionOptions& o) {
    DataTable dat;
    dat.comment(
        "bench_core_attribution: one row per run; part 0 full model, 1 no segregation at shear rates <= min_shear_rate (1/s), "
        "2 S = 0; core, axis: small-particle shares at t_end with their jitter over the last " +
        fig7_number(o.run.jitter_window) + " s (_se)");
    using Key = std::pair<int, double>;  // cells, dt_max
    std::map<Key, const Fig7Result*> full, none;
    for (std::size_t j = 0; j < runs.size(); ++j) {
        const Fig7Result& r = results[j];
        dat.row({{"part", static_cast<double>(runs[j].part)},
                 {"cells", static_cast<double>(r.run.cells)},
                 {"dt_max", r.run.dt_max},
                 {"min_shear_rate", r.run.min_shear_rate},
                 {"core", r.value[kCore]},
                 {"core_se", r.sampling[kCore]},
                 {"axis", r.value[kAxis]},
                 {"axis_se", r.sampling[kAxis]},
                 {"layer_mm", r.value[kLayer]},
                 {"angle", r.value[kAngle]},
                 {"initial_mixture", r.initial_mixture},
                 {"wall_seconds", r.wall}});
        if (runs[j].part == Part::full) full[{r.run.cells, r.run.dt_max}] = &r;
        if (runs[j].part == Part::no_segregation) none[{r.run.cells, r.run.dt_max}] = &r;
    }
    write_file_atomically(o.run.data_dir + "/core_attribution.dat", dat.str());

    // Rows by threshold, then the default step before the shorter one, then grid: per threshold its
    // grids, the change between successive grids, and the change the shorter step makes.
    struct Parts {
        Share i, ii, iii;
        Share below() const { return i - ii; }    // segregation at or below the threshold
        Share above() const { return ii - iii; }  // segregation above it, and what carries its product in
    };
    std::map<std::tuple<double, double, int>, Parts> rows;  // (threshold, -dt_max, cells)
    for (std::size_t j = 0; j < runs.size(); ++j) {
        if (runs[j].part != Part::creep_off) continue;
        const Fig7Run& run = results[j].run;
        const Key key{run.cells, run.dt_max};
        rows[{run.min_shear_rate, -run.dt_max, run.cells}] = {core_of(*full.at(key)), core_of(results[j]),
                                                              core_of(*none.at(key))};
    }
    std::ostringstream md;
    md << "| cells | dt_max (ms) | threshold (1/s) | (i) full model | (ii) no segregation at or below the threshold | (iii) S = "
          "0 "
          "| segregation at or below the threshold: (i) − (ii) | segregation above it and transport: (ii) − (iii) |\n"
          "|---|---|---|---|---|---|---|---|\n";
    const auto change = [&](const std::string& what, double threshold, const Parts& a, const Parts& b) {
        md << "| " << what << " | | " << fig7_number(threshold) << " | | | | " << (a.below() - b.below()).cell() << " | "
           << (a.above() - b.above()).cell() << " |\n";
    };
    const Parts* previous = nullptr;
    for (auto it = rows.begin(); it != rows.end(); ++it) {
        const auto& [threshold, minus_dt, cells] = it->first;
        const Parts& p = it->second;
        md << "| " << cells << " | " << fig7_number(-1e3 * minus_dt) << " | " << fig7_number(threshold) << " | " << p.i.cell()
           << " | " << p.ii.cell() << " | " << p.iii.cell() << " | " << p.below().cell() << " | " << p.above().cell() << " |\n";
        if (previous && -minus_dt == o.dt_max && std::get<0>(std::prev(it)->first) == threshold)
            change("grid: " + std::to_string(cells) + " − " + std::to_string(std::get<2>(std::prev(it)->first)), threshold, p,
                   *previous);
        if (-minus_dt != o.dt_max) {
            const auto coarse = rows.find({threshold, -o.dt_max, cells});
            if (coarse != rows.end())
                change("dt: " + fig7_number(-1e3 * minus_dt) + " − " + fig7_number(1e3 * o.dt_max) + " ms", threshold, p,
                       coarse->second);
        }
        previous = &p;
    }
    md << "\nThe core's (r < d − layer) small-particle share at t_end = " << fig7_number(o.run.t_end)
       << " s ± its jitter over the last " << fig7_number(o.run.jitter_window)
       << " s; muscl transport, packing feedback on. Written by bench_core_attribution.\n";
    write_generated_table(o.run.data_dir + "/core_attribution.md", md.str(), kDrumStudyParts);

    DataTable profile;
    profile.comment(
        "bench_core_attribution: run (i) at t_end on the vertical line through the axis (lab frame, mean of the cells within "
        "h/2 of x = 0 with Phi >= Phi_min): z (m), T (m^2/s^2), shear_rate kappa_max - kappa_min (1/s), phi_hat; one block per "
        "grid");
    for (int n : o.grids) append_profile(profile, o, n);
    write_file_atomically(o.run.data_dir + "/core_profile.dat", profile.str());
}

}  // namespace

int main(int argc, char** argv) {
    verify::parse_program_options(1, argv);  // only for its handling of the library's errors (exit 2, 3)
    const AttributionOptions o = parse(argc, argv);
    const std::vector<PlannedRun> runs = plan(o);
    std::printf("%s: %zu runs of verification/scenes/tumbler.toml, t_end %g s, dt_max %g s, %d side by side%s\n", kProgram,
                runs.size(), o.run.t_end, o.dt_max, o.run.lanes, o.run.reuse ? ", reusing unchanged runs" : "");
    std::vector<Fig7Result> results(runs.size());
    std::mutex print;
    run_side_by_side(static_cast<int>(runs.size()), o.run.lanes, [&](int j) {
        results[j] = run_fig7(runs[j].run, o.run);
        const Fig7Result& r = results[j];
        const std::lock_guard<std::mutex> lock(print);
        std::printf("run %-24s %8.1f s wall: core %.4f ± %.4f, axis %.4f, layer %.2f mm, angle %.3f deg\n", r.run.name.c_str(),
                    r.wall, r.value[kCore], r.sampling[kCore], r.value[kAxis], r.value[kLayer], r.value[kAngle]);
        std::fflush(stdout);
    });
    write_results(runs, results, o);
    CheckTable table("bench_core_attribution: the control (iii) keeps the core's composition");
    for (std::size_t j = 0; j < runs.size(); ++j)
        if (runs[j].part == Part::no_segregation)
            table.at_most(std::to_string(results[j].run.cells) + " cells, S = 0: |core - initial mixture|",
                          std::fabs(results[j].value[kCore] - results[j].initial_mixture), kControlTolerance);
    return table.finish();
}
