// Numbers in prose (verify_docs; docs/checked_pages.md, "Numbers in prose"): a number a program
// produced is stated in a page only inside a generated block, a command's output block or a
// value span (doc_values.hpp). What is left of a page once those, code (fenced, indented, in
// backticks), HTML comments and link targets are blanked out is its prose, and in it
//   - every decimal number (0.936, 1.7, 1e-12), and
//   - every integer counting what a run produces or costs: before %, s, seconds, minutes, hours,
//     CPU-s, CPU-hours, steps, sub-steps, iterations, cycles, V-cycles, and
//   - every ratio, share or count in words or as a count of a total: twice, N times, a third,
//     two thirds, a quarter, three quarters, a fifth, two to four fifths, a tenth, N hundredths,
//     "230 of 676"
//     (a span may show it in words, doc_words.hpp)
// is a result typed by hand, unless a declared input covers it. The inputs are declared once, in
// the ```inputs block of docs/checked_pages.md: one line per input, a regular expression
// (ECMAScript) and, after "  # ", why its numbers are inputs (scene keys, the paper's parameters,
// section and equation numbers, ...); a line starting "@PAGE " applies to that page only. The
// numbers inside a match of a declaration are inputs.
#pragma once

#include "harness/doc_hygiene.hpp"
#include "harness/text_pattern.hpp"

#include <string>
#include <vector>

namespace granseg::verify::docs {

/// One declared input.
struct DeclaredInput {
    std::string expression, why, page;  // page: "" for every page
    Pattern pattern;
    int line = 0;  // in the declaring page
};

/// The declarations of the first ```inputs block of `declaring_page`; `error` names a line that
/// is not "[@PAGE ]REGEX  # why" or whose expression does not compile.
std::vector<DeclaredInput> declared_inputs(const std::string& declaring_page, std::string& error);

/// Per line of a page: whether it is indented code (four blanks or a tab after a blank line or
/// after indented code, outside fenced blocks).
std::vector<bool> indented_code_lines(const std::string& page);

/// The page's prose: the text with fenced and indented code, generated blocks, value spans, HTML
/// comments, code spans in backticks and link targets replaced by blanks (lines and columns kept).
std::string prose_of(const std::string& page);

/// The results typed by hand in a page's prose (page: its path from the top, for @PAGE
/// declarations); `uses[i]` is increased by the matches of inputs[i] in the page.
std::vector<Finding> hand_typed_numbers(const std::string& page_text, const std::string& page,
                                        const std::vector<DeclaredInput>& inputs, std::vector<long>& uses);

}  // namespace granseg::verify::docs
