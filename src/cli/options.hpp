// Command-line helpers shared by the granseg subcommands (Boost.Program_options).
#pragma once

#include "run/scene_file.hpp"

#include <boost/program_options.hpp>

#include <string>
#include <vector>

namespace granseg::cli {

namespace po = boost::program_options;

/// Parses `args` (the words after the subcommand) against `desc`, long options only, so that
/// "-1" is read as a value. Returns false if --help was given (after printing the help).
/// Throws InputError "granseg COMMAND: what is wrong" on an unknown option or a bad value.
bool parse_options(const std::string& command, const std::string& usage, const std::vector<std::string>& args,
                   const po::options_description& desc, const po::positional_options_description& positional,
                   po::variables_map& vm);

/// Returns v, or throws InputError "granseg COMMAND: --OPTION: V is out of range (allowed: ...)".
double checked(const std::string& command, const std::string& option, double v, const Range& range);

}  // namespace granseg::cli
