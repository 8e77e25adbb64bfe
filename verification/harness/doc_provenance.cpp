#include "harness/doc_provenance.hpp"

#include "harness/doc_blocks.hpp"
#include "harness/doc_prose.hpp"
#include "harness/doc_values.hpp"
#include "harness/table_provenance.hpp"
#include "harness/text_pattern.hpp"

#include <algorithm>
#include <iostream>
#include <sstream>

namespace fs = std::filesystem;

namespace granseg::verify::docs {

namespace {

const std::string kMarkOpen = "<!-- earlier scheme: ";

/// The heading level of a line (1 for "# ...", ...), or 0.
int heading_level(const std::string& line) {
    const auto hashes = line.find_first_not_of('#');
    return hashes > 0 && hashes != std::string::npos && hashes <= 6 && line[hashes] == ' ' ? static_cast<int>(hashes) : 0;
}

std::string joined(const std::vector<std::string>& items, const std::string& separator) {
    std::string out;
    for (const std::string& s : items) out += (out.empty() ? "" : separator) + s;
    return out;
}

bool names(const SchemeMark& m, const std::string& table) {
    return std::find(m.tables.begin(), m.tables.end(), table) != m.tables.end();
}

}  // namespace

std::vector<TableQuote> table_quotes(const std::string& page) {
    static const Pattern generated_file(R"(docs/generated/([A-Za-z0-9_.-]+\.md))");
    std::vector<TableQuote> quotes;
    std::string error;
    for (const Generated& g : generated_blocks(page, error)) quotes.push_back({g.name, g.first_line});
    // A span in indented code is an example of the syntax (docs/checked_pages.md), not a quote.
    const std::vector<bool> example = indented_code_lines(page);
    for (const ValueSpan& s : value_spans(page, error)) {
        if (static_cast<std::size_t>(s.line) <= example.size() && example[static_cast<std::size_t>(s.line - 1)]) continue;
        for (const PatternMatch& m : generated_file.all_in(s.source)) quotes.push_back({m[1], s.line});
    }
    std::sort(quotes.begin(), quotes.end(), [](const TableQuote& a, const TableQuote& b) { return a.line < b.line; });
    return quotes;
}

std::vector<SchemeMark> scheme_marks(const std::string& page, std::string& error) {
    const std::vector<std::string> lines = lines_of(page);
    std::vector<SchemeMark> marks;
    std::vector<int> levels;  // per mark: the level of the section it stands in (0: before any heading)
    int level = 0;
    bool fenced = false;
    for (std::size_t i = 0; i < lines.size(); ++i) {
        const std::string& line = lines[i];
        const int number = static_cast<int>(i + 1);
        if (line.rfind("```", 0) == 0) fenced = !fenced;
        if (fenced) continue;
        if (const int h = heading_level(line)) {
            for (std::size_t k = 0; k < marks.size(); ++k)
                if (marks[k].last_line == 0 && h <= levels[k]) marks[k].last_line = number - 1;
            level = h;
            continue;
        }
        if (line.rfind(kMarkOpen, 0) != 0) continue;
        const auto found = line.find(" -->", kMarkOpen.size() - 1);
        const auto end = found == std::string::npos || found < kMarkOpen.size() ? std::string::npos : found;
        SchemeMark m;
        m.line = number;
        std::istringstream names(end == std::string::npos ? "" : line.substr(kMarkOpen.size(), end - kMarkOpen.size()));
        for (std::string w; std::getline(names, w, ',');) {
            w.erase(0, w.find_first_not_of(' '));
            w.erase(w.find_last_not_of(' ') + 1);
            if (!w.empty()) m.tables.push_back(w);
        }
        if (end == std::string::npos || m.tables.empty()) {
            if (error.empty()) error = "line " + std::to_string(number) + ": malformed mark (" + kMarkOpen + "NAME.md, ... -->)";
            continue;
        }
        m.note = line.substr(end + 4);
        marks.push_back(m);
        levels.push_back(level);
    }
    for (SchemeMark& m : marks)
        if (m.last_line == 0) m.last_line = static_cast<int>(lines.size());
    return marks;
}

QuoteFindings quote_findings(const std::string& page_text, const std::map<std::string, std::vector<std::string>>& stale,
                             const std::map<std::string, std::string>& made_by) {
    QuoteFindings f;
    std::string error;
    const std::vector<SchemeMark> marks = scheme_marks(page_text, error);
    if (!error.empty()) f.malformed.push_back(error);
    const std::vector<TableQuote> quotes = table_quotes(page_text);
    const auto is_stale = [&](const std::string& table) {
        const auto it = stale.find(table);
        return it != stale.end() && !it->second.empty();
    };
    std::vector<std::string> reported;  // one line per table and mark, not per quote
    for (const TableQuote& q : quotes) {
        const auto covering = std::find_if(marks.begin(), marks.end(), [&](const SchemeMark& m) {
            return m.line <= q.line && q.line <= m.last_line && names(m, q.table);
        });
        if (!is_stale(q.table) || covering != marks.end()) continue;
        if (std::find(reported.begin(), reported.end(), q.table) != reported.end()) continue;
        reported.push_back(q.table);
        const auto how = made_by.find(q.table);
        f.unmarked_stale.push_back("line " + std::to_string(q.line) + " quotes " + q.table +
                                   ", made by other physics than this build's: " + joined(stale.at(q.table), "; ") +
                                   ". Remake it (" + (how == made_by.end() ? "its program" : how->second) +
                                   ", then make docs-refresh), or mark the quote: " + kMarkOpen + q.table + " --> and a note");
    }
    for (const SchemeMark& m : marks) {
        const std::string where = "line " + std::to_string(m.line) + ": ";
        if (m.note.find_first_not_of(" \t") == std::string::npos)
            f.malformed.push_back(where + "the mark has no note for the reader after it");
        for (const std::string& table : m.tables) {
            if (!is_stale(table)) {
                f.marked_fresh.push_back(where + table +
                                         " is marked as made by an earlier scheme, but this build's physics made it: "
                                         "drop it from the mark");
                continue;
            }
            const bool quoted = std::any_of(quotes.begin(), quotes.end(), [&](const TableQuote& q) {
                return q.table == table && m.line <= q.line && q.line <= m.last_line;
            });
            if (!quoted) f.malformed.push_back(where + "the mark names " + table + ", which its section does not quote");
        }
    }
    return f;
}

std::string physics_verdict(const std::string& table_text, const Fingerprints& now) {
    const auto record = parse_provenance(table_text);
    if (!record) return "no provenance record";
    const auto changes = physics_changes(record->physics, now);
    return changes.empty() ? "made by this build's physics" : "made by other physics than this build's: " + joined(changes, "; ");
}

namespace {

/// The tables' states: table -> what changed (empty: fresh), and how each is made.
struct TableStates {
    std::map<std::string, std::vector<std::string>> stale;
    std::map<std::string, std::string> made_by;
};

TableStates table_states(CheckTable& t, const fs::path& root, const Fingerprints& now) {
    TableStates s;
    long fresh = 0, records = 0;
    std::vector<fs::path> files;
    for (const auto& e : fs::directory_iterator(root / "docs" / "generated")) files.push_back(e.path());
    std::sort(files.begin(), files.end());
    for (const fs::path& file : files) {
        const std::string name = file.filename().string();
        const auto record = parse_provenance(read_text(file));
        if (!record) {
            t.note("  docs/generated/" + name + ": no provenance record (its program writes one; docs/checked_pages.md)");
            s.stale[name] = {"no provenance record"};
            continue;
        }
        ++records;
        s.stale[name] = physics_changes(record->physics, now);
        s.made_by[name] = record->command;
        fresh += s.stale[name].empty();
        t.note("  " + name + ": " + (s.stale[name].empty() ? "made by this build's physics" : "made by other physics") + " (" +
               record->program + ")");
    }
    t.count("docs/generated: tables without a provenance record (of " + std::to_string(files.size()) + ")",
            static_cast<long>(files.size()) - records, 0);
    t.note(std::to_string(fresh) + " of " + std::to_string(files.size()) + " generated tables made by this build's physics");
    return s;
}

void report(CheckTable& t, const std::string& check, const std::vector<std::string>& lines) {
    t.count(check, static_cast<long>(lines.size()), 0);
    for (const std::string& l : lines) t.note("  " + l);
}

/// A record reads back as written; a quote of a table whose flow fingerprint no longer matches
/// fails unless marked, and a mark on a fresh table fails.
void check_provenance_rules(CheckTable& t, const Fingerprints& now) {
    Provenance p{"bench_x", "build/bench/bench_x --data out", "0123456789ab", {}};
    for (const std::string& part : kDrumStudyParts) p.physics[part] = now.count(part) ? now.at(part) : "unknown";
    const auto back = parse_provenance("| a | b |\n|---|---|\n| 1 | 2 |\n" + provenance_record(p));
    const bool same = back && back->program == p.program && back->command == p.command && back->commit == p.commit &&
                      back->physics == p.physics;
    t.count("provenance self-check: a record reads back as written", same ? 1 : 0, 1);
    Fingerprints changed = now;
    changed["flow"] = "0000000000000000";
    const auto changes = physics_changes(p.physics, changed);
    t.count("provenance self-check: a changed flow fingerprint is named (of 1 change)",
            static_cast<long>(std::count_if(changes.begin(), changes.end(),
                                            [](const std::string& c) { return c.find(part_title("flow")) == 0; })),
            1);
    const std::string quoting = "## A\n<!-- value: docs/generated/x.md \"a\" | b -->1<!-- /value -->\n";
    const std::string marked = "## A\n" + kMarkOpen + "x.md -->*Made by an earlier scheme.*\n" + quoting.substr(5);
    const std::map<std::string, std::vector<std::string>> stale = {{"x.md", changes}}, fresh = {{"x.md", {}}};
    t.count("provenance self-check: unmarked quote of a stale table flagged",
            static_cast<long>(quote_findings(quoting, stale, {}).unmarked_stale.size()), 1);
    const QuoteFindings ok = quote_findings(marked, stale, {});
    t.count("provenance self-check: marked quote of a stale table flagged",
            static_cast<long>(ok.unmarked_stale.size() + ok.malformed.size()), 0);
    t.count("provenance self-check: a mark on a fresh table flagged",
            static_cast<long>(quote_findings(marked, fresh, {}).marked_fresh.size()), 1);
}

}  // namespace

void check_provenance(CheckTable& t, const fs::path& root, const std::vector<std::string>& pages, const Fingerprints& now) {
    t.note("this build's physics: " + physics_line(now));
    const TableStates s = table_states(t, root, now);
    for (const std::string& page : pages) {
        if (page == "docs/history.md") continue;  // it tells how results came about: old tables included
        const std::string text = read_text(root / page);
        if (table_quotes(text).empty() && text.find(kMarkOpen) == std::string::npos) continue;
        const QuoteFindings f = quote_findings(text, s.stale, s.made_by);
        report(t, page + ": quotes of tables made by other physics, not marked as an earlier scheme's", f.unmarked_stale);
        report(t, page + ": earlier-scheme marks on tables of this build's physics", f.marked_fresh);
        report(t, page + ": malformed earlier-scheme marks", f.malformed);
    }
    check_provenance_rules(t, now);
}

int physics_mode(const fs::path& root, const std::vector<std::string>& args) {
    const Fingerprints now = physics_fingerprints(root);
    if (args.front() == "--physics") {
        for (const PhysicsPart& p : physics_parts()) std::cout << p.name << " " << now.at(p.name) << "  # " << p.title << "\n";
        return 0;
    }
    if (args.size() < 4) {
        std::cerr << "verify_docs --provenance: PROGRAM COMMAND PART... (allowed parts: flow drum segregation closures study)\n";
        return 2;
    }
    Provenance p{args[1], args[2], commit_of(root), {}};
    for (std::size_t i = 3; i < args.size(); ++i) {
        if (!now.count(args[i])) {
            std::cerr << "verify_docs --provenance: no part " << args[i] << " (allowed: flow drum segregation closures study)\n";
            return 2;
        }
        p.physics[args[i]] = now.at(args[i]);
    }
    std::cout << provenance_record(p);
    return 0;
}

}  // namespace granseg::verify::docs
