#include "study/fig7_work.hpp"

#include "harness/table_provenance.hpp"
#include "run/output.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace granseg::verify {

namespace {

std::string series_name(const Fig7Result& r) { return r.run.explicit_steps ? std::string("explicit") : r.run.transport; }

std::string run_text(const Fig7Result& r) {
    return series_name(r) + ", " + std::to_string(r.run.cells) + " cells per diameter, dt_max " +
           fig7_number(1e3 * r.run.dt_max, 4) + " ms";
}

/// An error and whether the reference's band resolves it ("<= band": it does not).
std::string error_cell(double error, double band) { return fig7_number(error, 3) + (error <= band ? " (<= band)" : ""); }

}  // namespace

// The tolerances: a figure is read to about 0.5 deg of slope and 0.02 on the 0..1 colour scale of
// phi_hat (differences a reader of Fig. 7 cannot see); a quick look needs the pattern's sense and
// a slope no further off than the two time-stepping modes differ at the paper's resolution
// (bench_drum_angle measures that difference); a paper quotes three digits of the angle and two of
// the index, so a fifth of the figure's tolerances.
const std::vector<Fig7Use>& fig7_uses() {
    static const std::vector<Fig7Use> uses{{"a quick look", 2.0, 0.1}, {"a figure", 0.5, 0.02}, {"a paper", 0.2, 0.01}};
    return uses;
}

std::vector<std::string> write_fig7_work(const Fig7Analysis& a, const Fig7Options& o) {
    const auto& quantities = fig7_quantities();
    const Fig7Result& ref = a.reference_run();
    DataTable table;
    std::string refs;
    for (int q = 0; q < kFig7Quantities; ++q)
        refs += std::string(q ? ", " : "") + quantities[q].name + " " + fig7_number(ref.value[q]) + " +- " +
                fig7_number(a.reference_band(q), 3);
    table.comment("bench_fig7_convergence: CPU time (s, all " + std::to_string(o.threads) +
                  " threads) and wall time of each grid "
                  "and dt run, |value - reference| per quantity, and (u_) the reference's band; transport: index in --transports "
                  "(-1 explicit); reference: the finest grid's smallest-dt run " +
                  ref.run.name +
                  " +- its band (the finest grid's uncertainty plus this run's time-step "
                  "uncertainty): " +
                  refs);
    std::vector<const Fig7Result*> runs;
    for (const Fig7Result& r : a.results)
        if ((r.run.kind == Fig7Kind::grid || r.run.kind == Fig7Kind::dt) && &r != &ref) runs.push_back(&r);
    std::sort(runs.begin(), runs.end(), [](const Fig7Result* x, const Fig7Result* y) { return x->cpu < y->cpu; });
    std::ostringstream md;
    md << "| transport | cells per diameter | dt_max (ms) | CPU time (s) | angle error (deg) | index error | layer error (mm) | "
          "core error |\n|---|---|---|---|---|---|---|---|\n";
    for (const Fig7Result* r : runs) {
        const auto t = std::find(o.transports.begin(), o.transports.end(), r->run.transport);
        TableRow row{{"transport", r->run.explicit_steps ? -1.0 : static_cast<double>(t - o.transports.begin())},
                     {"cells", static_cast<double>(r->run.cells)},
                     {"dt_factor", r->run.dt_factor},
                     {"cpu_s", r->cpu},
                     {"wall_s", r->wall}};
        for (int q = 0; q < kFig7Quantities; ++q)
            row.add(std::string("err_") + quantities[q].name, std::fabs(r->value[q] - ref.value[q]));
        for (int q = 0; q < kFig7Quantities; ++q) row.add(std::string("u_") + quantities[q].name, a.reference_band(q));
        table.row(row);
        const auto err = [&](int q) { return error_cell(std::fabs(r->value[q] - ref.value[q]), a.reference_band(q)); };
        md << "| " << series_name(*r) << " | " << r->run.cells << " | " << fig7_number(1e3 * r->run.dt_max, 4) << " | "
           << fig7_number(r->cpu, 4) << " | " << err(kAngle) << " | " << err(kIndex) << " | " << err(kLayer) << " | "
           << err(kCore) << " |\n";
    }
    double total_cpu = 0;
    for (const Fig7Result& r : a.results) total_cpu += r.cpu;
    md << "\nReference: the finest grid's smallest-dt run (" << run_text(ref) << ", " << fig7_number(ref.cpu, 4)
       << " s CPU), with its own band (the finest grid's uncertainty plus this run's time-step uncertainty): angle "
       << fig7_number(ref.value[kAngle]) << " +- " << fig7_number(a.reference_band(kAngle), 3) << " deg, index "
       << fig7_number(ref.value[kIndex]) << " +- " << fig7_number(a.reference_band(kIndex), 3)
       << ". Time: CPU seconds of all threads, one run each; an error marked (<= band) "
       << "is within the reference's own uncertainty and ranks nothing. The whole study: " << a.results.size() << " runs, "
       << fig7_number(total_cpu / 3600.0, 3) << " CPU-hours.\n\n";

    std::vector<std::string> answers;
    const double angle_u = a.reference_band(kAngle), index_u = a.reference_band(kIndex);
    for (const Fig7Use& use : fig7_uses()) {
        const Fig7Result* best = nullptr;
        for (const Fig7Result* r : runs) {
            const bool ok = std::fabs(r->value[kAngle] - ref.value[kAngle]) <= use.angle &&
                            std::fabs(r->value[kIndex] - ref.value[kIndex]) <= use.index;
            if (ok && (!best || r->cpu < best->cpu)) best = r;
        }
        std::string answer = "For " + std::string(use.use) + " (angle within " + fig7_number(use.angle) + " deg, index within " +
                             fig7_number(use.index) + " of the reference): ";
        answer += best ? run_text(*best) + ", " + fig7_number(best->cpu, 3) + " s CPU"
                       : "the reference run itself (" + fig7_number(ref.cpu, 3) + " s CPU), no cheaper run is close enough";
        if (angle_u > use.angle || index_u > use.index)
            answer += " (not established: the reference's band, " + fig7_number(angle_u, 3) + " deg and " +
                      fig7_number(index_u, 3) + ", exceeds the tolerance)";
        answers.push_back(answer + ".");
        md << "* " << answers.back() << "\n";
    }
    write_file_atomically(o.data_dir + "/fig7_work.dat", table.str());
    write_generated_table(o.data_dir + "/fig7_work.md", md.str(), kDrumStudyParts);
    return answers;
}

}  // namespace granseg::verify
