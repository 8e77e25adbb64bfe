#include "harness/doc_prose.hpp"

#include "harness/doc_blocks.hpp"

#include <sstream>

namespace granseg::verify::docs {

namespace {

const std::string kInputsFence = "```inputs";

bool blank(const std::string& line) { return line.find_first_not_of(" \t") == std::string::npos; }

void blank_range(std::string& line, std::size_t from, std::size_t to) {
    for (std::size_t i = from; i < to && i < line.size(); ++i) line[i] = ' ';
}

/// Blanks, within one line of prose, HTML comments (value spans with their number), code spans
/// and link targets.
void blank_inline(std::string& line) {
    for (std::size_t at = line.find("<!--"); at != std::string::npos; at = line.find("<!--", at)) {
        std::size_t end = line.find("-->", at + 4);
        end = end == std::string::npos ? line.size() : end + 3;
        if (line.compare(at, 11, "<!-- value:") == 0) {
            const std::size_t close = line.find("<!-- /value -->", at);
            end = close == std::string::npos ? line.size() : close + 15;
        }
        blank_range(line, at, end);
    }
    for (std::size_t at = line.find('`'); at != std::string::npos; at = line.find('`', at)) {
        const std::size_t end = line.find('`', at + 1);
        blank_range(line, at, end == std::string::npos ? line.size() : end + 1);
    }
    for (std::size_t at = line.find("]("); at != std::string::npos; at = line.find("](", at)) {
        const std::size_t end = line.find(')', at);
        blank_range(line, at + 1, end == std::string::npos ? line.size() : end + 1);
    }
}

// A result typed by hand: a decimal or exponent number, or an integer counting what a run
// produces or costs (a percentage, a time, steps, iterations).
const Pattern& decimal_pattern() {
    static const Pattern p(R"((^|[^\w.])(\d+(?:,\d{3})*\.\d+(?:[eE][-+]?\d+)?|\d+[eE][-+]?\d+)(?![\w]))");
    return p;
}
const Pattern& count_pattern() {
    static const Pattern p(
        R"((^|[^\w.,^])(\d+(?:,\d{3})* ?(?:%|CPU-hours?|CPU-s|seconds?|minutes?|min|hours?|s|sub-steps|steps|iterations|V-cycles|cycles))(?![\w/-]))");
    return p;
}

// A ratio, share or count of a result in words ("twice", "a third", "two hundredths") or as
// "N of M": a result typed by hand unless spanned (doc_words.hpp) or declared. "Half" is left out:
// pages use it for inputs (half the step) far more often than for results.
const Pattern& word_pattern() {
    static const Pattern p(
        R"((^|[^\w])((?:twice|thrice|(?:two|three|four|five|six|seven|eight|nine|ten|eleven|twelve|fifteen|twenty|thirty|)"
        R"(forty|fifty|a hundred) times|a third|two thirds|a quarter|three quarters|a fifth|(?:two|three|four) fifths|a tenth|)"
        R"((?:one|two|three|four|five|six|seven|eight|nine) hundredths?|\d+(?:,\d{3})* of \d+(?:,\d{3})*))(?![\w]))",
        true);
    return p;
}

}  // namespace

std::vector<DeclaredInput> declared_inputs(const std::string& declaring_page, std::string& error) {
    std::vector<DeclaredInput> inputs;
    const std::vector<std::string> lines = lines_of(declaring_page);
    bool inside = false;
    for (std::size_t i = 0; i < lines.size(); ++i) {
        const std::string& line = lines[i];
        if (!inside) {
            inside = line == kInputsFence;
            continue;
        }
        if (line.rfind("```", 0) == 0) break;
        if (blank(line)) continue;
        const std::string where = "inputs line " + std::to_string(i + 1) + ": ";
        const auto hash = line.rfind("  # ");
        if (hash == std::string::npos || blank(line.substr(hash + 4))) {
            error = where + "no \"  # why\" after the expression: " + line;
            return {};
        }
        std::string expression = line.substr(0, hash), page;
        if (expression.rfind('@', 0) == 0) {
            const auto space = expression.find(' ');
            page = expression.substr(1, space == std::string::npos ? std::string::npos : space - 1);
            expression = space == std::string::npos ? "" : expression.substr(space + 1);
        }
        expression.erase(expression.find_last_not_of(" \t") + 1);
        try {
            inputs.push_back({expression, line.substr(hash + 4), page, Pattern(expression), static_cast<int>(i + 1)});
        } catch (const std::exception& e) {
            error = where + "the expression does not compile (" + e.what() + "): " + expression;
            return {};
        }
    }
    if (!inside) error = "no " + kInputsFence + " block";
    return inputs;
}

std::vector<bool> indented_code_lines(const std::string& page) {
    const std::vector<std::string> lines = lines_of(page);
    std::vector<bool> code(lines.size(), false);
    bool fenced = false;
    for (std::size_t i = 0; i < lines.size(); ++i) {
        const std::string& line = lines[i];
        if (line.rfind("```", 0) == 0) fenced = !fenced;
        const bool code_indent = line.rfind("    ", 0) == 0 || line.rfind("\t", 0) == 0;
        code[i] = !fenced && code_indent && (i == 0 || code[i - 1] || blank(lines[i - 1])) && !blank(line);
    }
    return code;
}

std::string prose_of(const std::string& page) {
    std::vector<std::string> lines = lines_of(page);
    const std::vector<bool> indented = indented_code_lines(page);
    bool fenced = false, generated = false;
    for (std::size_t i = 0; i < lines.size(); ++i) {
        std::string& line = lines[i];
        const bool fence = line.rfind("```", 0) == 0;
        const bool generated_marker = line.rfind("<!-- generated: ", 0) == 0 || line == "<!-- end generated -->";
        if (fence) fenced = !fenced;
        if (generated_marker) generated = line != "<!-- end generated -->";
        if (fence || fenced || generated || generated_marker || indented[i])
            blank_range(line, 0, line.size());
        else
            blank_inline(line);
    }
    std::string out;
    for (const std::string& line : lines) out += line + "\n";
    return out;
}

std::vector<Finding> hand_typed_numbers(const std::string& page_text, const std::string& page,
                                        const std::vector<DeclaredInput>& inputs, std::vector<long>& uses) {
    uses.resize(inputs.size(), 0);
    std::vector<Finding> found;
    const std::vector<std::string> original = lines_of(page_text), prose = lines_of(prose_of(page_text));
    for (std::size_t n = 0; n < prose.size(); ++n) {
        std::string line = prose[n];
        if (blank(line)) continue;
        for (std::size_t i = 0; i < inputs.size(); ++i) {
            if (!inputs[i].page.empty() && inputs[i].page != page) continue;
            std::size_t from = 0;
            // Blank each match (its length kept), so that numbers inside it are not flagged.
            while (const auto m = inputs[i].pattern.first_in(line.substr(from))) {
                const std::size_t at = from + m->prefix.size(), length = (*m)[0].size();
                blank_range(line, at, at + length);
                ++uses[i];
                from = at + std::max<std::size_t>(length, 1);
                if (from >= line.size()) break;
            }
        }
        for (const Pattern* p : {&decimal_pattern(), &count_pattern(), &word_pattern()}) {
            std::size_t from = 0;
            while (const auto m = p->first_in(line.substr(from))) {
                const std::size_t at = from + m->prefix.size() + (*m)[1].size(), length = (*m)[2].size();
                const std::size_t start = at > 30 ? at - 30 : 0;
                found.push_back({static_cast<int>(n + 1), "number typed by hand: " + (*m)[2],
                                 original[n].substr(start, at - start + length + 20)});
                blank_range(line, at, at + length);
                from = at + length;
            }
        }
    }
    return found;
}

}  // namespace granseg::verify::docs
