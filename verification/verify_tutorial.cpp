// The tutorial cannot go stale: runs every command block of docs/tutorial.md and compares the
// lines the page marks as expected output with what the commands print.
//
// The page's conventions (docs/tutorial.md, "How this page is checked"):
//   - a fenced block ```sh is a command block: it runs as one `sh -e` script in a scratch
//     directory that looks like the top of the repository (build/, verification/, figures/,
//     docs/, src/ link to the real ones; out/ is the scratch's own), stdout and stderr together;
//     it must exit with status 0, or N if its fence says ```sh exit=N;
//   - a fenced block ```output right after a command block lists expected lines: each must
//     appear in the printed output, in order (other printed lines may come between them). Two
//     lines agree when their words are equal (runs of blanks count as one blank) and their
//     numbers agree to the precision the page prints: |printed - page| <= half a unit of the
//     page's last digit (0.9382 stands for [0.93815, 0.93825]; an integer for itself).
// What is checked, and why it can fail:
//   - every command block: its exit status;
//   - every output block: expected lines not found in order (0); the first one missing is
//     printed with the printed line most like it;
//   - the matcher itself: every expected line that holds a number, with its last number moved by
//     one unit of its last digit, must no longer agree with the line it matched (0 that still
//     agree), so a changed number on the page fails this program.
// The page must have at least one command block and one output block.
//
// Run: build/verification/verify_tutorial [--data DIR]   (about 10 s of CPU time, most of it the
// coupled drum of step 7; finds the page by walking up from its own directory, the CLI at build/granseg)
#include "harness/check_table.hpp"
#include "harness/program.hpp"

#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

namespace fs = std::filesystem;
using granseg::verify::CheckTable;

namespace {

// Relative slack on top of half a unit of the last digit: the printed value and the page's
// number are both decimal renderings, so only the conversion of each to double (1e-16
// relative) separates two equal numbers; 1e-12 is far below any printed precision.
constexpr double kConversionSlack = 1e-12;
// Seconds one command block may take before it counts as failed (the slowest block of the
// page runs three verification programs, a few seconds).
constexpr int kBlockTimeout = 300;

/// A fenced block of the page.
struct Block {
    std::string language, info;  // "sh", "exit=2"
    std::vector<std::string> lines;
    int first_line = 0;  // line number of the opening fence
};

std::vector<Block> fenced_blocks(const std::string& text) {
    std::vector<Block> blocks;
    std::istringstream in(text);
    Block* open = nullptr;
    int number = 0;
    for (std::string line; std::getline(in, line);) {
        ++number;
        if (line.rfind("```", 0) != 0) {
            if (open) open->lines.push_back(line);
            continue;
        }
        if (open) {
            open = nullptr;
            continue;
        }
        Block b;
        std::istringstream words(line.substr(3));
        words >> b.language;
        std::getline(words >> std::ws, b.info);
        b.first_line = number;
        blocks.push_back(b);
        open = &blocks.back();
    }
    return blocks;
}

/// A line split into words and numbers, in order.
struct Tokens {
    std::vector<std::string> words;  // text between the numbers, blanks collapsed
    std::vector<double> numbers;
    std::vector<double> units;  // one unit of the last printed digit of each number
};

std::string collapse_blanks(const std::string& s) {
    std::string out;
    for (char c : s) {
        const bool blank = c == ' ' || c == '\t';
        if (blank && (out.empty() || out.back() == ' ')) continue;
        out += blank ? ' ' : c;
    }
    while (!out.empty() && out.back() == ' ') out.pop_back();
    return out;
}

const std::regex& number_pattern() {
    static const std::regex r(R"([-+]?(\d+\.?(\d*)|\.(\d+))([eE]([-+]?\d+))?)");
    return r;
}

Tokens tokens_of(const std::string& line) {
    Tokens t;
    std::string rest = collapse_blanks(line);
    std::smatch m;
    while (std::regex_search(rest, m, number_pattern())) {
        t.words.push_back(m.prefix());
        t.numbers.push_back(std::stod(m.str(0)));
        const int decimals = static_cast<int>(m.length(2) + m.length(3));
        const int exponent = m[5].matched ? std::stoi(m.str(5)) : 0;
        t.units.push_back(std::pow(10.0, exponent - decimals));
        rest = m.suffix();
    }
    t.words.push_back(rest);
    return t;
}

/// True if the printed line agrees with the page's line (see the header).
bool agrees(const Tokens& printed, const Tokens& page) {
    if (printed.words != page.words || printed.numbers.size() != page.numbers.size()) return false;
    for (std::size_t i = 0; i < page.numbers.size(); ++i) {
        const double slack = 0.5 * page.units[i] + kConversionSlack * std::fabs(page.numbers[i]);
        if (!(std::fabs(printed.numbers[i] - page.numbers[i]) <= slack)) return false;
    }
    return true;
}

/// The page's line with its last number moved by one unit of its last digit.
Tokens mutated(Tokens t) {
    t.numbers.back() += t.units.back();
    return t;
}

struct Run {
    int status = -1;
    std::vector<std::string> lines;
};

std::vector<std::string> read_lines(const fs::path& p) {
    std::ifstream in(p);
    std::vector<std::string> lines;
    for (std::string line; std::getline(in, line);) lines.push_back(line);
    return lines;
}

Run run_block(const Block& b, const fs::path& scratch) {
    const fs::path script = scratch / "block.sh", output = scratch / "block.out";
    std::ofstream(script) << [&] {
        std::string s;
        for (const auto& line : b.lines) s += line + "\n";
        return s;
    }();
    const std::string command = "cd '" + scratch.string() + "' && timeout " + std::to_string(kBlockTimeout) +
                                " sh -e '" + script.string() + "' > '" + output.string() + "' 2>&1 < /dev/null";
    const int raw = std::system(command.c_str());
    return {WIFEXITED(raw) ? WEXITSTATUS(raw) : -1, read_lines(output)};
}

int expected_status(const Block& b) {
    const std::string key = "exit=";
    const auto at = b.info.find(key);
    return at == std::string::npos ? 0 : std::stoi(b.info.substr(at + key.size()));
}

/// How many words and numbers a printed line shares with the page's, for pointing at the nearest.
std::size_t likeness(const Tokens& printed, const Tokens& page) {
    std::size_t n = 0;
    for (std::size_t i = 0; i < std::min(printed.words.size(), page.words.size()); ++i) n += printed.words[i] == page.words[i];
    for (std::size_t i = 0; i < std::min(printed.numbers.size(), page.numbers.size()); ++i)
        n += std::fabs(printed.numbers[i] - page.numbers[i]) <= 0.5 * page.units[i];
    return n;
}

/// Per output block: expected lines not found in order; mutated lines that still agree.
struct Comparison {
    long missing = 0, mutants_agreeing = 0, numeric_lines = 0;
    std::string first_missing, nearest;
};

Comparison compare(const std::vector<std::string>& expected, const std::vector<std::string>& printed) {
    Comparison c;
    std::vector<Tokens> out;
    for (const auto& line : printed) out.push_back(tokens_of(line));
    std::size_t next = 0;  // expected lines match printed lines in order
    for (const auto& line : expected) {
        if (collapse_blanks(line).empty()) continue;
        const Tokens page = tokens_of(line);
        std::size_t k = next;
        while (k < out.size() && !agrees(out[k], page)) ++k;
        if (k == out.size()) {
            if (c.missing++ == 0) {
                c.first_missing = line;
                std::size_t best = 0;
                for (std::size_t i = 0; i < out.size(); ++i)
                    if (likeness(out[i], page) > likeness(out[best], page)) best = i;
                c.nearest = out.empty() ? "(nothing printed)" : printed[best];
            }
            continue;
        }
        if (!page.numbers.empty()) {
            ++c.numeric_lines;
            c.mutants_agreeing += agrees(out[k], mutated(page));
        }
        next = k + 1;
    }
    return c;
}

/// The directory holding docs/tutorial.md: the first ancestor of `start` that has it.
fs::path find_root(fs::path start) {
    for (fs::path p = fs::absolute(start); !p.empty(); p = p.parent_path()) {
        if (fs::exists(p / "docs" / "tutorial.md")) return p;
        if (p == p.parent_path()) break;
    }
    return {};
}

}  // namespace

int main(int argc, char** argv) {
    granseg::verify::parse_program_options(argc, argv);
    const fs::path build = fs::absolute(fs::path(argv[0])).parent_path().parent_path();
    const fs::path root = find_root(build);
    CheckTable t("docs/tutorial.md: every command block runs, every expected line is printed");
    t.count("docs/tutorial.md found above the build directory", !root.empty(), 1);
    if (root.empty()) return t.finish();

    const fs::path scratch = fs::temp_directory_path() / ("granseg_tutorial_" + std::to_string(::getpid()));
    fs::create_directories(scratch);
    fs::create_directory_symlink(build, scratch / "build");
    for (const char* dir : {"verification", "figures", "docs", "src"}) fs::create_directory_symlink(root / dir, scratch / dir);

    std::ifstream page(root / "docs" / "tutorial.md");
    std::stringstream text;
    text << page.rdbuf();
    const std::vector<Block> blocks = fenced_blocks(text.str());
    long commands = 0, outputs = 0, orphans = 0, numeric_lines = 0, mutants_agreeing = 0;
    Run last;
    bool after_command = false;
    for (const Block& b : blocks) {
        const std::string where = "line " + std::to_string(b.first_line);
        if (b.language == "sh") {
            ++commands;
            last = run_block(b, scratch);
            t.count(where + ": command block exit status", last.status, expected_status(b));
            after_command = true;
            continue;
        }
        if (b.language == "output") {
            if (!after_command) {
                ++orphans;
                continue;
            }
            ++outputs;
            const Comparison c = compare(b.lines, last.lines);
            t.count(where + ": expected lines not printed (of " + std::to_string(b.lines.size()) + ")", c.missing, 0);
            if (c.missing > 0) {
                t.note("  expected: " + c.first_missing);
                t.note("  nearest printed line: " + c.nearest);
            }
            numeric_lines += c.numeric_lines;
            mutants_agreeing += c.mutants_agreeing;
        }
        after_command = false;  // an output block belongs to the command block right before it
    }
    t.note(std::to_string(commands) + " command blocks, " + std::to_string(outputs) + " output blocks, " +
           std::to_string(numeric_lines) + " expected lines with numbers");
    t.at_least("command blocks on the page", commands, 1);
    t.at_least("output blocks on the page", outputs, 1);
    t.count("output blocks not right after a command block", orphans, 0);
    t.count("expected lines still agreeing with one digit changed", mutants_agreeing, 0);
    fs::remove_all(scratch);
    return t.finish();
}
