#include "harness/program.hpp"

#include "core/error.hpp"

#include <cstdlib>
#include <iostream>

namespace granseg::verify {

ProgramOptions parse_program_options(int argc, char** argv) {
    ProgramOptions options;
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        if (arg == "--data" && i + 1 < argc) {
            options.data_dir = argv[++i];
        } else {
            std::cerr << argv[0] << ": unknown argument \"" << arg << "\" (allowed: --data DIR)\n";
            std::exit(kExitBadInput);
        }
    }
    return options;
}

void write_data(const ProgramOptions& options, const std::string& name, const DataTable& table) {
    write_file_atomically(options.data_dir + "/" + name, table.str());
}

}  // namespace granseg::verify
