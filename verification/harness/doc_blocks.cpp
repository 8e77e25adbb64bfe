#include "harness/doc_blocks.hpp"

#include "harness/text_pattern.hpp"

#include <sys/wait.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>

namespace fs = std::filesystem;

namespace granseg::verify::docs {

namespace {

// Relative slack on top of half a unit of the last digit: the printed value and the page's
// number are both decimal renderings, so only the conversion of each to double (1.1e-16
// relative, half an ulp) separates two equal numbers at the boundary of the interval; 1e-15 covers
// it and stays below the last digit of any number a double prints (at most 17 significant digits
// of which a page quotes at most 15).
constexpr double kConversionSlack = 1e-15;

const std::string kGeneratedOpen = "<!-- generated: ";
const std::string kGeneratedClose = "<!-- end generated -->";

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

const Pattern& number_pattern() {
    static const Pattern r(R"([-+]?(\d+\.?(\d*)|\.(\d+))([eE]([-+]?\d+))?)");
    return r;
}

/// How many words and numbers a printed line shares with the page's, for pointing at the nearest.
std::size_t likeness(const Tokens& printed, const Tokens& page) {
    std::size_t n = 0;
    for (std::size_t i = 0; i < std::min(printed.words.size(), page.words.size()); ++i) n += printed.words[i] == page.words[i];
    for (std::size_t i = 0; i < std::min(printed.numbers.size(), page.numbers.size()); ++i)
        n += std::fabs(printed.numbers[i] - page.numbers[i]) <= 0.5 * page.units[i];
    return n;
}

std::vector<std::string> read_lines(const fs::path& p) {
    std::ifstream in(p);
    std::vector<std::string> lines;
    for (std::string line; std::getline(in, line);) lines.push_back(line);
    return lines;
}

}  // namespace

std::vector<Block> fenced_blocks(const std::string& text) {
    std::vector<Block> blocks;
    std::istringstream in(text);
    bool open = false;
    int number = 0;
    for (std::string line; std::getline(in, line);) {
        ++number;
        if (line.rfind("```", 0) != 0) {
            if (open) blocks.back().lines.push_back(line);
            continue;
        }
        if (open) {
            open = false;
            continue;
        }
        Block b;
        std::istringstream words(line.substr(3));
        words >> b.language;
        std::getline(words >> std::ws, b.info);
        b.first_line = number;
        blocks.push_back(b);
        open = true;
    }
    return blocks;
}

int expected_status(const Block& b) {
    const std::string key = "exit=";
    const auto at = b.info.find(key);
    return at == std::string::npos ? 0 : std::stoi(b.info.substr(at + key.size()));
}

Tokens tokens_of(const std::string& line) {
    Tokens t;
    std::string rest = collapse_blanks(line);
    while (const auto m = number_pattern().first_in(rest)) {
        t.words.push_back(m->prefix);
        t.numbers.push_back(std::stod((*m)[0]));
        const int decimals = static_cast<int>((*m)[2].size() + (*m)[3].size());
        const int exponent = m->took_part[5] ? std::stoi((*m)[5]) : 0;
        t.units.push_back(std::pow(10.0, exponent - decimals));
        rest = m->suffix;
    }
    t.words.push_back(rest);
    return t;
}

bool within_last_digit(double printed, double shown, double unit) {
    return std::fabs(printed - shown) <= 0.5 * unit + kConversionSlack * std::fabs(shown);
}

bool is_ellipsis(const std::string& line) {
    const std::string t = trimmed(line);
    return t.rfind("...", 0) == 0 && (t.size() == 3 || trimmed(t.substr(3)).rfind("//", 0) == 0);
}

std::string trimmed(const std::string& s) {
    const auto a = s.find_first_not_of(" \t"), b = s.find_last_not_of(" \t");
    return a == std::string::npos ? "" : s.substr(a, b - a + 1);
}

std::vector<std::string> lines_of(const std::string& text) {
    std::vector<std::string> lines;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);) lines.push_back(line);
    return lines;
}

bool agrees(const Tokens& printed, const Tokens& page) {
    if (printed.words != page.words || printed.numbers.size() != page.numbers.size()) return false;
    for (std::size_t i = 0; i < page.numbers.size(); ++i)
        if (!within_last_digit(printed.numbers[i], page.numbers[i], page.units[i])) return false;
    return true;
}

Tokens mutated(Tokens t) {
    t.numbers.back() += t.units.back();
    return t;
}

Comparison compare(const std::vector<std::string>& expected, const std::vector<std::string>& printed) {
    Comparison c;
    std::vector<Tokens> out;
    for (const auto& line : printed) out.push_back(tokens_of(line));
    std::size_t next = 0;  // expected lines match printed lines in order
    bool marked = false;   // a `...` line since the last matched line
    for (const auto& line : expected) {
        if (collapse_blanks(line).empty()) continue;
        if (is_ellipsis(line)) {
            marked = true;
            continue;
        }
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
            c.numbers += static_cast<long>(page.numbers.size());
            if (agrees(out[k], mutated(page)) && c.mutants_agreeing++ == 0) c.first_mutant_agreeing = line;
        }
        if (k > next && !marked && c.unmarked_gaps++ == 0) c.first_unmarked = line;
        next = k + 1, marked = false;
    }
    if (next < out.size() && !marked && c.missing == 0 && c.unmarked_gaps++ == 0) c.first_unmarked = "(the end of the block)";
    return c;
}

Run run_block(const Block& b, const fs::path& scratch, int timeout_seconds) {
    const fs::path script = scratch / "block.sh", output = scratch / "block.out";
    {
        std::ofstream s(script);
        for (const auto& line : b.lines) s << line << '\n';
    }
    // One OpenMP thread: make verify runs the verification programs side by side, and a threaded
    // run on a busy machine waits for its threads far longer than it computes.
    const std::string command = "cd '" + scratch.string() + "' && OMP_NUM_THREADS=1 timeout " + std::to_string(timeout_seconds) +
                                " sh -e '" + script.string() + "' > '" + output.string() + "' 2>&1 < /dev/null";
    const int raw = std::system(command.c_str());
    return {WIFEXITED(raw) ? WEXITSTATUS(raw) : -1, read_lines(output)};
}

std::vector<Generated> generated_blocks(const std::string& page, std::string& error) {
    std::vector<Generated> blocks;
    std::istringstream in(page);
    bool open = false;
    int number = 0;
    for (std::string line; std::getline(in, line);) {
        ++number;
        const bool opens = line.rfind(kGeneratedOpen, 0) == 0, closes = line == kGeneratedClose;
        if (opens || closes) {
            if (opens == open) {
                error = "line " + std::to_string(number) + ": " + (open ? "nested generated block" : "end without a start");
                return blocks;
            }
            open = opens;
            if (opens) {
                const auto end = line.find(" -->");
                if (end == std::string::npos || end <= kGeneratedOpen.size()) {
                    error = "line " + std::to_string(number) + ": malformed marker " + line;
                    return blocks;
                }
                blocks.push_back({line.substr(kGeneratedOpen.size(), end - kGeneratedOpen.size()), "", number});
            }
            continue;
        }
        if (open) blocks.back().text += line + "\n";
    }
    if (open) error = "line " + std::to_string(blocks.back().first_line) + ": generated block not closed";
    return blocks;
}

std::string with_generated(const std::string& page, const std::string& name, const std::string& text) {
    std::string out;
    std::istringstream in(page);
    bool skipping = false;
    for (std::string line; std::getline(in, line);) {
        if (skipping && line != kGeneratedClose) continue;
        skipping = false;
        out += line + "\n";
        if (line == kGeneratedOpen + name + " -->") {
            out += text;
            skipping = true;
        }
    }
    return out;
}

std::string read_text(const fs::path& p, bool* found) {
    std::ifstream in(p, std::ios::binary);
    if (found) *found = static_cast<bool>(in);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

}  // namespace granseg::verify::docs
