// The analysis of the Fig. 7 study's runs (bench_fig7_convergence): for each Fig. 7 quantity and
// each series of runs the convergence condition, the least-squares order, extrapolated value and
// uncertainty (harness/grid_convergence.hpp) with the sampling errors weighing in, and the tables
// and markdown the benchmark writes.
//
// Series (fine to coarse, all runs of the series):
//   default   the default time stepping against h (three grids or more)
//   explicit  the explicit time stepping against h (two grids: order 1 assumed, Fs = 3)
//   dt        the default time stepping at one grid against the mean time step t_end/steps
//             (dt_max halved, as in the scene, doubled)
//   tracer    the passive tracer's core share (the core quantity only) against h
#pragma once

#include "harness/fig7_study.hpp"
#include "harness/grid_convergence.hpp"

#include <string>
#include <vector>

namespace granseg::verify {

/// The formal order of the coupled scheme for Roy's rule and for two grids: first in space and time
/// (the bulk step's limited reconstruction falls to first order at extrema and walls, the
/// segregation flux and the Lie splitting are first order; docs/sect4.2_tumbler.md).
constexpr double kFormalOrder = 1.0;

struct Fig7Estimate {
    int quantity = 0;
    std::string series;
    std::vector<double> h, f, se;  // fine to coarse: cell size (m) or mean time step (s), value, sampling error
    GridConvergence g;
    double se_max = 0;             // largest sampling error of the runs used
};

struct Fig7Analysis {
    std::vector<Fig7Result> results;
    std::vector<Fig7Estimate> estimates;

    /// The estimate of `quantity` in `series`, or nullptr if the study has no such series.
    const Fig7Estimate* find(int quantity, const std::string& series) const;
    /// The runs of one kind and time stepping, fine to coarse (dt runs: dt_max 0.5, 1, 2 times).
    std::vector<const Fig7Result*> runs(Fig7Kind kind, bool explicit_steps) const;
    /// The finest default-mode grid run.
    const Fig7Result& finest() const;
    /// The best estimate of the h -> 0 value of `quantity` and its uncertainty: the default series'
    /// extrapolation when monotone and inside the physical range, else the finest run; the
    /// uncertainty of the finest run (reference_note says which).
    double reference(int quantity) const;
    double reference_uncertainty(int quantity) const;
    std::string reference_note(int quantity) const;
};

/// The estimates of every quantity in every series the runs allow.
Fig7Analysis analyse_fig7(std::vector<Fig7Result> results, const Fig7Options& options);

/// Writes DIR/fig7_runs.dat (one row per run), DIR/fig7_convergence.dat (one row per quantity and
/// series) and DIR/fig7_convergence.md (the same as a markdown table for docs/generated/).
void write_fig7_convergence(const Fig7Analysis& analysis, const Fig7Options& options);

/// Formats a number with `digits` significant digits ("nan" for NaN).
std::string fig7_number(double v, int digits = 6);

}  // namespace granseg::verify
