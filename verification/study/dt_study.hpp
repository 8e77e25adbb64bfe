// The coupled drum's time-step study (bench_time_step): the paper's drum
// (verification/scenes/tumbler.toml) on fixed grids with dt_max refined, for each part of the
// coupling and each transport, so that each Fig. 7 quantity's error from the time step is measured
// apart from the grid's (the Fig. 7 study refines both together).
//
// Parts, per [flow] transport and grid:
//   no-feedback  [coupling] packing_feedback = false: the flow does not see phi, so its angle and
//                layer are the flow alone's (tests/coupled/coupled_tumbler.cpp checks the identity)
//                and the pattern is carried and segregated by that flow;
//   feedback     the full model (the paper's run): Phi_rcp and Phi_co follow phi_hat.
// Per part, transport, grid and quantity: the values at each dt_max with their sampling errors (the
// standard error of a time average, or the jitter of a value at t_end), the least-squares fit
// f = f0 + alpha dt^p (harness/grid_convergence.hpp with the mean time step as the abscissa, formal
// order 1), and the time error at the largest dt_max: f(dt) - f0 where the series converges
// monotonically; where it resolves no trend, its whole range bounds the error. A run whose mean step
// is within 1 % of a finer run's adds no point: a bound, not dt_max, set its steps (the acoustic
// bound of the semi-implicit step, src/flow/time_step.hpp, caps the step near 0.9 ms at 100 cells).
//
// The series and the cost runs set dt_max at the flow solver's acoustic Courant number (five): at the
// coupled drum's own (two, C9) the larger dt_max would all take one step.
// Error against cost: the full model (feedback) at each --cost-dt-max and at the coupled drum's
// default step (its scene's dt_max and acoustic Courant number: run NAME ..._default) on every grid
// and transport, each run's time error the value less its grid's series limit, beside its CPU
// seconds; the check of bench_time_step is the error at the default step.
#pragma once

#include "study/fig7_report.hpp"
#include "study/fig7_study.hpp"

#include <array>
#include <string>
#include <vector>

namespace granseg::verify {

/// One grid and its time steps (s, largest first: the first is the default step).
struct DtGrid {
    int cells = 0;
    std::vector<double> dt_max;
};

struct DtStudyOptions {
    Fig7Options run;  // data_dir, t_end, average_from, jitter_window, threads, lanes, reuse, transports
    std::vector<DtGrid> grids{{50, {2e-3, 1e-3, 5e-4, 2.5e-4}}, {100, {1e-3, 5e-4, 2.5e-4}}};
    std::vector<bool> feedback{false, true};                  // the parts: packing feedback off, on
    std::vector<double> cost_dt_max{1e-3, 2e-3, 3e-3, 4e-3};  // s, the error-against-cost runs (feedback part)
};

/// The quantities of the study, in the order of its tables (indices into fig7_quantities()).
const std::vector<int>& dt_study_quantities();

/// The runs, grid by grid: per transport, part and dt_max (largest first), then the cost runs not
/// among them and the run at the default step.
std::vector<Fig7Run> plan_dt_runs(const DtStudyOptions& options);

/// One series: a part, transport and grid, and a quantity.
struct DtEstimate {
    bool feedback = false;
    std::string transport;
    int cells = 0;
    Fig7Estimate e;         // fine to coarse: mean time step, value, sampling error; the fit
    double at_default = 0;  // the value at the largest dt_max
    double error = 0;       // its time error: value - f0 (monotone, two runs), else NaN
    double bound = 0;       // |error|, or where no limit is formed the range of the values
};

/// The estimates of every quantity of every series (results in plan order).
std::vector<DtEstimate> analyse_dt(const std::vector<Fig7Result>& results, const DtStudyOptions& options);

/// One run of the full model against its series' limit: per quantity its time error (value - f0,
/// NaN where the series forms no limit) and a bound on it (|error|, else the range of the series'
/// values and this run's).
struct DtCost {
    const Fig7Result* run = nullptr;
    std::array<double, kFig7Quantities> error{}, bound{};
};

/// The cost runs (--cost-dt-max, ascending, then the default step), grid by grid and transport;
/// runs whose series has no estimate are left out.
std::vector<DtCost> dt_costs(const std::vector<Fig7Result>& results, const std::vector<DtEstimate>& estimates,
                             const DtStudyOptions& options);

/// Writes DIR/time_step_runs.dat (a row per run), DIR/time_step.dat (a row per estimate, for
/// figures/bench_time_step.gp) and DIR/time_step.md (the table of docs/generated/).
void write_dt_study(const std::vector<Fig7Result>& results, const std::vector<DtEstimate>& estimates,
                    const DtStudyOptions& options);

/// Writes DIR/time_step_cost.dat and DIR/time_step_cost.md: per cost run its steps, the share the
/// acoustic bound set, CPU seconds and the time errors of the angle, index, core and axis.
void write_dt_costs(const std::vector<DtCost>& costs, const DtStudyOptions& options);

/// Whether `r` is the run at the coupled drum's default step (its scene's dt_max and acoustic
/// Courant number), not a series or cost run.
bool at_default_step(const Fig7Result& r);

/// "no feedback" or "feedback".
std::string part_name(bool feedback);

}  // namespace granseg::verify
