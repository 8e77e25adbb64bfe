// Command-line lists of the drum studies (bench_fig7_convergence, bench_time_step). A bad list
// stops the program with one line naming the program, the option and what it allows, exit 2.
#pragma once

#include "study/fig7_study.hpp"

#include <string>
#include <vector>

namespace granseg::verify {

/// Prints "PROGRAM: --OPTION: WHAT (allowed: ALLOWED)" on stderr and exits with kExitBadInput.
[[noreturn]] void bad_option(const std::string& program, const std::string& option, const std::string& what,
                             const std::string& allowed);

/// "50,70,100" -> {50, 70, 100}; "" or "none" -> {}; each at least the tumbler's smallest grid and
/// at most 2000, strictly increasing.
std::vector<int> cell_list(const std::string& program, const std::string& option, const std::string& text);

/// "0.5,0.25" -> {0.5, 0.25}; "" or "none" -> {}; each number in the open interval (lower, upper).
std::vector<double> number_list(const std::string& program, const std::string& option, const std::string& text,
                                double lower, double upper);

/// "muscl,donor-cell" -> the transports, each one of [flow] transport's names, no repeats.
std::vector<std::string> transport_list(const std::string& program, const std::string& text);

/// The options every drum study shares: t_end, average_from, jitter_window, threads and lanes
/// (lanes = 0 becomes one per core with one thread per run, else 1); bad_option for one out of range.
void check_run_options(const std::string& program, Fig7Options& o);

}  // namespace granseg::verify
