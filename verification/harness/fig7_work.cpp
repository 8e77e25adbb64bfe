#include "harness/fig7_work.hpp"

#include "core/output.hpp"

#include <cmath>
#include <sstream>

namespace granseg::verify {

namespace {

constexpr int kAngle = 0, kIndex = 2;  // fig7_quantities()

std::string run_text(const Fig7Result& r) {
    std::string s = (r.run.explicit_steps ? std::string("explicit time stepping") : r.run.transport) + ", " +
                    std::to_string(r.run.cells) + " cells per diameter";
    s += ", dt_max " + fig7_number(1e3 * r.run.dt_max, 4) + " ms";
    return s;
}

}  // namespace

// The tolerances: a figure is read to about 0.5 deg of slope and 0.02 on the 0..1 colour scale of
// phi_hat (differences a reader of Fig. 7 cannot see); a quick look needs the
// pattern's sense and the slope within the 2.3 deg that separated the two time-stepping modes at
// 100 cells; a paper quotes three digits (23.x deg, 0.8x), so a fifth of the figure's tolerances.
const std::vector<Fig7Use>& fig7_uses() {
    static const std::vector<Fig7Use> uses{{"a quick look", 2.0, 0.1}, {"a figure", 0.5, 0.02}, {"a paper", 0.2, 0.01}};
    return uses;
}

std::vector<std::string> write_fig7_work(const Fig7Analysis& a, const Fig7Options& o) {
    const auto& quantities = fig7_quantities();
    std::vector<std::string> columns{"explicit", "cells", "dt_factor", "wall_s"};
    for (const Fig7Quantity& q : quantities) columns.push_back(std::string("err_") + q.name);
    for (const Fig7Quantity& q : quantities) columns.push_back(std::string("u_") + q.name);
    DataTable table(columns);
    std::string refs;
    for (int q = 0; q < kFig7Quantities; ++q)
        refs += std::string(q ? ", " : "") + quantities[q].name + " " + fig7_number(a.reference(q)) + " +- " +
                fig7_number(a.reference_uncertainty(q), 2);
    table.comment("bench_fig7_convergence: wall time (s, " + std::to_string(o.threads) + " threads) and |value - reference| per "
                  "grid and dt run, and (u_) the reference's uncertainty; reference (the first transport's series, extrapolated if monotone inside the physical range, else the finest run) +- its uncertainty: " + refs);
    std::vector<const Fig7Result*> runs;
    for (const Fig7Result& r : a.results)
        if (r.run.kind == Fig7Kind::grid || r.run.kind == Fig7Kind::dt) runs.push_back(&r);
    std::ostringstream md;
    md << "| transport | cells per diameter | dt_max (ms) | wall time (s) | angle error (deg) | index error | "
          "layer error (mm) | core error |\n|---|---|---|---|---|---|---|---|\n";
    for (const Fig7Result* r : runs) {
        std::vector<double> row{r->run.explicit_steps ? 1.0 : 0.0, static_cast<double>(r->run.cells), r->run.dt_factor, r->wall};
        for (int q = 0; q < kFig7Quantities; ++q) row.push_back(std::fabs(r->value[q] - a.reference(q)));
        for (int q = 0; q < kFig7Quantities; ++q) row.push_back(a.reference_uncertainty(q));
        table.row(row);
        md << "| " << (r->run.explicit_steps ? "explicit" : r->run.transport) << " | " << r->run.cells << " | "
           << fig7_number(1e3 * r->run.dt_max, 4) << " | " << fig7_number(r->wall, 3) << " | " << fig7_number(row[4 + kAngle], 2)
           << " | " << fig7_number(row[4 + kIndex], 2) << " | " << fig7_number(row[4 + 1], 2) << " | "
           << fig7_number(row[4 + 5], 2) << " |\n";
    }
    md << "\nReference: " << a.reference_note(kAngle) << " for the angle (" << fig7_number(a.reference(kAngle)) << " +- "
       << fig7_number(a.reference_uncertainty(kAngle), 2) << " deg), " << a.reference_note(kIndex) << " for the index ("
       << fig7_number(a.reference(kIndex)) << " +- " << fig7_number(a.reference_uncertainty(kIndex), 2) << ").\n\n";

    std::vector<std::string> answers;
    const double angle_u = a.reference_uncertainty(kAngle), index_u = a.reference_uncertainty(kIndex);
    for (const Fig7Use& use : fig7_uses()) {
        const Fig7Result* best = nullptr;
        for (const Fig7Result* r : runs) {
            const bool angle_ok = std::fabs(r->value[kAngle] - a.reference(kAngle)) <= use.angle;
            const bool index_ok = std::fabs(r->value[kIndex] - a.reference(kIndex)) <= use.index;
            if (angle_ok && index_ok && (!best || r->wall < best->wall)) best = r;
        }
        std::string answer = "For " + std::string(use.use) + " (angle within " + fig7_number(use.angle) + " deg, index within " +
                             fig7_number(use.index) + " of the reference): ";
        answer += best ? run_text(*best) + ", " + fig7_number(best->wall, 3) + " s wall" : "none of the runs; a finer grid is needed";
        if (angle_u > use.angle || index_u > use.index)
            answer += " (not established: the reference itself is uncertain by " + fig7_number(angle_u, 2) + " deg and " +
                      fig7_number(index_u, 2) + ")";
        answers.push_back(answer + ".");
        md << "* " << answers.back() << "\n";
    }
    write_file_atomically(o.data_dir + "/fig7_work.dat", table.str());
    write_file_atomically(o.data_dir + "/fig7_work.md", md.str());
    return answers;
}

}  // namespace granseg::verify
