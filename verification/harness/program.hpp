// Command line, data output and timing helpers shared by the verification programs and benchmarks:
//   PROGRAM [--data DIR]     DIR receives the .dat files for the figures (default build/data).
#pragma once

#include "run/output.hpp"

#include <functional>
#include <map>
#include <string>
#include <vector>

namespace granseg::verify {

struct ProgramOptions {
    std::string data_dir = "build/data";
};

/// Parses argv; prints usage and exits with status 2 on an unknown argument. From then on an
/// InputError or InvariantError that escapes main ends the program with its one-line message
/// and exit status 2 or 3, as in the CLI.
ProgramOptions parse_program_options(int argc, char** argv);

/// The rows of a data file a program wrote (comment lines and blank lines skipped).
std::vector<std::vector<double>> read_rows(const std::string& path);

/// The last row of a table (DataTable text: "# name ..." first, then comments and rows) as
/// column name -> value (nan and inf included); last_row reads it from the file at `path`.
std::map<std::string, double> last_row_of(const std::string& text);
std::map<std::string, double> last_row(const std::string& path);

/// Writes `table` to DIR/name (atomically, see run/output.hpp).
void write_data(const ProgramOptions& options, const std::string& name, const DataTable& table);

/// The median of `values` (the upper one of the middle two for an even count; benchmarks).
double median(std::vector<double> values);

/// CPU time of this process in seconds (POSIX clock_gettime; nanosecond resolution).
double cpu_seconds();

/// Wall-clock (steady_clock) and CPU seconds of some work.
struct Timing {
    double wall = 0.0, cpu = 0.0;
};
/// Runs `work` and adds its wall-clock and CPU seconds to `t`.
void add_timed(Timing& t, const std::function<void()>& work);

/// The machine's load averages over 1, 5 and 15 minutes (/proc/loadavg), for a benchmark's header.
std::string load_average();

}  // namespace granseg::verify
