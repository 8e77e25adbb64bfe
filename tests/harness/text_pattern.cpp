// The regular expressions of the page checks: the literal prefilter never rules out a text that
// matches, and finds what each kind of expression requires.
#include "harness/text_pattern.hpp"

#include <boost/test/unit_test.hpp>

#include <string>
#include <vector>

using granseg::verify::Pattern;
using granseg::verify::required_literals;
using Literals = std::vector<std::string>;

BOOST_AUTO_TEST_SUITE(text_pattern_tests)

BOOST_AUTO_TEST_CASE(required_literals_of_each_kind_of_expression) {
    // The longest run; an optional character ends it (and is left out), a repeated one ends it.
    BOOST_TEST(required_literals(R"(every 1000 steps)", false) == Literals{"every 1000 steps"});
    BOOST_TEST(required_literals(R"(\bsteps? per \d+ s)", false) == Literals{" per "});
    BOOST_TEST(required_literals(R"(ab+cd)", false) == Literals{"ab"});
    BOOST_TEST(required_literals(R"(0\.9 of)", false) == Literals{"0.9 of"});
    // One requirement per top-level alternative, joined; a group's alternatives when the group is
    // the best that must appear; lower case when case is ignored.
    BOOST_TEST(required_literals(R"(foo|bar(x|y)?z)", false) == (Literals{"bar", "foo"}));
    BOOST_TEST(required_literals(R"(\b(Xeon|EPYC)\b)", false) == (Literals{"EPYC", "Xeon"}));
    BOOST_TEST(required_literals(R"(\b(Today|yesterday)\b)", true) == (Literals{"today", "yesterday"}));
    // A digit that must appear: the ten digits, unless a literal as short is required too.
    BOOST_TEST(required_literals(R"(\b\d{4}\b)", false).size() == 10u);
    BOOST_TEST(required_literals(R"(\b\d{4}-)", false) == Literals{"-"});  // as short, fewer
    // Nothing required: an alternative of classes only, an optional or a lookahead group.
    BOOST_TEST(required_literals(R"([a-z]+|foo)", false).empty());
    BOOST_TEST(required_literals(R"((foo)?\w)", false).empty());
    BOOST_TEST(required_literals(R"((?=foo)\w+)", false).empty());
    BOOST_TEST(required_literals(R"(\d?x{0,2})", false).empty());
}

BOOST_AUTO_TEST_CASE(the_prefilter_keeps_every_match) {
    struct Case {
        const char* expression;
        bool ignore_case;
        const char* text;
    };
    const Case cases[] = {
        {R"(0\.1 (rev/s|rps))", false, "the drum turns at 0.1 rps here"},
        {R"(\b(this|the shared) machine\b)", true, "on The Shared Machine we"},
        {R"(\b\d{1,2} (May|June),? \d{4}\b)", false, "on 7 June 2026 it ran"},
        {R"(φ̂0? = 0\.5|initial 0\.5)", false, "with φ̂0 = 0.5 at first"},
        {R"(a\+b|c\(d\))", false, "x c(d) y"},
        {R"(^\|\s+\|.*)", false, "|   | key | range |"},
        {R"(ab+c)", false, "abbbc"},
    };
    for (const Case& c : cases) {
        const Pattern p(c.expression, c.ignore_case);
        BOOST_TEST_CONTEXT(c.expression) {
            BOOST_TEST(p.found_in(c.text));
            BOOST_TEST(p.all_in(c.text).size() == 1u);
            BOOST_TEST(p.removed_from(c.text) != std::string(c.text));
        }
    }
    // And a text without the literal is answered without the expression.
    BOOST_TEST(!Pattern(R"(every 1000 steps)").found_in("every 100 steps"));
}

BOOST_AUTO_TEST_SUITE_END()
