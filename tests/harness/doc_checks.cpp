// The checks behind verify_docs: the number-aware line matcher, generated blocks, value spans and
// their sources, the numbers in prose, the history, outside-reference and link detectors, and the
// figure fingerprint.
#include "harness/doc_blocks.hpp"
#include "harness/doc_excerpts.hpp"
#include "harness/doc_figures.hpp"
#include "harness/doc_hygiene.hpp"
#include "harness/doc_prose.hpp"
#include "harness/doc_values.hpp"

#include <boost/test/unit_test.hpp>

#include <filesystem>
#include <fstream>
#include <string>

namespace fs = std::filesystem;

BOOST_AUTO_TEST_SUITE(harness_doc_checks_tests)

using namespace granseg::verify::docs;

BOOST_AUTO_TEST_CASE(numbers_agree_to_the_precision_the_page_prints) {
    const Tokens page = tokens_of("fitted p | 0.9382 | 1");
    BOOST_TEST(agrees(tokens_of("fitted p   |   0.93824 | 1"), page));  // blanks collapse; within half a unit
    BOOST_TEST(!agrees(tokens_of("fitted p | 0.93826 | 1"), page));     // beyond half a unit
    BOOST_TEST(!agrees(tokens_of("fitted q | 0.9382 | 1"), page));      // a word differs
    BOOST_TEST(!agrees(tokens_of("fitted p | 0.9382 | 1 | 2"), page));  // a number more
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
    // Lines left out are marked by `...` (the tutorial's rule): between, before and after.
    BOOST_TEST(compare({"a = 1", "c = 3"}, printed).unmarked_gaps == 1);
    BOOST_TEST(compare({"a = 1", "...", "c = 3"}, printed).unmarked_gaps == 0);
    BOOST_TEST(compare({"...", "b = 2.5"}, printed).unmarked_gaps == 1);
    BOOST_TEST(compare({"...", "b = 2.5", "..."}, printed).unmarked_gaps == 0);
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

BOOST_AUTO_TEST_CASE(value_spans_are_found_with_their_place) {
    const std::string page =
        "a <!-- value: docs/t.md \"x\" -->0.93<!-- /value --> b <!-- value: build/d.dat:c@last -->12<!-- /value -->\n"
        "```\n<!-- value: in a code block -->1<!-- /value -->\n```\n";
    std::string error;
    const auto spans = value_spans(page, error);
    BOOST_TEST(error.empty());
    BOOST_TEST_REQUIRE(spans.size() == 2u);
    BOOST_TEST(spans[0].source == "docs/t.md \"x\"");
    BOOST_TEST(spans[0].text == "0.93");
    BOOST_TEST(page.substr(spans[1].offset, 2) == "12");
    BOOST_TEST(spans[1].line == 1);
    value_spans("x <!-- value: docs/t.md \"x\" -->0.93\n<!-- /value -->\n", error);
    BOOST_TEST(!error.empty());  // a span ends on its own line
}

BOOST_AUTO_TEST_CASE(sources_parse_and_bad_ones_say_why) {
    std::string error;
    const auto cell = parse_source("docs/generated/s.md \"segregation index\" | at 100 cells #2 *100", error);
    BOOST_TEST_REQUIRE(cell.has_value());
    BOOST_TEST(cell->file == "docs/generated/s.md");
    BOOST_TEST(cell->match == "segregation index");
    BOOST_TEST(cell->column == "at 100 cells");
    BOOST_TEST(cell->number == 2);
    BOOST_TEST(cell->scale == 100.0);
    const auto line = parse_source("build/results/v.log \"d. pattern\" #-1 /3600", error);
    BOOST_TEST_REQUIRE(line.has_value());
    BOOST_TEST(line->column.empty());
    BOOST_TEST(line->number == -1);
    BOOST_TEST(line->scale == 1.0 / 3600);
    const auto data = parse_source("build/data/summary.dat:angle_mean_deg@cells=100", error);
    BOOST_TEST_REQUIRE(data.has_value());
    BOOST_TEST(data->data);
    BOOST_TEST(data->row == "cells=100");
    BOOST_TEST(!parse_source("docs/x.md angle", error).has_value());     // no quoted match
    BOOST_TEST(!parse_source("../x.md \"a\"", error).has_value());       // outside docs/ and build/
    BOOST_TEST(!parse_source("docs/x.md \"a\" *0", error).has_value());  // a scale must be positive
}

BOOST_AUTO_TEST_CASE(sources_read_lines_table_cells_and_data_columns) {
    std::string error;
    const std::string log = "a. ring | 0.4357 | >= 0 | - | PASS\n# d. pattern at t = 25 s: index 0.89, ring 0.9357\n";
    BOOST_TEST(*source_value(*parse_source("build/results/v.log \"d. pattern\" #-1", error), log, error) == 0.9357);
    BOOST_TEST(*source_value(*parse_source("build/results/v.log \"d. pattern\" #2", error), log, error) == 0.89);
    BOOST_TEST(*source_value(*parse_source("build/results/v.log \"index\"", error), log, error) == 0.89);     // after MATCH
    BOOST_TEST(*source_value(*parse_source("build/results/v.log \"ring\"~2", error), log, error) == 0.9357);  // the second line
    BOOST_TEST(!source_value(*parse_source("build/results/v.log \"ring\"~3", error), log, error).has_value());
    BOOST_TEST(!source_value(*parse_source("build/results/v.log \"d. pattern\" #4", error), log, error).has_value());
    BOOST_TEST(!source_value(*parse_source("build/results/v.log \"no such line\"", error), log, error).has_value());
    const std::string table =
        "| quantity | at 100 cells | distance to the limit | limit |\n|---|---|---|---|\n"
        "| angle (deg) | 23.4 ± 0.02 | – | – |\n| index | 0.936 ± 0.001 | -0.014 | 0.95 |\n\nFootnote 7.\n";
    BOOST_TEST(*source_value(*parse_source("docs/t.md \"index\" | limit", error), table, error) == 0.95);
    BOOST_TEST(*source_value(*parse_source("docs/t.md \"angle\" | at 100 #2 *10", error), table, error) == 0.2);
    BOOST_TEST(*source_value(*parse_source("docs/t.md \"index\" [limit]", error), table, error) == 0.95);  // inside a table row
    BOOST_TEST(!source_value(*parse_source("docs/t.md \"angle\" | limit", error), table, error).has_value());     // a dash
    BOOST_TEST(!source_value(*parse_source("docs/t.md \"Footnote\" | limit", error), table, error).has_value());  // not a row
    const std::string dat = "# cells angle\n# a comment 5\n50 23.5\n100 23.4\n\n140 23.3\n";
    BOOST_TEST(*source_value(*parse_source("build/d.dat:angle@last", error), dat, error) == 23.3);
    BOOST_TEST(*source_value(*parse_source("build/d.dat:angle@2", error), dat, error) == 23.4);
    BOOST_TEST(*source_value(*parse_source("build/d.dat:angle@cells=50", error), dat, error) == 23.5);
    BOOST_TEST(!source_value(*parse_source("build/d.dat:wall@last", error), dat, error).has_value());
    BOOST_TEST(!source_value(*parse_source("build/d.dat:angle@4", error), dat, error).has_value());
}

BOOST_AUTO_TEST_CASE(spans_resolve_against_their_files_and_differences) {
    const fs::path root = fs::temp_directory_path() / "granseg_test_spans";
    fs::create_directories(root / "docs" / "generated");
    fs::create_directories(root / "build" / "results");
    std::ofstream(root / "docs" / "generated" / "t.md") << "| q | a | b |\n|---|---|---|\n| x | 23.51 | 23.31 |\n";
    std::ofstream(root / "build" / "results" / "v.log") << "steps: 12503\n";
    const std::string page =
        "<!-- value: docs/generated/t.md \"x\" | b - docs/generated/t.md \"x\" | a -->-0.20<!-- /value -->\n"
        "<!-- value: build/results/v.log \"steps:\" + docs/generated/t.md \"x\" | a -->12526.51<!-- /value -->\n"
        "<!-- value: build/results/w.log \"steps:\" -->1<!-- /value -->\n"
        "```output\nflux = -0.125\n```\nso <!-- value: output \"flux = \" -->-0.125<!-- /value -->\n";
    std::string error;
    const auto spans = resolved_spans(page, root, root / "build", error);
    fs::remove_all(root);
    BOOST_TEST(error.empty());
    BOOST_TEST_REQUIRE(spans.size() == 4u);
    BOOST_TEST(*spans[3].value == -0.125);  // the output block above
    BOOST_TEST_REQUIRE(spans[0].value.has_value());
    BOOST_TEST(shows(*shown_number(spans[0].span.text), *spans[0].value));
    BOOST_TEST(*spans[1].value == 12503.0 + 23.51);
    BOOST_TEST(!spans[2].value.has_value());
    BOOST_TEST(spans[2].error.find("make verify") != std::string::npos);
}

BOOST_AUTO_TEST_CASE(a_span_shows_its_value_to_its_own_precision) {
    const auto shown = shown_number("0.936");
    BOOST_TEST_REQUIRE(shown.has_value());
    BOOST_TEST(shows(*shown, 0.93587));
    BOOST_TEST(!shows(*shown, 0.93651));
    BOOST_TEST(!shows({shown->value + shown->unit, shown->unit}, 0.93587));  // the self-check's mutant
    BOOST_TEST(shows(*shown_number("13,092"), 13092.0));
    BOOST_TEST(shows(*shown_number("1.5e-4"), 1.46e-4));
    BOOST_TEST(!shown_number("0.9°").has_value());
    BOOST_TEST(!shown_number("about 3").has_value());
    BOOST_TEST(rendered_like(0.94971, "0.950") == "0.950");
    BOOST_TEST(rendered_like(23.254, "23.40") == "23.25");
    BOOST_TEST(rendered_like(12503.0, "13,092") == "12,503");
    BOOST_TEST(rendered_like(1.46e-4, "1.5e-4") == "1.5e-4");
    BOOST_TEST(rendered_like(-0.0001, "0.00") == "0.00");
}

// A number in words stands for the values that round to it, and is rewritten in the same words.
BOOST_AUTO_TEST_CASE(a_span_in_words_shows_what_rounds_to_it) {
    const auto twice = shown_number("twice");
    BOOST_TEST_REQUIRE(twice.has_value());
    BOOST_TEST(shows(*twice, 2.4));
    BOOST_TEST(!shows(*twice, 2.6));                                     // "three times"
    BOOST_TEST(!shows({twice->value + twice->unit, twice->unit}, 2.1));  // the self-check's mutant
    BOOST_TEST(shows(*shown_number("a third"), 230.0 / 676.0));
    BOOST_TEST(!shows(*shown_number("a quarter"), 230.0 / 676.0));
    BOOST_TEST(shows(*shown_number("twenty times"), 22.6));
    BOOST_TEST(shows(*shown_number("two hundredths"), 0.018));
    BOOST_TEST(!shown_number("thrice as often").has_value());
    BOOST_TEST(rendered_like(2.7, "twice") == "three times");
    BOOST_TEST(rendered_like(22.6, "eight times") == "twenty times");
    BOOST_TEST(rendered_like(0.26, "a third") == "a quarter");
    BOOST_TEST(rendered_like(0.011, "two hundredths") == "one hundredth");
}

BOOST_AUTO_TEST_CASE(refresh_rewrites_spans_at_their_precision) {
    const std::string page =
        "index <!-- value: docs/t.md \"i\" -->0.92<!-- /value -->, steps <!-- value: docs/t.md \"s\" -->12,000<!-- /value -->\n";
    std::string error;
    std::vector<ResolvedSpan> spans;
    for (const ValueSpan& s : value_spans(page, error)) spans.push_back({s, std::nullopt, ""});
    spans[0].value = 0.93587, spans[1].value = 12503.0;
    int changed = 0;
    BOOST_TEST(
        with_values(page, spans, changed) ==
        "index <!-- value: docs/t.md \"i\" -->0.94<!-- /value -->, steps <!-- value: docs/t.md \"s\" -->12,503<!-- /value -->\n");
    BOOST_TEST(changed == 2);
}

BOOST_AUTO_TEST_CASE(numbers_in_prose_are_results_unless_declared_inputs) {
    std::string error;
    const auto inputs = declared_inputs(
        "text\n```inputs\nSect\\. \\d+(\\.\\d+)?  # section numbers\n"
        "@docs/a.md 0\\.1 rev/s  # the drum's speed\n```\n",
        error);
    BOOST_TEST(error.empty());
    BOOST_TEST_REQUIRE(inputs.size() == 2u);
    BOOST_TEST(inputs[1].page == "docs/a.md");
    std::vector<long> uses;
    const std::string page =
        "In Sect. 4.2 the drum turns at 0.1 rev/s; the index is 0.936 after 132 s, 93 % of 12,503 steps.\n"
        "`dt = 0.5` <!-- value: docs/t.md \"i\" -->0.936<!-- /value --> [x](sect4.2.md) 25 cells, Fig. 7\n"
        "```\n0.25\n```\n\n    indented 0.5\n<!-- generated: t.md -->\n| 0.7 |\n<!-- end generated -->\n";
    const auto in_a = hand_typed_numbers(page, "docs/a.md", inputs, uses);
    BOOST_TEST(in_a.size() == 4u);  // 0.936, 132 s, 93 %, 12,503 steps
    BOOST_TEST(uses[0] == 1);
    BOOST_TEST(uses[1] == 1);
    BOOST_TEST(hand_typed_numbers(page, "docs/b.md", inputs, uses).size() == 5u);  // 0.1 is declared for a.md only
    BOOST_TEST(!declared_inputs("```inputs\n0\\.1 rev/s\n```\n", error).size());   // no reason given
    BOOST_TEST(!error.empty());
    error.clear();
    BOOST_TEST(!declared_inputs("```inputs\n(unclosed  # why\n```\n", error).size());
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
    const std::string page =
        "[b](b.md) [part](b.md#2-the-part) [web](https://example.org)\n"
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

BOOST_AUTO_TEST_CASE(an_excerpt_is_its_code_with_every_omission_marked) {
    const std::string source =
        "double flux(double x);  // a declaration: skipped\n"
        "/// flux(x): the comment is not the definition\n"
        "double flux(double x) {\n"
        "    const char* s = \"}\";  // a brace in a string\n"
        "    if (x > 0) {\n"
        "        return x;\n"
        "    }\n"
        "    return -x;\n"
        "}\n"
        "double other() { return flux(1.0); }\n";
    const auto def = definition_of(source, "flux");
    BOOST_TEST_REQUIRE(def.size() == 7u);
    BOOST_TEST(def.front() == "double flux(double x) {");
    BOOST_TEST(def.back() == "}");
    BOOST_TEST(!excerpt_problem(def, def).has_value());
    const std::vector<std::string> marked = {"double flux(double x) {", "    ...", "    return -x;", "}"};
    BOOST_TEST(!excerpt_problem(marked, def).has_value());
    // The break-to-fail cases: a line dropped with no `...`, a changed line, a `...` for nothing,
    // a tail left out with no `...`, lines out of order.
    BOOST_TEST(excerpt_problem({"double flux(double x) {", "    return -x;", "}"}, def).has_value());
    BOOST_TEST(excerpt_problem({"double flux(double x) {", "    ...", "    return +x;", "}"}, def).has_value());
    std::vector<std::string> nothing_left_out = def;
    nothing_left_out.insert(nothing_left_out.begin() + 1, "    ...");
    BOOST_TEST(excerpt_problem(nothing_left_out, def).has_value());
    BOOST_TEST(
        excerpt_problem({"double flux(double x) {", "    const char* s = \"}\";  // a brace in a string"}, def).has_value());
    BOOST_TEST(!excerpt_problem({"double flux(double x) {", "    const char* s = \"}\";  // a brace in a string", "..."}, def)
                    .has_value());
    BOOST_TEST(excerpt_problem({"...", "    return -x;", "    if (x > 0) {", "..."}, def).has_value());
    BOOST_TEST(excerpt_mutants_accepted(marked, def) == 0);
    BOOST_TEST(definition_of(source, "nothing").empty());
    BOOST_TEST(is_ellipsis("    ...  // the other sign"));
    BOOST_TEST(!is_ellipsis("    x...;"));
}

BOOST_AUTO_TEST_CASE(excerpt_markers_name_a_file_and_a_symbol) {
    std::string error;
    const auto found = excerpts_of("text\n<!-- excerpt: src/a.cpp f -->\n```cpp\nint f() {\n```\nmore\n", error);
    BOOST_TEST(error.empty());
    BOOST_TEST_REQUIRE(found.size() == 1u);
    BOOST_TEST(found[0].file == "src/a.cpp");
    BOOST_TEST(found[0].symbol == "f");
    BOOST_TEST(found[0].lines.size() == 1u);
    excerpts_of("<!-- excerpt: src/a.cpp -->\n```cpp\n```\n", error);
    BOOST_TEST(!error.empty());
}

BOOST_AUTO_TEST_SUITE_END()
