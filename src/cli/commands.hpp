// The granseg subcommands. Each takes the words after its name and returns the exit status;
// bad arguments throw InputError (exit 2), handled in main.cpp.
#pragma once

#include <string>
#include <vector>

namespace granseg::cli {

struct Command {
    const char* name;
    const char* summary;
    int (*main)(const std::vector<std::string>& args);
};

/// Every subcommand, in the order `granseg --help` lists them.
const std::vector<Command>& commands();

int closures_main(const std::vector<std::string>& args);
int direction_main(const std::vector<std::string>& args);
int run_main(const std::vector<std::string>& args);
int riemann_main(const std::vector<std::string>& args);

}  // namespace granseg::cli
