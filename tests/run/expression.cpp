// muparser expressions: evaluation, variables, and the errors users see.
#include "run/expression.hpp"
#include "core/error.hpp"

#include <boost/test/unit_test.hpp>

#include <cmath>

using granseg::Expression;
using granseg::InputError;

BOOST_AUTO_TEST_SUITE(run_expression_tests)

BOOST_AUTO_TEST_CASE(evaluates_with_variables_in_order) {
    const Expression e("0.62 - 0.08*cos(_pi*z)^2 + 0*T", {"z", "T"});
    BOOST_TEST(e({0.0, 5.0}) == 0.54, boost::test_tools::tolerance(1e-15));
    BOOST_TEST(e({0.5, 5.0}) == 0.62, boost::test_tools::tolerance(1e-15));
}

BOOST_AUTO_TEST_CASE(copies_are_independent) {
    const Expression a("2*x", {"x"});
    Expression b = a;
    BOOST_TEST(b({3.0}) == 6.0);
    BOOST_TEST(a({1.0}) == 2.0);
    BOOST_TEST(b.text() == "2*x");
}

BOOST_AUTO_TEST_CASE(unknown_variable_is_named) {
    try {
        Expression("z + y", {"z"});
        BOOST_FAIL("no exception");
    } catch (const InputError& e) {
        BOOST_TEST(std::string(e.what()).find("unknown variable \"y\"") != std::string::npos);
    }
}

BOOST_AUTO_TEST_CASE(syntax_error_is_one_line) {
    try {
        Expression("0.6 - *z", {"z"});
        BOOST_FAIL("no exception");
    } catch (const InputError& e) {
        const std::string what = e.what();
        BOOST_TEST(what.find("malformed expression") != std::string::npos);
        BOOST_TEST(what.find('\n') == std::string::npos);
    }
    BOOST_CHECK_THROW(Expression("sin(", {"z"}), InputError);
    BOOST_CHECK_THROW(Expression("", {"z"}), InputError);
}

BOOST_AUTO_TEST_CASE(wrong_number_of_values_throws) {
    const Expression e("z", {"z"});
    BOOST_CHECK_THROW(e({1.0, 2.0}), InputError);
}

BOOST_AUTO_TEST_SUITE_END()
