// Quotes of generated tables and the physics that made them (verify_docs; docs/checked_pages.md,
// "Where a table came from"). Every table under docs/generated ends with a provenance record
// (table_provenance.hpp); a page quotes a table by a generated block or by a value span whose
// source reads docs/generated/NAME.md. A quote of a table made by other physics than the build's
// (a fingerprint differs, or was never recorded) fails, naming the page, the line, the table and
// what changed, unless the page marks it as made by an earlier scheme:
//
//   <!-- earlier scheme: fig7_summary.md, fig7_convergence.md -->*Made by an earlier scheme ...*
//
// a line that starts with the marker and goes on with the note a reader sees. It covers the rest
// of its section (up to the next heading of the same or a higher level; before any heading, the
// whole page). A mark must name only tables that are stale and that its section quotes: a table
// made again by the build's physics drops out of the mark, and verify_docs says so.
#pragma once

#include "harness/check_table.hpp"
#include "harness/physics_fingerprint.hpp"

#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace granseg::verify::docs {

/// A quote of a generated table on a page.
struct TableQuote {
    std::string table;  // NAME.md
    int line = 0;
};

/// The quotes of a page: its generated blocks (at their opening marker) and its value spans'
/// sources under docs/generated/.
std::vector<TableQuote> table_quotes(const std::string& page);

/// An earlier-scheme mark and the lines it covers.
struct SchemeMark {
    std::vector<std::string> tables;
    int line = 0, last_line = 0;
    std::string note;  // the visible text after the marker
};

/// The marks of a page; `error` names a malformed one (no tables, no closing "-->").
std::vector<SchemeMark> scheme_marks(const std::string& page, std::string& error);

/// What is wrong with one page's quotes, given which tables are stale (table -> what changed;
/// absent or empty: made by the build's physics).
struct QuoteFindings {
    std::vector<std::string> unmarked_stale;  // a stale table quoted outside a mark naming it
    std::vector<std::string> marked_fresh;    // a mark naming a table of the build's physics
    std::vector<std::string> malformed;       // a mark without a note, or naming no quoted table
};
QuoteFindings quote_findings(const std::string& page_text, const std::map<std::string, std::vector<std::string>>& stale,
                             const std::map<std::string, std::string>& made_by);

/// Checks every table's record and every page's quotes against the build's fingerprints `now`,
/// with the self-checks: a record reads back as written, and a quote of a table whose flow
/// fingerprint changes fails unless marked.
void check_provenance(CheckTable& t, const std::filesystem::path& root, const std::vector<std::string>& pages,
                      const Fingerprints& now);

/// verify_docs --physics: prints this build's fingerprints, a part a line; verify_docs
/// --provenance PROGRAM COMMAND PART...: prints the record of a table that PROGRAM made by COMMAND
/// with this build (make fig7's tables). Exit status 2 for a missing argument or an unknown part.
int physics_mode(const std::filesystem::path& root, const std::vector<std::string>& args);

/// For `make docs-refresh`: "made by this build's physics", or what differs from it.
std::string physics_verdict(const std::string& table_text, const Fingerprints& now);

}  // namespace granseg::verify::docs
