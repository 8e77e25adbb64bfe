// Command line shared by the verification programs and benchmarks:
//   PROGRAM [--data DIR]     DIR receives the .dat files for the figures (default build/data).
#pragma once

#include "core/output.hpp"

#include <string>

namespace granseg::verify {

struct ProgramOptions {
    std::string data_dir = "build/data";
};

/// Parses argv; prints usage and exits with status 2 on an unknown argument.
ProgramOptions parse_program_options(int argc, char** argv);

/// Writes `table` to DIR/name (atomically, see core/output.hpp).
void write_data(const ProgramOptions& options, const std::string& name, const DataTable& table);

}  // namespace granseg::verify
