// Scene-file validation: every kind of bad input gives one line
// "FILE: [section] key: what (allowed: ...)" and nothing is written.
#include "run/scene_file.hpp"
#include "core/error.hpp"
#include "harness/text_pattern.hpp"
#include "scenes/scene_kind.hpp"

#include <boost/test/unit_test.hpp>

#include <filesystem>
#include <fstream>

using namespace granseg;

namespace {

/// The InputError message of `action`, or "" if it did not throw.
template <class F>
std::string error_of(F action) {
    try {
        action();
    } catch (const InputError& e) {
        return e.what();
    }
    return "";
}

/// Message of reading `key` as a number in [0, 1] from `toml`, then finishing.
std::string number_error(const std::string& toml) {
    return error_of([&] {
        const SceneFile s = SceneFile::parse(toml, "t.toml");
        s.number("grid", "length", Range::left_open(0, 1));
        s.finish();
    });
}

bool is_one_line_in_format(const std::string& message) {
    static const verify::Pattern format(R"(^t\.toml: \[[a-z_]*\] [A-Za-z_]+: .+ \(allowed: .+\)$)");
    return format.matches(message);
}

}  // namespace

BOOST_AUTO_TEST_SUITE(run_scene_file_tests)

BOOST_AUTO_TEST_CASE(valid_file_reads_and_finishes) {
    const SceneFile s = SceneFile::parse(
        "[grid]\ncells = 200\nlength = 1\n[segregation]\nscheme = \"a\"\n"
        "S = 2.5\nlist = [1, 2.5]\nPhi = \"0.6 - 0.1*z\"\non = true\n",
        "t.toml");
    BOOST_TEST(s.integer("grid", "cells", 1, 1000) == 200);
    BOOST_TEST(s.number("grid", "length", Range::above(0)) == 1.0);  // integers are numbers
    BOOST_TEST(s.choice("segregation", "scheme", {"a", "b"}) == "a");
    BOOST_TEST(s.number("segregation", "S", Range::above(0), 1.0) == 2.5);
    BOOST_TEST(s.numbers("segregation", "list", Range::any()).size() == 2u);
    BOOST_TEST(s.expression("segregation", "Phi", {"z"})({1.0}) == 0.5, boost::test_tools::tolerance(1e-15));
    BOOST_TEST(s.flag("segregation", "on", false));
    BOOST_TEST(s.number("segregation", "absent", Range::any(), 7.0) == 7.0);
    BOOST_CHECK_NO_THROW(s.finish());
}

BOOST_AUTO_TEST_CASE(missing_required_key) {
    const std::string m = number_error("[grid]\ncells = 3\n");
    BOOST_TEST(m == "t.toml: [grid] length: missing (allowed: number, 0 < length <= 1)");
}

BOOST_AUTO_TEST_CASE(string_where_a_number_belongs) {
    const std::string m = number_error("[grid]\nlength = \"one\"\n");
    BOOST_TEST(is_one_line_in_format(m), m);
    BOOST_TEST(m.find("expected a number, got the string \"one\"") != std::string::npos);
}

BOOST_AUTO_TEST_CASE(out_of_range_value) {
    const std::string m = number_error("[grid]\nlength = 1.5\n");
    BOOST_TEST(m == "t.toml: [grid] length: 1.5 is out of range (allowed: number, 0 < length <= 1)");
    BOOST_TEST(is_one_line_in_format(number_error("[grid]\nlength = nan\n")));
    BOOST_TEST(is_one_line_in_format(number_error("[grid]\nlength = 0\n")));
}

BOOST_AUTO_TEST_CASE(float_where_an_integer_belongs) {
    const std::string m = error_of([] { SceneFile::parse("[grid]\ncells = 2.5\n", "t.toml").integer("grid", "cells", 1, 9); });
    BOOST_TEST(is_one_line_in_format(m), m);
    BOOST_TEST(m.find("expected an integer") != std::string::npos);
}

BOOST_AUTO_TEST_CASE(unknown_key_names_the_allowed_ones) {
    const std::string m = number_error("[grid]\nlength = 0.5\ncels = 3\n");
    BOOST_TEST(m == "t.toml: [grid] cels: unknown key (allowed: length)");
}

BOOST_AUTO_TEST_CASE(unknown_section) {
    const std::string m = number_error("[grid]\nlength = 0.5\n[gird]\nx = 1\n");
    BOOST_TEST(m == "t.toml: [gird]: unknown section (allowed: grid)");
}

BOOST_AUTO_TEST_CASE(key_outside_any_section) {
    const std::string m = number_error("cells = 3\n[grid]\nlength = 0.5\n");
    BOOST_TEST(m.find("t.toml: cells: key outside any section") == 0u, m);
}

BOOST_AUTO_TEST_CASE(first_problem_in_file_order_is_reported) {
    const std::string m = number_error("[grid]\nlength = 0.5\nzzz = 1\naaa = 2\n");
    BOOST_TEST(m.find("zzz") != std::string::npos);
}

BOOST_AUTO_TEST_CASE(unknown_choice) {
    const std::string m = error_of([] {
        SceneFile::parse("[s]\nscheme = \"upwnd\"\n", "t.toml").choice("s", "scheme", {"upwind", "godunov"});
    });
    BOOST_TEST(m == "t.toml: [s] scheme: unknown value \"upwnd\" (allowed: godunov, upwind)");
}

BOOST_AUTO_TEST_CASE(malformed_expression) {
    const std::string m =
        error_of([] { SceneFile::parse("[initial]\nPhi = \"0.6 - *z\"\n", "t.toml").expression("initial", "Phi", {"z"}); });
    BOOST_TEST(is_one_line_in_format(m), m);
    BOOST_TEST(m.find("malformed expression") != std::string::npos);
    const std::string v =
        error_of([] { SceneFile::parse("[initial]\nPhi = \"0.6 - y\"\n", "t.toml").expression("initial", "Phi", {"z"}); });
    BOOST_TEST(v.find("unknown variable \"y\"") != std::string::npos, v);
}

BOOST_AUTO_TEST_CASE(bad_array_element) {
    const std::string m =
        error_of([] { SceneFile::parse("[s]\nx = [0.1, \"a\"]\n", "t.toml").numbers("s", "x", Range::closed(0, 1)); });
    BOOST_TEST(is_one_line_in_format(m), m);
    BOOST_TEST(m.find("element 2") != std::string::npos);
}

BOOST_AUTO_TEST_CASE(toml_syntax_error_names_line_and_column) {
    const std::string m = error_of([] { SceneFile::parse("[grid]\ncells = = 3\n", "t.toml"); });
    BOOST_TEST(m.find("t.toml: TOML syntax error at line 2") == 0u, m);
    BOOST_TEST(m.find('\n') == std::string::npos);
}

BOOST_AUTO_TEST_CASE(bad_scenes_write_nothing) {
    namespace fs = std::filesystem;
    const fs::path dir = fs::temp_directory_path() / ("granseg_test_" + std::to_string(::getpid()));
    fs::create_directories(dir);
    const std::string out = (dir / "out").string();
    const std::string header = "[output]\ndir = \"" + out + "\"\n";
    const std::vector<std::pair<std::string, std::string>> cases = {
        {"[scene]\nkind = \"no-such-kind\"\n", "[scene] kind: unknown value \"no-such-kind\""},
        {"[scene]\nkind = \"closure-sweep\"\n[sweep]\nPhi_max = 0.6\nPhi_mx = 0.5\n", "[sweep] Phi_mx: unknown key"},
        {"[scene]\nkind = \"closure-sweep\"\n[sweep]\nPhi_max = \"0.6\"\n", "[sweep] Phi_max: expected a number"},
        {"[scene]\nkind = \"closure-sweep\"\n[sweep]\nPhi_max = 0.69\n", "[sweep] Phi_max: 0.69 >= Phi_rcp"},
        {"[scene]\nkind = \"closure-sweep\"\n[sweep]\nPhi_max = 0.6\nT = \"0.01 - Phi\"\n", "[sweep] T: T = "},
    };
    for (const auto& [body, expected] : cases) {
        const std::string file = (dir / "bad.toml").string();
        std::ofstream(file) << header << body;
        const std::string m = error_of([&] { run_scene_file(file); });
        BOOST_TEST(m.find(file + ": " + expected) == 0u, m);
        BOOST_TEST(m.find('\n') == std::string::npos);
        BOOST_TEST(!fs::exists(out), "output written for: " + expected);
    }
    fs::remove_all(dir);
}

BOOST_AUTO_TEST_CASE(valid_scene_writes_its_table) {
    namespace fs = std::filesystem;
    const fs::path dir = fs::temp_directory_path() / ("granseg_test_ok_" + std::to_string(::getpid()));
    const std::string file = (dir / "ok.toml").string();
    fs::create_directories(dir);
    std::ofstream(file) << "[scene]\nkind = \"closure-sweep\"\n[sweep]\nPhi_max = 0.6\npoints = 3\n";
    const auto written = run_scene_file(file, (dir / "out").string());
    BOOST_TEST(written.size() == 1u);
    std::ifstream in(written.at(0));
    std::string first;
    std::getline(in, first);
    BOOST_TEST(first.rfind("# phi_hat Phi T", 0) == 0u);
    fs::remove_all(dir);
}

BOOST_AUTO_TEST_SUITE_END()
