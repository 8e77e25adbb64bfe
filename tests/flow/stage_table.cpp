// The flow step's stages are written down three times: the enum FlowStage (whose labels name the
// summaries' seconds_LABEL columns), the header comment of flow/flow_solver.hpp (the walk-through
// of both modes and the table of what each stage reads and writes), and the code, where each
// stage's scope is timed by a Stopwatch. This suite holds the comment and the code against the enum,
// so that a stage added, renamed or reordered in one place fails here until the others follow.
#include "flow/flow_solver.hpp"

#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

using namespace granseg;

namespace {

std::string text_of(const std::string& path) {
    std::ifstream in(path);
    BOOST_REQUIRE_MESSAGE(in, "cannot read " << path << " (make test runs from the repository's top folder)");
    std::ostringstream all;
    all << in.rdbuf();
    return all.str();
}

std::vector<std::string> labels() {
    std::vector<std::string> all;
    for (int k = 0; k < kFlowStages; ++k) all.push_back(flow_stage_name(static_cast<FlowStage>(k)));
    return all;
}

/// The rows of the header's table of reads and writes, by mode: "both" (closures, temperature),
/// "explicit" and "semi-implicit", each its stage names in order.
std::vector<std::pair<std::string, std::string>> table_rows(const std::string& header) {
    std::vector<std::pair<std::string, std::string>> rows;
    std::istringstream in(header.substr(header.find("//   stage            reads")));
    std::string line, mode = "both";
    std::getline(in, line);
    const std::regex row(R"(^//   ([a-z_]+) +\S.*)"), heading(R"(^//   (explicit|semi-implicit) step:$)");
    for (std::smatch m; std::getline(in, line) && line != "//";) {
        if (std::regex_match(line, m, heading))
            mode = m[1];
        else if (std::regex_match(line, m, row))
            rows.emplace_back(m[1] == "temperature" ? "both" : mode, m[1]);
    }
    return rows;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(flow_stage_table_tests)

BOOST_AUTO_TEST_CASE(the_table_lists_the_semi_implicit_step_in_the_enums_order_and_the_explicit_steps_stages) {
    const auto rows = table_rows(text_of("src/flow/flow_solver.hpp"));
    std::vector<std::string> semi_implicit, explicit_step;
    for (const auto& [mode, name] : rows) {
        if (mode != "explicit") semi_implicit.push_back(name);
        if (mode != "semi-implicit") explicit_step.push_back(name);
    }
    BOOST_TEST(semi_implicit == labels(), boost::test_tools::per_element());
    for (const std::string& name : explicit_step) {
        const auto all = labels();
        BOOST_TEST((std::find(all.begin(), all.end(), name) != all.end()), name << " is no FlowStage");
    }
}

BOOST_AUTO_TEST_CASE(every_stage_is_walked_through_and_timed_in_the_code) {
    const std::string header = text_of("src/flow/flow_solver.hpp");
    const std::string code = text_of("src/flow/flow_solver.cpp") + text_of("src/flow/semi_implicit_step.cpp");
    for (const std::string& name : labels()) {
        BOOST_TEST(header.find("\n//   " + name + ": ") != std::string::npos, name << " is not walked through");
        BOOST_TEST(code.find("Stopwatch watch(timers_, FlowStage::" + name + ")") != std::string::npos, name << " is not timed");
    }
}

BOOST_AUTO_TEST_SUITE_END()
