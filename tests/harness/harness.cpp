// The verification harness: pass/fail logic, NaN handling, exit status, table layout.
#include "harness/check_table.hpp"

#include <boost/test/unit_test.hpp>

#include <cmath>
#include <sstream>

using granseg::verify::CheckTable;

BOOST_AUTO_TEST_SUITE(harness_tests)

BOOST_AUTO_TEST_CASE(all_passing_checks_give_exit_status_zero) {
    std::ostringstream out;
    CheckTable t("demo", out);
    BOOST_TEST(t.near("a", 1.0, 1.0 + 1e-12, 1e-10));
    BOOST_TEST(t.near_relative("b", 100.0, 100.5, 1e-2));
    BOOST_TEST(t.at_most("c", 0.5, 1.0));
    BOOST_TEST(t.at_least("d", 2.0, 1.0));
    BOOST_TEST(t.count("e", 0, 0));
    BOOST_TEST(t.finish() == 0);
    BOOST_TEST(t.passed() == 5);
    BOOST_TEST(out.str().find("demo: 5 checks, 0 failed") != std::string::npos);
}

BOOST_AUTO_TEST_CASE(one_failure_gives_nonzero_exit_status) {
    std::ostringstream out;
    CheckTable t("demo", out);
    t.near("ok", 1.0, 1.0, 0.0);
    BOOST_TEST(!t.near("off by 1e-3", 1.0, 1.001, 1e-4));
    BOOST_TEST(t.finish() != 0);
    BOOST_TEST(t.failed() == 1);
    BOOST_TEST(out.str().find("FAIL") != std::string::npos);
}

BOOST_AUTO_TEST_CASE(non_finite_measurements_always_fail) {
    std::ostringstream out;
    CheckTable t("demo", out);
    BOOST_TEST(!t.near("nan", std::nan(""), 0.0, 1e300));
    BOOST_TEST(!t.at_most("nan bound", std::nan(""), 1.0));
    BOOST_TEST(!t.at_least("inf", INFINITY, 1.0));
    BOOST_TEST(!t.near_relative("inf rel", INFINITY, 1.0, 1e300));
    BOOST_TEST(t.failed() == 4);
}

BOOST_AUTO_TEST_CASE(bounds_and_counts) {
    std::ostringstream out;
    CheckTable t("demo", out);
    BOOST_TEST(!t.at_most("above", 1.0 + 1e-15, 1.0));
    BOOST_TEST(!t.at_least("below", 1.0 - 1e-15, 1.0));
    BOOST_TEST(!t.count("one violation", 1, 0));
    BOOST_TEST(!t.near_relative("relative", 1.02, 1.0, 1e-2));
}

BOOST_AUTO_TEST_CASE(rows_have_the_five_columns) {
    std::ostringstream out;
    CheckTable t("demo", out);
    t.near("a check", 1.5, 1.5, 0.1);
    std::istringstream lines(out.str());
    std::string title, header, rule, row;
    std::getline(lines, title);
    std::getline(lines, header);
    std::getline(lines, rule);
    std::getline(lines, row);
    BOOST_TEST(header.find("check") == 0);
    BOOST_TEST(header.find("| measured") != std::string::npos);
    BOOST_TEST(header.find("| PASS/FAIL") != std::string::npos);
    // The '|' separators of a row line up with the header's.
    BOOST_TEST(row.find('|') == header.find('|'));
    BOOST_TEST(row.rfind('|') == header.rfind('|'));
    BOOST_TEST(row.substr(row.size() - 4) == "PASS");
}

BOOST_AUTO_TEST_SUITE_END()
