// The checks behind verify_docs: the number-aware line matcher, generated blocks, the history,
// outside-reference and link detectors, and the figure fingerprint.
#include "harness/doc_blocks.hpp"
#include "harness/doc_figures.hpp"
#include "harness/doc_hygiene.hpp"

#include <boost/test/unit_test.hpp>

#include <filesystem>
#include <fstream>
#include <string>

namespace fs = std::filesystem;

BOOST_AUTO_TEST_SUITE(doc_checks)

using namespace granseg::verify::docs;

BOOST_AUTO_TEST_CASE(numbers_agree_to_the_precision_the_page_prints) {
    const Tokens page = tokens_of("fitted p | 0.9382 | 1");
    BOOST_TEST(agrees(tokens_of("fitted p   |   0.93824 | 1"), page));   // blanks collapse; within half a unit
    BOOST_TEST(!agrees(tokens_of("fitted p | 0.93826 | 1"), page));      // beyond half a unit
    BOOST_TEST(!agrees(tokens_of("fitted q | 0.9382 | 1"), page));       // a word differs
    BOOST_TEST(!agrees(tokens_of("fitted p | 0.9382 | 1 | 2"), page));   // a number more
    BOOST_TEST(agrees(tokens_of("g = 1.577e-06"), tokens_of("g = 1.6e-06")));
    BOOST_TEST(!agrees(tokens_of("g = 1.577e-06"), tokens_of("g = 1.5e-06")));
}

BOOST_AUTO_TEST_CASE(a_number_moved_by_one_digit_no_longer_agrees) {
    for (const char* line : {"sample = 0 0.644948974278", "count | 30 | 30 | 0", "p_k = 1.046400526e-05"}) {
        const Tokens t = tokens_of(line);
        BOOST_TEST(agrees(t, t));
        BOOST_TEST(!agrees(t, mutated(t)));
    }
}

BOOST_AUTO_TEST_CASE(expected_lines_match_in_order) {
    const std::vector<std::string> printed = {"a = 1", "noise", "b = 2.5", "c = 3"};
    BOOST_TEST(compare({"a = 1", "c = 3"}, printed).missing == 0);
    const Comparison wrong_order = compare({"c = 3", "a = 1"}, printed);
    BOOST_TEST(wrong_order.missing == 1);
    BOOST_TEST(wrong_order.first_missing == "a = 1");
    const Comparison changed = compare({"b = 2.6"}, printed);
    BOOST_TEST(changed.missing == 1);
    BOOST_TEST(changed.nearest == "b = 2.5");
}

BOOST_AUTO_TEST_CASE(fenced_blocks_and_their_exit_status) {
    const auto blocks = fenced_blocks("text\n```sh exit=2\nfalse\n```\n```output\nx\n```\n```\nplain\n```\n");
    BOOST_TEST_REQUIRE(blocks.size() == 3u);
    BOOST_TEST(blocks[0].language == "sh");
    BOOST_TEST(expected_status(blocks[0]) == 2);
    BOOST_TEST(blocks[1].lines.front() == "x");
    BOOST_TEST(blocks[2].language.empty());
}

BOOST_AUTO_TEST_CASE(generated_blocks_are_found_and_replaced) {
    const std::string page = "a\n<!-- generated: t.md -->\n| 1 |\n<!-- end generated -->\nb\n";
    std::string error;
    const auto blocks = generated_blocks(page, error);
    BOOST_TEST(error.empty());
    BOOST_TEST_REQUIRE(blocks.size() == 1u);
    BOOST_TEST(blocks[0].name == "t.md");
    BOOST_TEST(blocks[0].text == "| 1 |\n");
    BOOST_TEST(with_generated(page, "t.md", "| 2 |\n| 3 |\n") ==
               "a\n<!-- generated: t.md -->\n| 2 |\n| 3 |\n<!-- end generated -->\nb\n");
    generated_blocks("<!-- generated: t.md -->\nno end\n", error);
    BOOST_TEST(!error.empty());
}

BOOST_AUTO_TEST_CASE(history_is_flagged_and_citations_are_not) {
    for (const char* line : {"on 2 December 2026", "in May 2025", "main af0974d", "an Intel Xeon", "2026-12-03",
                             "780 s on today's machine", "load average 0.4"})
        BOOST_TEST(history_findings(line).size() == 1u, line);
    for (const char* line : {"Gray & Thornton (2005)", "12800 cells", "p_k = 1.046400526e-05", "colour #1f77b4",
                             "Desmond & Weeks, Phys. Rev. E 90, 022204 (2014)"})
        BOOST_TEST(history_findings(line).empty(), line);
}

BOOST_AUTO_TEST_CASE(references_outside_the_repository_are_flagged) {
    BOOST_TEST(outside_references(std::string("see ../") + "sha" + "red/paper/x").size() == 1u);
    BOOST_TEST(outside_references(std::string("(model") + ".md 3.4)").size() == 1u);
    BOOST_TEST(outside_references("see docs/paper_notes.md").empty());
}

BOOST_AUTO_TEST_CASE(links_must_lead_to_files_of_the_repository) {
    const fs::path root = fs::temp_directory_path() / "granseg_test_links";
    fs::create_directories(root / "docs");
    std::ofstream(root / "docs" / "b.md") << "# B page\n\n## 2. The part\n";
    const std::string page = "[b](b.md) [part](b.md#2-the-part) [web](https://example.org)\n"
                             "![f](../build/figures/x.png) [gone](c.md) [bad anchor](b.md#nothing)\n";
    const auto found = broken_links(page, root / "docs", root);
    fs::remove_all(root);
    BOOST_TEST_REQUIRE(found.size() == 3u);
    BOOST_TEST(found[0].text.find("build/") != std::string::npos);
    BOOST_TEST(found[1].text.find("no such file") != std::string::npos);
    BOOST_TEST(found[2].text.find("anchor") != std::string::npos);
}

BOOST_AUTO_TEST_CASE(fingerprints_see_what_a_figure_shows_and_nothing_finer) {
    const std::string data = "# x y\n0.1 1.2341e-3\n0.2 2.0\n\n0.3 1e-20\n";
    BOOST_TEST(data_fingerprint(data) == data_fingerprint("# x y (other comment)\n0.1 1.23412e-3\n0.2 2.0\n\n0.3 -3e-21\n"));
    BOOST_TEST(data_fingerprint(data) != data_fingerprint("# x y\n0.1 1.2361e-3\n0.2 2.0\n\n0.3 1e-20\n"));
    BOOST_TEST(data_fingerprint(data) != data_fingerprint("# x y\n0.1 1.2341e-3\n0.2 2.0\n0.3 1e-20\n"));
}

BOOST_AUTO_TEST_SUITE_END()
