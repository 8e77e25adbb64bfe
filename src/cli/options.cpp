#include "cli/options.hpp"

#include "core/error.hpp"
#include "core/format.hpp"

#include <iostream>

namespace granseg::cli {

bool parse_options(const std::string& command, const std::string& usage, const std::vector<std::string>& args,
                   const po::options_description& desc, const po::positional_options_description& positional,
                   po::variables_map& vm) {
    po::options_description all = desc;
    all.add_options()("help", "print this help");
    try {
        namespace style = po::command_line_style;
        po::store(po::command_line_parser(args)
                      .options(all)
                      .positional(positional)
                      .style(style::allow_long | style::long_allow_adjacent | style::long_allow_next)
                      .run(),
                  vm);
        if (vm.count("help")) {
            std::cout << "usage: granseg " << command << " " << usage << "\n\n" << all;
            return false;
        }
        po::notify(vm);
    } catch (const po::error& e) {
        throw InputError("granseg " + command + ": " + e.what() + " (see granseg " + command + " --help)");
    }
    return true;
}

double checked(const std::string& command, const std::string& option, double v, const Range& range) {
    if (!range.contains(v))
        throw InputError("granseg " + command + ": --" + option + ": " + format_number(v) +
                         " is out of range (allowed: " + range.describe(option) + ")");
    return v;
}

}  // namespace granseg::cli
