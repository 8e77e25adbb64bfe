#include "study/study_options.hpp"

#include "core/choice.hpp"
#include "core/error.hpp"
#include "flow/fields/flow_settings.hpp"
#include "harness/side_by_side.hpp"
#include "harness/table_provenance.hpp"
#include "scenes/tumbler.hpp"
#include "study/fig7_report.hpp"

#include <algorithm>
#include <cstdlib>
#include <iostream>
#include <sstream>

namespace granseg::verify {

void bad_option(const std::string& program, const std::string& option, const std::string& what, const std::string& allowed) {
    std::cerr << program << ": --" << option << ": " << what << " (allowed: " << allowed << ")\n";
    std::exit(kExitBadInput);
}

std::vector<int> cell_list(const std::string& program, const std::string& option, const std::string& text) {
    const std::string allowed = "comma-separated increasing integers >= " + std::to_string(min_tumbler_cells()) + ", or none";
    std::vector<int> cells;
    if (text.empty() || text == "none") return cells;
    std::istringstream in(text);
    for (std::string item; std::getline(in, item, ',');) {
        std::size_t used = 0;
        int n = 0;
        try {
            n = std::stoi(item, &used);
        } catch (const std::exception&) {
            bad_option(program, option, "\"" + item + "\" is not an integer", allowed);
        }
        if (used != item.size() || n < min_tumbler_cells() || n > 2000 || (!cells.empty() && n <= cells.back()))
            bad_option(program, option, "\"" + text + "\"", allowed);
        cells.push_back(n);
    }
    return cells;
}

std::vector<double> number_list(const std::string& program, const std::string& option, const std::string& text, double lower,
                                double upper) {
    std::ostringstream allowed;
    allowed << "comma-separated numbers in (" << lower << ", " << upper << "), or none";
    std::vector<double> numbers;
    if (text.empty() || text == "none") return numbers;
    std::istringstream in(text);
    for (std::string item; std::getline(in, item, ',');) {
        char* end = nullptr;
        const double v = std::strtod(item.c_str(), &end);
        if (item.empty() || *end != '\0' || !(v > lower && v < upper))
            bad_option(program, option, "\"" + text + "\"", allowed.str());
        numbers.push_back(v);
    }
    return numbers;
}

std::vector<std::string> transport_list(const std::string& program, const std::string& text) {
    const std::vector<std::string> names = choice_names(kTransports);
    std::string allowed;
    for (const std::string& n : names) allowed += (allowed.empty() ? "" : ", ") + n;
    std::vector<std::string> out;
    std::istringstream in(text);
    for (std::string item; std::getline(in, item, ',');) {
        if (std::find(names.begin(), names.end(), item) == names.end() || std::find(out.begin(), out.end(), item) != out.end())
            bad_option(program, "transports", "\"" + text + "\"", "comma-separated, each once: " + allowed);
        out.push_back(item);
    }
    if (out.empty()) bad_option(program, "transports", "\"" + text + "\"", "one or more of " + allowed);
    return out;
}

void check_run_options(const std::string& program, Fig7Options& o) {
    if (!(o.t_end > 0.0 && o.t_end <= 1000.0)) bad_option(program, "t-end", fig7_number(o.t_end), "0 < t_end <= 1000");
    if (!(o.average_from >= 0.0 && o.average_from < o.t_end))
        bad_option(program, "average-from", fig7_number(o.average_from), "0 <= average_from < t_end");
    if (!(o.jitter_window > 0.0 && o.jitter_window <= o.t_end))
        bad_option(program, "jitter-window", fig7_number(o.jitter_window), "0 < jitter_window <= t_end");
    if (o.threads < 1 || o.threads > 256) bad_option(program, "threads", std::to_string(o.threads), "1..256");
    if (o.lanes == 0) o.lanes = o.threads == 1 ? machine_cores() : 1;
    if (o.lanes < 1 || o.lanes > 256 || (o.lanes > 1 && o.threads != 1))
        bad_option(program, "lanes", std::to_string(o.lanes), "0..256, and 1 unless --threads 1");
}

void add_run_options(boost::program_options::options_description& d, Fig7Options& o) {
    namespace po = boost::program_options;
    d.add_options()("t-end", po::value(&o.t_end)->default_value(o.t_end), "s, length of every run")(
        "average-from", po::value(&o.average_from)->default_value(o.average_from),
        "s, start of the angle's and layer's averages")(
        "jitter-window", po::value(&o.jitter_window)->default_value(o.jitter_window), "s before t_end for a value's jitter")(
        "threads", po::value(&o.threads)->default_value(o.threads), "OpenMP threads of every run")(
        "lanes", po::value(&o.lanes)->default_value(o.lanes), "runs side by side, one thread each (0: one per core)")(
        "reuse", "reuse a run whose scene text is unchanged (after changing the code: do not)");
}

boost::program_options::variables_map parse_study_command_line(const std::string& program, int argc, char** argv,
                                                               const boost::program_options::options_description& d,
                                                               Fig7Options& o) {
    namespace po = boost::program_options;
    remember_command_line(argc, argv);  // for the tables it writes (harness/table_provenance.hpp)
    po::variables_map vm;
    try {
        po::store(po::parse_command_line(argc, argv, d), vm);
        po::notify(vm);
    } catch (const po::error& e) {
        std::cerr << program << ": " << e.what() << " (allowed: the options of --help)\n";
        std::exit(kExitBadInput);
    }
    if (vm.count("help")) std::cout << d << "\n", std::exit(0);
    o.reuse = vm.count("reuse") > 0;
    return vm;
}

}  // namespace granseg::verify
