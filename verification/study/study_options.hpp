// Command-line lists of the drum studies (bench_fig7_convergence, bench_time_step). A bad list
// stops the program with one line naming the program, the option and what it allows, exit 2.
#pragma once

#include "study/fig7_study.hpp"

#include <boost/program_options.hpp>

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
std::vector<double> number_list(const std::string& program, const std::string& option, const std::string& text, double lower,
                                double upper);

/// "muscl,donor-cell" -> the transports, each one of [flow] transport's names, no repeats.
std::vector<std::string> transport_list(const std::string& program, const std::string& text);

/// The options every drum study shares: t_end, average_from, jitter_window, threads and lanes
/// (lanes = 0 becomes one per core with one thread per run, else 1); bad_option for one out of range.
void check_run_options(const std::string& program, Fig7Options& o);

/// Adds to `d` the command-line options every drum study shares, stored into `o`: t-end,
/// average-from, jitter-window, threads, lanes, reuse (read the last with `reused`).
void add_run_options(boost::program_options::options_description& d, Fig7Options& o);

/// Parses the command line with `d`: --help prints `d` and exits 0; an unknown or malformed option
/// stops with "PROGRAM: WHAT (allowed: the options of --help)", exit 2. Sets o.reuse from --reuse.
boost::program_options::variables_map parse_study_command_line(const std::string& program, int argc, char** argv,
                                                               const boost::program_options::options_description& d,
                                                               Fig7Options& o);

}  // namespace granseg::verify
