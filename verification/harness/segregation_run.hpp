// Runs a 1-D segregation column for the verification programs and the benchmark, and records
// what every run must show: the amount of small particles (sum of phi, summed here
// in long double, independently of the library's own monitor), the extremes of phi against its
// bounds over all steps, non-finite values, and the cost (steps, cell updates, CPU time).
#pragma once

#include "segregation/column.hpp"
#include "segregation/segregation_solver.hpp"

#include <functional>
#include <string>
#include <vector>

namespace granseg::verify {

struct ColumnRun {
    std::vector<double> phi;  // at the end
    double max_excess = 0.0;  // max over steps and cells of phi - Phi (monitored runs)
    double min_phi = 0.0;     // min over steps and cells of phi (monitored runs)
    long nonfinite = 0;       // non-finite values seen (monitored runs)
    double correction = 0.0;  // largest clip of the solver's round-off guard (largest_correction)
    double mass_drift = 0.0;  // |sum phi(end) - sum phi(0)| / sum phi(0)
    long steps = 0;
    long long updates = 0;  // cell updates (one per cell and Runge-Kutta stage)
    double seconds = 0.0;   // CPU time of the time loop (CLOCK_PROCESS_CPUTIME_ID)
};

/// Runs `column` from phi0 to t_end with the given scheme options. With `monitor`, the bounds
/// and finiteness are checked after every step (this costs time: the benchmark turns it off).
ColumnRun run_column(const Column& column, const std::vector<double>& phi0, const SegregationOptions& options, double t_end,
                     bool monitor = true);

/// Options with the given scheme and cfl (limiter: mc).
SegregationOptions scheme_options(SegregationScheme scheme, double cfl = 0.9);

/// A scheme's name as a data-file column ("modified_godunov").
std::string scheme_column(SegregationScheme scheme);

/// Relative change of the long-double sum of phi between two states.
double relative_mass_change(const std::vector<double>& before, const std::vector<double>& after);

/// Largest violation of 0 <= phi <= Phi over the cells (0 if the bounds hold).
double bound_violation(const std::vector<double>& phi, const std::vector<double>& Phi);

/// Least-squares slope of log(error) against log(1/N): the observed order over all resolutions.
double fitted_order(const std::vector<int>& cells, const std::vector<double>& errors);

}  // namespace granseg::verify
