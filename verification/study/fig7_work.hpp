// Work against error for the paper's drum (bench_fig7_convergence): each run's
// wall time against its distance from the best estimate of the h -> 0 value (Fig7Analysis::
// reference), per time stepping, resolution and dt_max, and which run reaches a tolerance soonest.
#pragma once

#include "study/fig7_report.hpp"

#include <string>
#include <vector>

namespace granseg::verify {

/// A use of the drum and the accuracy it needs in the angle of repose (deg) and the index.
struct Fig7Use {
    const char* use;
    double angle, index;
};

/// The uses the study answers for (fig7_work.cpp says why these tolerances).
const std::vector<Fig7Use>& fig7_uses();

/// Writes DIR/fig7_work.dat (one row per grid and dt run: wall time, |value - reference| of every
/// quantity and the reference's uncertainty) and DIR/fig7_work.md (the table and the answers), and returns the answers: for
/// each use the cheapest run whose angle and index lie within its tolerances of the reference (or
/// that none does), flagged where the reference's own uncertainty exceeds the tolerances.
std::vector<std::string> write_fig7_work(const Fig7Analysis& analysis, const Fig7Options& options);

}  // namespace granseg::verify
