// granseg: command-line entry point. `granseg --help` lists the subcommands,
// `granseg COMMAND --help` explains one.
#include "cli/commands.hpp"
#include "core/error.hpp"

#include <sys/resource.h>

#include <cstdio>
#include <exception>
#include <fstream>
#include <iostream>
#include <new>
#include <string>

namespace granseg::cli {

const std::vector<Command>& commands() {
    static const std::vector<Command> table = {
        {"closures", "print the Sect. 2.1 closures at one state (Phi, phi_hat, T)", closures_main},
        {"direction", "the Sect. 2.3 segregation direction d_s at one point (grad u, u)", direction_main},
        {"run", "run a scene file (TOML); `granseg run --help` lists the scene kinds", run_main},
        {"riemann", "solve one Riemann problem of system (52) exactly (Sect. 3.2, Table 1)", riemann_main},
    };
    return table;
}

}  // namespace granseg::cli

namespace {

std::string gigabytes(double bytes) {
    char text[32];
    std::snprintf(text, sizeof text, "%.2f GB", bytes / 1e9);
    return text;
}

/// One line for a run that could not get its memory: it needed more than it held at its peak
/// (VmPeak, the most address space it had), beyond what the process may use (ulimit -v).
std::string out_of_memory() {
    double peak = 0.0;
    std::ifstream status("/proc/self/status");
    for (std::string word; status >> word;)
        if (word == "VmPeak:" && status >> peak) peak *= 1024.0;  // kB
    rlimit limit{};
    const bool limited = getrlimit(RLIMIT_AS, &limit) == 0 && limit.rlim_cur != RLIM_INFINITY;
    return "granseg: out of memory: the run needed more than the " + gigabytes(peak) + " it held at its peak, beyond " +
           (limited ? "the " + gigabytes(static_cast<double>(limit.rlim_cur)) + " this process may use (ulimit -v)"
                    : std::string("what the machine gave it")) +
           " (allowed: a run that fits: fewer cells, e.g. [drum] cells_per_diameter, or more memory)";
}

void print_help() {
    std::cout << "granseg: reference code for 'Size segregation in compressible granular shear flows\n"
                 "of binary particle systems' (Gilberg, Klar & Steiner, Granular Matter 22, 45, 2020).\n\n"
                 "usage: granseg COMMAND [options]    (granseg COMMAND --help for its options)\n\n"
                 "commands:\n";
    for (const auto& c : granseg::cli::commands()) {
        std::string name = c.name;
        name.resize(12, ' ');
        std::cout << "  " << name << c.summary << '\n';
    }
}

}  // namespace

int main(int argc, char** argv) {
    using namespace granseg;
    const std::vector<std::string> words(argv + 1, argv + argc);
    if (words.empty() || words[0] == "--help" || words[0] == "-h" || words[0] == "help") {
        print_help();
        return words.empty() ? kExitBadInput : kExitOk;
    }
    try {
        for (const auto& c : cli::commands())
            if (words[0] == c.name) return c.main(std::vector<std::string>(words.begin() + 1, words.end()));
        throw InputError("granseg: unknown command \"" + words[0] + "\" (see granseg --help)");
    } catch (const InputError& e) {
        std::cerr << e.what() << '\n';
        return kExitBadInput;
    } catch (const InvariantError& e) {
        std::cerr << "granseg: stopped, invariant broken: " << e.what() << '\n';
        return kExitInvariant;
    } catch (const Interrupted& e) {
        std::cerr << e.what() << '\n';
        return 128 + e.signal();
    } catch (const std::bad_alloc&) {
        std::cerr << out_of_memory() << '\n';
        return kExitFailure;
    } catch (const std::exception& e) {
        std::cerr << "granseg: error: " << e.what() << '\n';
        return kExitFailure;
    }
}
