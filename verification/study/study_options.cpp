#include "study/study_options.hpp"

#include "core/choice.hpp"
#include "flow_fields/flow_settings.hpp"
#include "core/error.hpp"
#include "harness/side_by_side.hpp"
#include "study/fig7_report.hpp"
#include "scenes/tumbler.hpp"

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

std::vector<double> number_list(const std::string& program, const std::string& option, const std::string& text,
                                double lower, double upper) {
    std::ostringstream allowed;
    allowed << "comma-separated numbers in (" << lower << ", " << upper << "), or none";
    std::vector<double> numbers;
    if (text.empty() || text == "none") return numbers;
    std::istringstream in(text);
    for (std::string item; std::getline(in, item, ',');) {
        char* end = nullptr;
        const double v = std::strtod(item.c_str(), &end);
        if (item.empty() || *end != '\0' || !(v > lower && v < upper)) bad_option(program, option, "\"" + text + "\"", allowed.str());
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

}  // namespace granseg::verify
