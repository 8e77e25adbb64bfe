// The checked blocks of a documentation page (verify_docs; conventions in docs/checked_pages.md):
//   - a fenced block ```sh is a command block, run as one `sh -e` script; it must exit with 0, or N
//     if its fence says ```sh exit=N;
//   - a fenced block ```output right after a command block lists lines the commands must print, in
//     order (other printed lines may come between them; a line `...` marks where, and
//     Comparison::unmarked_gaps counts the places left out without one). Two lines agree when
//     their words are equal (runs of blanks count as one blank) and their numbers agree to the
//     precision the page prints: |printed - page| <= half a unit of the page's last digit (0.9382
//     stands for [0.93815, 0.93825]; an integer for itself);
//   - a generated block is the text between `<!-- generated: NAME.md -->` and
//     `<!-- end generated -->`: a copy of docs/generated/NAME.md, which a program writes.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace granseg::verify::docs {

/// A fenced block of a page.
struct Block {
    std::string language, info;  // "sh", "exit=2"
    std::vector<std::string> lines;
    int first_line = 0;  // line number of the opening fence
};

/// The fenced blocks of a page's text, in order.
std::vector<Block> fenced_blocks(const std::string& text);

/// The exit status a command block's fence asks for (0 unless it says exit=N).
int expected_status(const Block& b);

/// A line split into words and numbers, in order.
struct Tokens {
    std::vector<std::string> words;  // text between the numbers, blanks collapsed
    std::vector<double> numbers;
    std::vector<double> units;  // one unit of the last printed digit of each number
};

Tokens tokens_of(const std::string& line);

/// True if a printed number agrees with the page's number `shown`, written with `unit` the unit of
/// its last digit: |printed - shown| <= unit/2 (plus the decimal conversions' round-off).
bool within_last_digit(double printed, double shown, double unit);

/// The text without its leading and trailing blanks and tabs.
std::string trimmed(const std::string& s);

/// True for a line that stands for lines left out: `...` after blanks, then nothing or a `//`
/// comment (code excerpts and output blocks).
bool is_ellipsis(const std::string& line);

/// The lines of a text.
std::vector<std::string> lines_of(const std::string& text);

/// True if the printed line agrees with the page's line (see the header).
bool agrees(const Tokens& printed, const Tokens& page);

/// The page's line with its last number moved by one unit of its last digit.
Tokens mutated(Tokens t);

/// One output block against what its command block printed: expected lines not found in order,
/// and, of the expected lines with numbers, how many still agree with their printed line after
/// `mutated` (a matcher that lets a changed number pass would show up here).
struct Comparison {
    long missing = 0, mutants_agreeing = 0, numeric_lines = 0, numbers = 0;
    std::string first_missing, nearest;  // the first expected line not found, the printed line most like it
    std::string first_mutant_agreeing;   // the first expected line whose mutant still agrees
    long unmarked_gaps = 0;              // printed lines left out (between, before or after) without a `...`
    std::string first_unmarked;          // the expected line after the first such gap
};
Comparison compare(const std::vector<std::string>& expected, const std::vector<std::string>& printed);

/// What a command block printed (stdout and stderr together) and its exit status.
struct Run {
    int status = -1;
    std::vector<std::string> lines;
};

/// Runs the block as `sh -e` in `scratch` on one OpenMP thread, at most `timeout_seconds` long.
Run run_block(const Block& b, const std::filesystem::path& scratch, int timeout_seconds);

/// A generated block of a page: the table file it copies and its text (without the markers).
struct Generated {
    std::string name;  // NAME.md
    std::string text;  // the lines between the markers, each ending in '\n'
    int first_line = 0;
};

/// The generated blocks of a page; `error` gets a message for an unclosed or nested marker.
std::vector<Generated> generated_blocks(const std::string& page, std::string& error);

/// The page with the text of every generated block NAME replaced by `text`.
std::string with_generated(const std::string& page, const std::string& name, const std::string& text);

/// The text of a file ("" if it cannot be read); `found` tells which.
std::string read_text(const std::filesystem::path& p, bool* found = nullptr);

}  // namespace granseg::verify::docs
