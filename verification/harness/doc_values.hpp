// Checked inline values (verify_docs; conventions in docs/checked_pages.md): a number a page states
// in its prose is written inside a span that names where the number comes from,
//
//   <!-- value: SOURCE -->0.936<!-- /value -->
//
// on one line. verify_docs reads the source and fails when the span's number and the source's
// differ by more than half a unit of the span's last digit (0.936 stands for [0.9355, 0.9365]);
// `make docs-refresh` rewrites the span with the source's value at the span's precision.
//
// SOURCE, one of
//   FILE "MATCH" [#N] [SCALE]           a text file (a program's log, a generated table): the
//                                       first line containing MATCH, the N-th number after
//                                       MATCH on it (1 the first, the default; -1 the last);
//                                       "MATCH"~K takes the K-th line containing MATCH
//   FILE "MATCH" | COLUMN [#N] [SCALE]  a markdown table: the row containing MATCH, the cell
//                                       under the header COLUMN (else the first header containing
//                                       it), its N-th number; "MATCH" [COLUMN] says the same inside
//                                       a table row, where a bar would split the cell
//   FILE:COLUMN@ROW [SCALE]             a data file (.dat: a "# name name ..." header line, rows
//                                       of numbers): column COLUMN of data row ROW, which is
//                                       "last", a number from 1, or KEY=VALUE (the first row
//                                       whose column KEY holds VALUE)
// and SOURCE - SOURCE, SOURCE + SOURCE or SOURCE / SOURCE, the difference, sum or ratio of two
// values (a change, a distance to a limit, the end of a band, "twice"), any of them followed by
// ^ K, the value to the power K (^ 0.5: a ratio of temperatures as one of speeds). The span's number may be
// written in words ("twice", "a third"; doc_words.hpp). FILE may
// also be `output`: the page's last output block above the span, which verify_docs checks
// against what its command printed (a page restating a number its own block shows).
// FILE is a path from the top of the repository: docs/generated/NAME.md (committed; verify_docs
// ties it to its program's fresh output), build/results/NAME.log and build/data/... (written by
// make verify). SCALE is *K or /K (a percentage: *100). Numbers are counted as the output-block
// matcher counts them (doc_blocks.hpp tokens_of).
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace granseg::verify::docs {

/// A value span of a page.
struct ValueSpan {
    std::string source;      // as written after "value: "
    std::string text;        // the number the page shows
    int line = 0;            // 1-based line of the page
    std::size_t offset = 0;  // of `text` in the page
};

/// The value spans of a page's text (fenced blocks skipped); `error` names the first malformed
/// one (unclosed on its line, empty, or with an empty source).
std::vector<ValueSpan> value_spans(const std::string& page, std::string& error);

/// A parsed SOURCE (see the header).
struct ValueSource {
    std::string file;    // from the top of the repository
    std::string match;   // text sources: the line selector
    std::string column;  // a markdown table's header, or a data file's column name
    std::string row;     // data files: "last", "N" or "KEY=VALUE"
    int number = 1;      // which number of the line or cell; negative from the end
    int occurrence = 1;  // text sources: which line containing `match` ("MATCH"~2: the second)
    double scale = 1.0;
    bool data = false;  // FILE:COLUMN@ROW
};

/// Parses a span's source; `error` says what is wrong when it returns nothing.
std::optional<ValueSource> parse_source(const std::string& source, std::string& error);

/// The value a source names, read from `file_text` (the text of source.file); `error` says why
/// when it returns nothing (no such line, column, row or number).
std::optional<double> source_value(const ValueSource& source, const std::string& file_text, std::string& error);

/// A span's number: its value and one unit of its last digit. Thousands separators (13,092) are
/// allowed, and a number in words (doc_words.hpp: its unit the width it stands for); anything
/// else is not.
struct ShownNumber {
    double value = 0, unit = 1;
};
std::optional<ShownNumber> shown_number(const std::string& text);

/// True if `value` rounds to what the page shows (within half a unit of its last digit).
bool shows(const ShownNumber& shown, double value);

/// `value` written as the page wrote `like` (the same decimals or exponent digits, separators).
std::string rendered_like(double value, const std::string& like);

/// A span with what its source says: the value, or why there is none.
struct ResolvedSpan {
    ValueSpan span;
    std::optional<double> value;
    std::string error;
};

/// The spans of a page, each resolved against its source file: FILE with a leading "build/"
/// read from `build` (the build tree may lie elsewhere), else from `root`.
std::vector<ResolvedSpan> resolved_spans(const std::string& page, const std::filesystem::path& root,
                                         const std::filesystem::path& build, std::string& error);

/// The page with every resolved span's number rewritten from its value at the span's precision
/// (`rendered_like`); `changed` counts the spans whose text changed.
std::string with_values(const std::string& page, const std::vector<ResolvedSpan>& spans, int& changed);

}  // namespace granseg::verify::docs
