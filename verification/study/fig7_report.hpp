// The analysis of the Fig. 7 study's runs (bench_fig7_convergence): for each Fig. 7 quantity and
// each series of runs the convergence condition, the least-squares order, extrapolated value and
// uncertainty (harness/grid_convergence.hpp) with the sampling errors weighing in, and the tables
// and markdown the benchmark writes.
//
// Series (fine to coarse, all runs of the series):
//   TRANSPORT    each --transports' grid series against h, dt ~ h (three grids or more); the
//                first is the reference series
//   explicit     the explicit time stepping against h (two grids: order 1 assumed, Fs = 3)
//   dt coarsest  the reference transport at the coarsest grid against the mean time step
//   dt finest    t_end/steps, dt_max times the factors and 1 (the grid run)
//   tracer       the passive tracer's core share (the core quantity only) against h
#pragma once

#include "harness/grid_convergence.hpp"
#include "study/fig7_study.hpp"

#include <string>
#include <utility>
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
    double se_max = 0;  // largest sampling error of the runs used
};

struct Fig7Analysis {
    std::vector<Fig7Result> results;
    std::vector<Fig7Estimate> estimates;
    std::string reference_series;  // the first transport

    /// The estimate of `quantity` in `series`, or nullptr if the study has no such series.
    const Fig7Estimate* find(int quantity, const std::string& series) const;
    /// The runs of one kind and time stepping (and transport, unless empty), fine to coarse.
    std::vector<const Fig7Result*> runs(Fig7Kind kind, bool explicit_steps, const std::string& transport = "") const;
    /// The dt study at one grid: its dt runs and the reference transport's grid run, smallest dt first.
    std::vector<const Fig7Result*> dt_runs(int cells) const;
    /// The run (explicit ones aside) whose steps dt_max set least often: the evidence that dt ~ h.
    const Fig7Result& loosest_run() const;
    /// The finest grid run of the reference transport.
    const Fig7Result& finest() const;
    /// The reference of the work-against-error table: the finest grid's run with the smallest dt
    /// (the dt study's, or the grid run without one).
    const Fig7Result& reference_run() const;
    /// The band of the finest grid run's value of `quantity`: its grid uncertainty (the reference
    /// series' U) plus its time-step uncertainty (the dt study at the finest grid, evaluated at
    /// this run's step, the study's largest; where the study has one). Why both: the grid series
    /// refines h and dt together, and its one fit assumes that their errors share one order; where
    /// the observed orders are not within 10 % of the formal order 1 (Fs = 3) the series is not in
    /// that asymptotic range, where a time error of another order could be absorbed into the fit
    /// or cancel against the grid's. The dt study measures the time step's own effect at the
    /// finest grid directly, and its uncertainty is added as that allowance.
    double band(int quantity) const;
    /// The band of the reference run's value (the finest grid's smallest step, reference_run):
    /// the same grid uncertainty (the grid's error taken as the same at the smaller step) plus
    /// the dt study's uncertainty of its own finest value, this run's.
    double reference_band(int quantity) const;
    /// The finest value's band f1 +- band(quantity), clipped to the quantity's physical range.
    std::pair<double, double> band_range(int quantity) const;
};

/// The estimate of `quantity` over `runs` (fine to coarse) against their cell size, or with dt_axis
/// their mean time step: a study where the abscissae increase and every value is defined, else the
/// range of the values (condition undetermined).
Fig7Estimate fig7_estimate(int quantity, const std::string& series, const std::vector<const Fig7Result*>& runs, bool dt_axis);

/// The estimates of every quantity in every series the runs allow.
Fig7Analysis analyse_fig7(std::vector<Fig7Result> results, const Fig7Options& options);

/// Writes DIR/fig7_runs.dat (one row per run), DIR/fig7_convergence.dat (one row per quantity and
/// series) and DIR/fig7_convergence.md (the same as a markdown table for docs/generated/).
void write_fig7_convergence(const Fig7Analysis& analysis, const Fig7Options& options);

/// An estimate's band f1 +- U clipped to the quantity's physical range.
std::pair<double, double> clipped_band(const Fig7Estimate& e);

/// The uncertainty a check may use: the series' U, unless its fit is rejected (its limit lies
/// outside the physical range), then the range of its values, which rests on no fit.
double check_uncertainty(const Fig7Estimate& e);

/// Formats a number with `digits` significant digits ("nan" for NaN).
std::string fig7_number(double v, int digits = 6);

}  // namespace granseg::verify
