// Command line shared by the verification programs and benchmarks:
//   PROGRAM [--data DIR]     DIR receives the .dat files for the figures (default build/data).
#pragma once

#include "core/output.hpp"

#include <string>

namespace granseg::verify {

struct ProgramOptions {
    std::string data_dir = "build/data";
};

/// Parses argv; prints usage and exits with status 2 on an unknown argument. From then on an
/// InputError or InvariantError that escapes main ends the program with its one-line message
/// and exit status 2 or 3, as in the CLI.
ProgramOptions parse_program_options(int argc, char** argv);

/// Writes `table` to DIR/name (atomically, see core/output.hpp).
void write_data(const ProgramOptions& options, const std::string& name, const DataTable& table);

}  // namespace granseg::verify
