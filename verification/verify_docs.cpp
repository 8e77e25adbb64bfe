// The pages cannot drift from the code: checks every teaching page (README.md and docs/*.md)
// against the programs, by the conventions of docs/checked_pages.md.
//
// What is checked, and why it can fail:
//   - every ```sh block of every page runs (in a scratch directory that looks like the top of
//     the repository: build/, verification/, figures/, docs/, src/ link to the real ones, out/ is
//     the scratch's own) and exits with the status its fence names; every ```output block right
//     after it is printed, line by line in order, numbers to the precision the page shows
//     (harness/doc_blocks.hpp);
//   - every code excerpt (<!-- excerpt: FILE SYMBOL --> above a fenced block) is the symbol's
//     definition with each run of lines it leaves out marked by a `...` line
//     (harness/doc_excerpts.hpp); the tutorial's output blocks mark what they leave out too;
//   - every value span (<!-- value: SOURCE -->0.936<!-- /value -->) shows its source's number to
//     the precision the page writes, and no page but docs/history.md states a number in its prose
//     outside a span, a block or a declared input (the ```inputs block of docs/checked_pages.md;
//     harness/doc_values.hpp, harness/doc_prose.hpp); every declared input is used;
//   - every generated block equals its committed copy docs/generated/NAME.md, and that copy
//     equals the program's fresh output build/data/NAME.md or build/bench-data/NAME.md when one
//     exists; every committed copy is shown by some page;
//   - no teaching page (every page but docs/history.md) holds a date, a commit hash or a machine
//     name, or refers to a file outside the repository; no source file refers outside either;
//     every relative link and image leads to a file of the repository (not into build/); every
//     name a page shows in backticks (file, function, type, key, option, make target) exists
//     somewhere in the tree (harness/doc_names.hpp);
//   - every reference figure docs/figures/NAME.png is recorded in docs/figures/fingerprints.txt,
//     and its fingerprint equals that of the data it would be drawn from now
//     (harness/doc_figures.hpp), so a stale image fails until `make docs-figures` redraws it;
//   - the checker itself (mutation self-checks): every expected line with a number, its last
//     number moved by one unit of its last digit, must no longer agree with the line it matched;
//     every generated block with one digit changed must differ from its copy; every recorded
//     figure with one data digit changed must get another fingerprint; every value span with its
//     last digit moved must disagree with its source; the number check must flag hand-typed
//     samples and pass declared, spanned and code ones; and the history,
//     outside-reference and name detectors must flag samples of what they look for (invented
//     names among them) and pass samples of what exists.
//   - every generated table records what made it (harness/table_provenance.hpp), and a page
//     quotes a table made by other physics than the build's only under an earlier-scheme mark
//     (harness/doc_provenance.hpp).
// Run: build/verification/verify_docs [--data DIR]   (make verify runs it after every other
// verification program, whose results and data files some blocks and the figure check read;
// its slowest part is the tutorial's blocks). Its other modes: verify_docs --help.
#include "harness/check_table.hpp"
#include "harness/doc_blocks.hpp"
#include "harness/doc_excerpts.hpp"
#include "harness/doc_figures.hpp"
#include "harness/doc_hygiene.hpp"
#include "harness/doc_names.hpp"
#include "harness/doc_prose.hpp"
#include "harness/doc_provenance.hpp"
#include "harness/doc_refresh.hpp"
#include "harness/doc_values.hpp"
#include "harness/program.hpp"
#include "harness/table_provenance.hpp"

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <iostream>
#include <string>
#include <vector>

#include "run/output.hpp"

namespace fs = std::filesystem;
using namespace granseg::verify;
using namespace granseg::verify::docs;

namespace {

// Seconds one command block may take before it counts as failed.
constexpr int kBlockTimeout = 300;
// A command block slower than this is named in the table (make verify's time budget).
constexpr double kSlowBlock = 2.0;
// Pages whose output blocks show what their commands print whole, or mark each place where they
// leave lines out with a `...` line (the tutorial: a student compares line by line).
const std::vector<std::string> kPagesMarkingOmissions = {"docs/tutorial.md"};

struct Repository {
    fs::path root, build;
    std::vector<std::string> pages;  // relative to root: README.md, docs/*.md
};

std::string finding_line(const Finding& f) { return "  line " + std::to_string(f.line) + ": " + f.what + ": " + f.text; }

/// History, outside references, links and names of one page (history.md may name what was).
void check_hygiene(CheckTable& t, const Repository& repo, const TreeNames& tree, const std::string& page,
                   const std::string& text) {
    const auto history = history_findings(text), outside = outside_references(text);
    if (page != "docs/history.md") {
        t.count(page + ": lines with a date, commit hash or machine", static_cast<long>(history.size()), 0);
        for (const auto& f : history) t.note(finding_line(f));
        const auto names = unknown_names(text, page, tree);
        t.count(page + ": names in backticks that exist nowhere in the tree", static_cast<long>(names.size()), 0);
        for (const auto& f : names) t.note(finding_line(f));
    }
    t.count(page + ": references outside the repository", static_cast<long>(outside.size()), 0);
    for (const auto& f : outside) t.note(finding_line(f));
    const auto links = broken_links(text, (repo.root / page).parent_path(), repo.root);
    t.count(page + ": links not leading to a file of the repository", static_cast<long>(links.size()), 0);
    for (const auto& f : links) t.note(finding_line(f));
}

struct BlockCounts {
    long commands = 0, outputs = 0, numeric_lines = 0, numbers = 0, mutants_agreeing = 0, orphans = 0;
};

/// Runs the command blocks of one page and matches its output blocks.
void check_blocks(CheckTable& t, const std::string& page, const std::string& text, const fs::path& scratch, BlockCounts& n) {
    Run last;
    bool after_command = false;
    for (const Block& b : fenced_blocks(text)) {
        const std::string where = page + ":" + std::to_string(b.first_line);
        if (b.language == "sh") {
            ++n.commands;
            const auto start = std::chrono::steady_clock::now();
            last = run_block(b, scratch, kBlockTimeout);
            const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
            if (seconds > kSlowBlock) t.note(where + ": command block took " + granseg::verify::format(seconds) + " s");
            t.count(where + ": command block exit status", last.status, expected_status(b));
            if (last.status != expected_status(b))
                for (std::size_t i = last.lines.size() > 3 ? last.lines.size() - 3 : 0; i < last.lines.size(); ++i)
                    t.note("  printed: " + last.lines[i]);
            after_command = true;
            continue;
        }
        if (b.language == "output") {
            if (!after_command) {
                ++n.orphans;
                continue;
            }
            ++n.outputs;
            const Comparison c = compare(b.lines, last.lines);
            t.count(where + ": expected lines not printed (of " + std::to_string(b.lines.size()) + ")", c.missing, 0);
            if (c.missing > 0) {
                t.note("  expected: " + c.first_missing);
                t.note("  nearest printed line: " + c.nearest);
            }
            if (std::count(kPagesMarkingOmissions.begin(), kPagesMarkingOmissions.end(), page) > 0) {
                t.count(where + ": places where printed lines are left out without a ... line", c.unmarked_gaps, 0);
                if (c.unmarked_gaps > 0) t.note("  first before: " + c.first_unmarked);
            }
            n.numeric_lines += c.numeric_lines;
            n.numbers += c.numbers;
            n.mutants_agreeing += c.mutants_agreeing;
            if (c.mutants_agreeing > 0)
                t.note("  " + where + ": with one digit changed, this line still agrees: " + c.first_mutant_agreeing);
        }
        after_command = false;  // an output block belongs to the command block right before it
    }
}

/// The code excerpts of one page against the code they name (harness/doc_excerpts.hpp).
void check_excerpts(CheckTable& t, const Repository& repo, const std::string& page, const std::string& text, long& shown,
                    long& mutants_accepted) {
    std::string error;
    const auto found = excerpts_of(text, error);
    t.count(page + ": malformed excerpt markers", error.empty() ? 0 : 1, 0);
    if (!error.empty()) t.note("  " + error);
    long wrong = 0;
    for (const Excerpt& e : found) {
        const ExcerptCheck c = check_excerpt(e, repo.root);
        ++shown;
        if (c.problem) {
            ++wrong;
            t.note("  line " + std::to_string(e.marker_line) + ": " + e.file + " " + e.symbol + ": " + *c.problem +
                   " (make docs-refresh shows the whole definition, to trim again)");
        } else {
            mutants_accepted += excerpt_mutants_accepted(e.lines, c.definition);
        }
    }
    t.count(page + ": code excerpts that differ from their code (of " + std::to_string(found.size()) + ")", wrong, 0);
}

struct NumberCounts {
    long spans = 0, mutants_agreeing = 0;
    std::vector<long> uses;  // per declared input, its matches on all pages
};

/// The value spans of one page against their sources, and its prose for numbers typed by hand.
void check_numbers(CheckTable& t, const Repository& repo, const std::string& page, const std::string& text,
                   const std::vector<DeclaredInput>& inputs, NumberCounts& n) {
    std::string error;
    const auto spans = resolved_spans(text, repo.root, repo.build, error);
    t.count(page + ": malformed value spans", error.empty() ? 0 : 1, 0);
    if (!error.empty()) t.note("  " + error);
    long wrong = 0;
    for (const ResolvedSpan& r : spans) {
        const auto shown = shown_number(r.span.text);
        const std::string where = "  line " + std::to_string(r.span.line) + ": ";
        if (!shown || !r.value) {
            ++wrong;
            t.note(where + (shown ? r.error : "the span shows no number: \"" + r.span.text + "\"") + " [" + r.span.source + "]");
            continue;
        }
        ++n.spans;
        if (!shows(*shown, *r.value)) {
            ++wrong;
            t.note(where + "the page shows " + r.span.text + ", its source " + rendered_like(*r.value, r.span.text) + " (" +
                   granseg::verify::format(*r.value) + ") [" + r.span.source + "]; make docs-refresh rewrites it");
        } else {
            n.mutants_agreeing += shows({shown->value + shown->unit, shown->unit}, *r.value);
        }
    }
    t.count(page + ": value spans that disagree with their source (of " + std::to_string(spans.size()) + ")", wrong, 0);
    std::vector<long> uses;
    const auto typed = hand_typed_numbers(text, page, inputs, uses);
    for (std::size_t i = 0; i < uses.size(); ++i) n.uses[i] += uses[i];
    t.count(page + ": numbers typed by hand in prose (no span, block or declared input)", static_cast<long>(typed.size()), 0);
    for (const auto& f : typed) t.note(finding_line(f));
}

/// The declared inputs (the ```inputs block of docs/checked_pages.md).
std::vector<DeclaredInput> read_inputs(CheckTable& t, const Repository& repo) {
    std::string error;
    auto inputs = declared_inputs(read_text(repo.root / "docs" / "checked_pages.md"), error);
    t.count("docs/checked_pages.md: inputs block readable", error.empty() ? 1 : 0, 1);
    if (!error.empty()) t.note("  " + error);
    return inputs;
}

/// Every declaration is used, and the number check flags a result typed by hand and passes what
/// a page may hold.
void check_number_rules(CheckTable& t, const std::vector<DeclaredInput>& inputs, const NumberCounts& n) {
    long unused = 0;
    for (std::size_t i = 0; i < inputs.size(); ++i)
        if (n.uses[i] == 0)
            ++unused, t.note("  docs/checked_pages.md line " + std::to_string(inputs[i].line) + ": no page uses " +
                             inputs[i].expression);
    t.count("declared inputs that no page uses (of " + std::to_string(inputs.size()) + ")", unused, 0);
    const std::string typed =
        "the angle is 23.40 deg\nthe run took 132 s, 93 % of it in 12,503 steps\nthe core moves twice as far in 230 of 676 "
        "cells\n";
    const std::string allowed =
        "Sect. 4.2 and `dt = 0.5` and <!-- value: docs/x.md \"y\" -->0.936<!-- /value -->\n```\n0.25\n```\n";
    std::vector<long> ignored;
    t.count("number self-check: hand-typed sample numbers flagged (of 6)",
            static_cast<long>(hand_typed_numbers(typed, "docs/x.md", inputs, ignored).size()), 6);
    t.count("number self-check: declared, spanned and code numbers flagged",
            static_cast<long>(hand_typed_numbers(allowed, "docs/x.md", inputs, ignored).size()), 0);
}

/// The text with its first digit changed (the generated-block self-check).
std::string one_digit_changed(std::string s) {
    const auto at = s.find_first_of("0123456789");
    if (at != std::string::npos) s[at] = s[at] == '9' ? '0' : static_cast<char>(s[at] + 1);
    return s;
}

/// Generated blocks of one page; records which committed copies are shown.
void check_generated(CheckTable& t, const Repository& repo, const std::string& page, const std::string& text,
                     std::vector<std::string>& shown, long& mutants_equal) {
    std::string error;
    const auto blocks = generated_blocks(text, error);
    if (!error.empty()) t.note(page + ": " + error);
    t.count(page + ": malformed generated markers", error.empty() ? 0 : 1, 0);
    for (const Generated& g : blocks) {
        const std::string where = page + ":" + std::to_string(g.first_line) + " " + g.name;
        bool found = false;
        const std::string copy = shown_part(read_text(repo.root / "docs" / "generated" / g.name, &found));
        t.count(where + ": block equals docs/generated/" + g.name, found && copy == g.text ? 0 : 1, 0);
        if (g.text.find_first_of("0123456789") != std::string::npos) mutants_equal += one_digit_changed(g.text) == copy;
        shown.push_back(g.name);
        const fs::path fresh = fresh_table(repo.build, g.name);
        if (fresh.empty() || !compared(g.name)) {
            t.note("  " + g.name +
                   (fresh.empty() ? ": no fresh output in build/ (its program has not run); committed copy used"
                                  : ": a run's cost, the machine's: not compared (make docs-refresh copies it)"));
            continue;
        }
        t.count(where + ": committed copy equals fresh " + fresh.lexically_relative(repo.build).string() +
                    " (else make docs-refresh)",
                shown_part(read_text(fresh)) == copy ? 0 : 1, 0);
    }
}

/// Outside references in the sources (comments included).
void check_sources(CheckTable& t, const Repository& repo) {
    long files = 0, references = 0;
    for (const char* dir : {"src", "verification", "tests", "figures"})
        for (const auto& e : fs::recursive_directory_iterator(repo.root / dir)) {
            if (!e.is_regular_file()) continue;
            const std::string rel = e.path().lexically_relative(repo.root).generic_string();
            const auto found = outside_references(read_text(e.path()));
            ++files;
            references += static_cast<long>(found.size());
            for (const auto& f : found) t.note(rel + finding_line(f));
        }
    t.count("source files (" + std::to_string(files) + ") referring outside the repository: references", references, 0);
}

/// The detectors flag what they look for and pass what they must not flag.
void check_detectors(CheckTable& t, const TreeNames& tree) {
    const std::string history =
        "measured on 2 December 2026\nin May 2025\nmain af0974d\na freshly booted Intel Xeon\n"
        "on 2026-12-03\nload average 0.4\n";
    const std::string clean = "Gray & Thornton (2005)\nN = 1600, 12800 cells\n#1f77b4 colour\np_k = 1.046400526e-05\n";
    t.count("detector self-check: history sample lines flagged (of 6)", static_cast<long>(history_findings(history).size()), 6);
    t.count("detector self-check: clean sample lines flagged", static_cast<long>(history_findings(clean).size()), 0);
    const std::string outside = std::string("see ../") + "sha" + "red/paper/NOTES" + ".md\n(model" + ".md 3.4)\n";
    t.count("detector self-check: outside-reference sample lines flagged (of 2)",
            static_cast<long>(outside_references(outside).size()), 2);
    // Invented names of each kind (split so that this file does not hold them whole), then real ones.
    const std::string invented = std::string("`FlowSolver::nonexis") + "tent_stage()`\n`make nonexis" + "tent-target`\n" +
                                 "`src/flow/nonexis" + "tent_file.cpp`\n`[flow] nonexis" + "tent_key = 1`\n`--nonexis" +
                                 "tent-option`\n";
    const std::string real =
        "`FlowSolver::step()`\n`make verify`\n`src/flow/pressure/pressure_solver.hpp`\n`[flow] dt_max = 2e-3`\n"
        "`--data`\n`steps_dt_max`\n`time = 1.5 s`\n";
    t.count("detector self-check: invented names flagged (of 5)",
            static_cast<long>(unknown_names(invented, "docs/x.md", tree).size()), 5);
    t.count("detector self-check: existing names flagged", static_cast<long>(unknown_names(real, "docs/x.md", tree).size()), 0);
}

Repository find_repository(const char* argv0) {
    Repository repo;
    repo.build = fs::absolute(fs::path(argv0)).parent_path().parent_path();
    for (fs::path p = repo.build; !p.empty(); p = p.parent_path()) {
        if (fs::exists(p / "docs" / "tutorial.md")) {
            repo.root = p;
            break;
        }
        if (p == p.parent_path()) break;
    }
    if (repo.root.empty()) return repo;
    repo.pages.push_back("README.md");
    std::vector<std::string> docs;
    for (const auto& e : fs::directory_iterator(repo.root / "docs"))
        if (e.path().extension() == ".md") docs.push_back("docs/" + e.path().filename().string());
    std::sort(docs.begin(), docs.end());
    repo.pages.insert(repo.pages.end(), docs.begin(), docs.end());
    return repo;
}

}  // namespace

// verify_docs --help.
constexpr const char* kUsage =
    "verify_docs: every page checked against the programs (docs/checked_pages.md)\n"
    "  verify_docs [--data DIR]          the full check (make verify runs it last)\n"
    "  verify_docs --numbers             only the value spans, the numbers in prose and the code\n"
    "                                    excerpts (a second)\n"
    "  verify_docs --refresh             copy fresh generated tables into docs/generated/ and the pages,\n"
    "                                    then rewrite every value span (make docs-refresh)\n"
    "  verify_docs --fingerprint NAME..  record the fingerprints of reference figures just drawn\n"
    "                                    (make docs-figures)\n"
    "  verify_docs --tables              only the generated tables' provenance: every quote of a table\n"
    "                                    made by other physics than this build's is marked (a few seconds)\n"
    "  verify_docs --physics             print this build's physics fingerprints (a few seconds)\n"
    "  verify_docs --provenance PROGRAM COMMAND PART..\n"
    "                                    print the provenance record of a table PROGRAM made by\n"
    "                                    COMMAND with this build, whose numbers depend on PARTs\n"
    "                                    (make fig7's tables)\n"
    "  verify_docs --help                this list\n";

int main(int argc, char** argv) {
    const Repository repo = find_repository(argv[0]);
    const std::string mode = argc > 1 ? argv[1] : "";
    if (mode == "--help" || mode == "-h") return std::cout << kUsage, 0;
    if (mode == "--refresh" || mode == "--fingerprint" || mode == "--physics" || mode == "--provenance") {
        parse_program_options(1, argv);  // only for its handling of errors (exit 2, 3)
        if (repo.root.empty()) return 2;
        if (mode == "--refresh") return refresh_pages(repo.root, repo.build, repo.pages, physics_fingerprints(repo.root));
        if (mode == "--fingerprint")
            return record_fingerprints(repo.root, repo.build, {argv + 2, argv + argc}, repo.build / "data");
        return physics_mode(repo.root, std::vector<std::string>(argv + 1, argv + argc));
    }
    const bool numbers_only = mode == "--numbers", tables_only = mode == "--tables";
    const ProgramOptions options = parse_program_options(numbers_only || tables_only ? 1 : argc, argv);
    CheckTable t("docs: every page checked against the programs (docs/checked_pages.md)");
    t.count("docs/tutorial.md found above the build directory", !repo.root.empty(), 1);
    if (repo.root.empty()) return t.finish();
    if (tables_only) return check_provenance(t, repo.root, repo.pages, physics_fingerprints(repo.root)), t.finish();
    const std::vector<DeclaredInput> inputs = read_inputs(t, repo);
    NumberCounts numbers;
    numbers.uses.assign(inputs.size(), 0);
    for (const std::string& page : repo.pages)
        if (page != "docs/history.md") check_numbers(t, repo, page, read_text(repo.root / page), inputs, numbers);
    check_number_rules(t, inputs, numbers);
    t.note(std::to_string(numbers.spans) + " value spans agree with their sources");
    t.count("self-check: value spans still agreeing with one digit changed", numbers.mutants_agreeing, 0);
    long excerpts = 0, excerpt_mutants = 0;
    for (const std::string& page : repo.pages)
        check_excerpts(t, repo, page, read_text(repo.root / page), excerpts, excerpt_mutants);
    t.note(std::to_string(excerpts) + " code excerpts agree with their code or are counted above");
    t.count("self-check: code excerpts still agreeing with a line changed or dropped without ...", excerpt_mutants, 0);
    if (numbers_only) return t.finish();

    const fs::path scratch = fs::temp_directory_path() / ("granseg_docs_" + std::to_string(::getpid()));
    fs::create_directories(scratch / "out");
    fs::create_directory_symlink(repo.build, scratch / "build");
    for (const char* dir : {"verification", "figures", "docs", "src"})
        fs::create_directory_symlink(repo.root / dir, scratch / dir);

    const TreeNames tree = tree_names(repo.root);
    BlockCounts n;
    std::vector<std::string> shown;
    long generated_mutants_equal = 0, figure_mutants_unchanged = 0;
    for (const std::string& page : repo.pages) {
        const std::string text = read_text(repo.root / page);
        check_hygiene(t, repo, tree, page, text);
        check_blocks(t, page, text, scratch, n);
        check_generated(t, repo, page, text, shown, generated_mutants_equal);
    }
    fs::remove_all(scratch);
    for (const auto& e : fs::directory_iterator(repo.root / "docs" / "generated"))
        t.count("docs/generated/" + e.path().filename().string() + ": shown by a page",
                std::count(shown.begin(), shown.end(), e.path().filename().string()) > 0 ? 1 : 0, 1);
    check_sources(t, repo);
    check_figures(t, repo.root, repo.build, fs::path(options.data_dir), figure_mutants_unchanged);
    check_detectors(t, tree);
    check_provenance(t, repo.root, repo.pages, physics_fingerprints(repo.root));
    t.note(std::to_string(repo.pages.size()) + " pages, " + std::to_string(n.commands) + " command blocks, " +
           std::to_string(n.outputs) + " output blocks, " + std::to_string(n.numeric_lines) + " expected lines with " +
           std::to_string(n.numbers) + " numbers, " + std::to_string(shown.size()) + " generated blocks, " +
           std::to_string(excerpts) + " code excerpts");
    t.count("output blocks not right after a command block", n.orphans, 0);
    t.count("self-check: expected lines still agreeing with one digit changed", n.mutants_agreeing, 0);
    t.count("self-check: generated blocks still equal with one digit changed", generated_mutants_equal, 0);
    t.count("self-check: figures whose fingerprint misses a changed digit", figure_mutants_unchanged, 0);
    return t.finish();
}
