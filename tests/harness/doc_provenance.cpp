// Where a generated table came from (harness/table_provenance.hpp, harness/doc_provenance.hpp):
// a record reads back as written and leaves the shown table alone; a changed or unrecorded
// fingerprint is named; a page's quotes of a stale table need an earlier-scheme mark, which
// covers its section only and must not name a fresh table; and a physics fingerprint leaves out
// a run's timings and round-off diagnostics but not its results.
#include "harness/doc_provenance.hpp"
#include "harness/number_fingerprint.hpp"
#include "harness/table_provenance.hpp"

#include <boost/test/unit_test.hpp>

#include <string>

BOOST_AUTO_TEST_SUITE(harness_doc_provenance_tests)

using namespace granseg::verify;
using namespace granseg::verify::docs;

namespace {

const std::string kTable = "| a | b |\n|---|---|\n| 1 | 2 |\n\nWritten by `bench_x`.\n";

Provenance sample() {
    return {"bench_x", "build/bench/bench_x --data out", "0123456789ab", {{"flow", "aaaa"}, {"drum", "bbbb"}}};
}

}  // namespace

BOOST_AUTO_TEST_CASE(a_record_reads_back_and_the_page_shows_the_table_without_it) {
    const std::string text = kTable + provenance_record(sample());
    const auto back = parse_provenance(text);
    BOOST_TEST_REQUIRE(back.has_value());
    BOOST_TEST(back->command == sample().command);
    BOOST_TEST(back->commit == sample().commit);
    BOOST_TEST((back->physics == sample().physics));
    BOOST_TEST(shown_part(text) == kTable);
    BOOST_TEST(!parse_provenance(kTable).has_value());
    BOOST_TEST(shown_part(kTable) == kTable);
}

BOOST_AUTO_TEST_CASE(a_changed_or_unrecorded_fingerprint_is_named_by_its_part) {
    BOOST_TEST(physics_changes(sample().physics, {{"flow", "aaaa"}, {"drum", "bbbb"}, {"closures", "cccc"}}).empty());
    const auto changed = physics_changes(sample().physics, {{"flow", "ffff"}, {"drum", "bbbb"}});
    BOOST_TEST_REQUIRE(changed.size() == 1u);
    BOOST_TEST(changed[0].find("the flow step (recorded aaaa, this build ffff)") == 0);
    const auto unknown = physics_changes({{"drum", "unknown"}}, {{"drum", "unknown"}});
    BOOST_TEST_REQUIRE(unknown.size() == 1u);
    BOOST_TEST(unknown[0].find("not recorded") != std::string::npos);
}

BOOST_AUTO_TEST_CASE(quotes_are_blocks_and_value_spans_of_generated_tables) {
    const std::string page =
        "# P\n<!-- generated: t.md -->\n| x |\n<!-- end generated -->\n"
        "a <!-- value: docs/generated/u.md \"a\" | b - docs/generated/t.md \"c\" [d] -->1<!-- /value -->\n"
        "b <!-- value: build/results/v.log \"x\" -->2<!-- /value -->\n";
    const auto quotes = table_quotes(page);
    BOOST_TEST_REQUIRE(quotes.size() == 3u);
    BOOST_TEST(quotes[0].table == "t.md");
    BOOST_TEST(quotes[0].line == 2);
    BOOST_TEST(quotes[1].table == "u.md");
    BOOST_TEST(quotes[2].table == "t.md");
    BOOST_TEST(quotes[2].line == 5);
}

BOOST_AUTO_TEST_CASE(a_mark_covers_the_rest_of_its_section) {
    const std::string page =
        "# Page\n## A\n<!-- earlier scheme: t.md, u.md -->*Made by an earlier scheme.*\n"
        "```sh\n# not a heading\n```\n### A.1\ntext\n## B\ntext\n";
    std::string error;
    const auto marks = scheme_marks(page, error);
    BOOST_TEST(error.empty());
    BOOST_TEST_REQUIRE(marks.size() == 1u);
    BOOST_TEST(marks[0].line == 3);
    BOOST_TEST(marks[0].last_line == 8);  // through the sub-section A.1, up to ## B
    BOOST_TEST(marks[0].tables.size() == 2u);
    BOOST_TEST(marks[0].note == "*Made by an earlier scheme.*");
    scheme_marks("<!-- earlier scheme: -->x\n", error);
    BOOST_TEST(!error.empty());
}

BOOST_AUTO_TEST_CASE(a_stale_quote_needs_a_mark_and_a_fresh_one_must_not_have_one) {
    const std::string quote = "q <!-- value: docs/generated/t.md \"a\" | b -->1<!-- /value -->\n";
    const std::string mark = "<!-- earlier scheme: t.md -->*Made by an earlier scheme.*\n";
    const std::map<std::string, std::vector<std::string>> stale = {{"t.md", {"the flow step (recorded a, this build b)"}}};
    const std::map<std::string, std::vector<std::string>> fresh = {{"t.md", {}}};
    const auto unmarked = quote_findings("## A\n" + quote, stale, {{"t.md", "build/bench/bench_x"}});
    BOOST_TEST_REQUIRE(unmarked.unmarked_stale.size() == 1u);
    BOOST_TEST(unmarked.unmarked_stale[0].find("line 2 quotes t.md") == 0);
    BOOST_TEST(unmarked.unmarked_stale[0].find("the flow step") != std::string::npos);
    BOOST_TEST(unmarked.unmarked_stale[0].find("build/bench/bench_x") != std::string::npos);
    const auto marked = quote_findings("## A\n" + mark + quote, stale, {});
    BOOST_TEST(marked.unmarked_stale.empty());
    BOOST_TEST(marked.malformed.empty());
    // A mark in another section does not cover the quote.
    BOOST_TEST(quote_findings("## A\n" + mark + "## B\n" + quote, stale, {}).unmarked_stale.size() == 1u);
    BOOST_TEST(quote_findings("## A\n" + mark + quote, fresh, {}).marked_fresh.size() == 1u);
    BOOST_TEST(quote_findings("## A\n<!-- earlier scheme: t.md -->\n" + quote, stale, {}).malformed.size() == 1u);  // no note
    BOOST_TEST(quote_findings("## A\n" + mark, stale, {}).malformed.size() == 1u);  // quotes nothing
}

BOOST_AUTO_TEST_CASE(a_physics_fingerprint_leaves_out_timings_and_round_off_but_not_results) {
    const std::string run = "# t angle mass_change wall_seconds\n0.1 23.4567891 1e-16 12.5\n";
    const auto physics = [](const std::string& text) { return numbers_fingerprint(text, 9, counts_in_fingerprint); };
    BOOST_TEST(physics(run) == physics("# t angle mass_change wall_seconds\n0.1 23.4567891 -3e-16 14.0\n"));
    BOOST_TEST(physics(run) != physics("# t angle mass_change wall_seconds\n0.1 23.4567892 1e-16 12.5\n"));
    BOOST_TEST(physics(run) == physics("# t angle mass_change wall_seconds\n0.1 23.45678910004 1e-16 12.5\n"));
}

BOOST_AUTO_TEST_SUITE_END()
