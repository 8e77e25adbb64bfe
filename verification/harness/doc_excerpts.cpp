#include "harness/doc_excerpts.hpp"

#include "harness/doc_blocks.hpp"

#include <cctype>
#include <map>
#include <sstream>
#include <tuple>
#include <utility>

namespace fs = std::filesystem;

namespace granseg::verify::docs {

namespace {

const std::string kMarkerOpen = "<!-- excerpt: ";
const std::string kMarkerClose = "-->";

bool identifier_char(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

/// The line with comments, string and character literals blanked (for finding the code's braces);
/// `in_block` carries a /* comment over lines.
std::string code_only(const std::string& line, bool& in_block) {
    std::string out(line.size(), ' ');
    for (std::size_t i = 0; i < line.size(); ++i) {
        if (in_block) {
            if (line.compare(i, 2, "*/") == 0) in_block = false, ++i;
            continue;
        }
        if (line.compare(i, 2, "//") == 0) break;
        if (line.compare(i, 2, "/*") == 0) {
            in_block = true, ++i;
            continue;
        }
        const char c = line[i];
        if (c == '"' || (c == '\'' && !(i > 0 && std::isxdigit(static_cast<unsigned char>(line[i - 1]))))) {
            for (++i; i < line.size() && line[i] != c; ++i)
                if (line[i] == '\\') ++i;
            continue;
        }
        out[i] = c;
    }
    return out;
}

/// How the code of a line (comments blanked) names the symbol: 'f' a function (its name after a
/// return type, then '('), 't' a type (struct, class, enum), 'c' a constant or table ('=', '{' or
/// '[' after it), 0 not as a definition.
char defines(const std::string& code, const std::string& symbol) {
    for (auto at = code.find(symbol); at != std::string::npos; at = code.find(symbol, at + 1)) {
        const std::size_t after = at + symbol.size();
        if ((at > 0 && identifier_char(code[at - 1])) || (after < code.size() && identifier_char(code[after]))) continue;
        const std::string before = trimmed(code.substr(0, at));
        std::size_t next = code.find_first_not_of(' ', after);
        const char follows = next == std::string::npos ? '\0' : code[next];
        for (const char* kind : {"struct", "class", "enum", "enum class"}) {
            const std::string k = kind;
            if (before.size() >= k.size() && before.compare(before.size() - k.size(), k.size(), k) == 0) return 't';
        }
        // A definition starts with its type: only type characters before the name, at least one word.
        if (before.empty() || before.find_first_not_of(
                                  "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789_:<>,*& ") != std::string::npos)
            continue;
        std::istringstream words(before);
        bool statement = false;
        for (std::string w; words >> w;) statement = statement || w == "return" || w == "else" || w == "new" || w == "delete";
        if (statement) continue;
        if (follows == '(') return 'f';
        if (follows == '=' || follows == '{' || follows == '[') return 'c';
    }
    return 0;
}

/// Lines [first, last] of the definition that starts at line `first`, or nullopt for a declaration.
std::optional<std::size_t> definition_end(const std::vector<std::string>& lines, std::size_t first, char kind) {
    bool in_block = false, opened = false;
    int depth = 0;
    for (std::size_t i = first; i < lines.size(); ++i) {
        for (char c : code_only(lines[i], in_block)) {
            if (c == '{') ++depth, opened = true;
            if (c == '}') --depth;
            if (c == ';' && !opened) return kind == 'f' ? std::nullopt : std::optional<std::size_t>(i);
            if (opened && depth == 0) return i;
        }
    }
    return std::nullopt;
}

/// Whether shown[i..] matches definition lines after `prev` (-1: none yet), with `gap` true when an
/// ellipsis stands right before shown[i]; memoised on (i, prev, gap).
struct Matcher {
    const std::vector<std::string>& shown;
    const std::vector<std::string>& definition;
    std::map<std::tuple<std::size_t, long, bool>, bool> memo;

    bool from(std::size_t i, long prev, bool gap) {
        const long n = static_cast<long>(definition.size());
        if (i == shown.size()) return gap ? prev < n - 1 : prev == n - 1;  // a trailing `...` must leave something out
        if (is_ellipsis(shown[i])) return !gap && from(i + 1, prev, true);
        const auto key = std::make_tuple(i, prev, gap);
        if (const auto hit = memo.find(key); hit != memo.end()) return hit->second;
        bool ok = false;
        if (!gap) {
            ok = prev + 1 < n && definition[prev + 1] == shown[i] && from(i + 1, prev + 1, false);
        } else {
            for (long j = prev + 2; j < n && !ok; ++j) ok = definition[j] == shown[i] && from(i + 1, j, false);
        }
        return memo[key] = ok;
    }
};

}  // namespace

std::vector<Excerpt> excerpts_of(const std::string& page, std::string& error) {
    const std::vector<std::string> lines = lines_of(page);
    std::vector<Excerpt> found;
    for (std::size_t i = 0; i < lines.size(); ++i) {
        const std::string t = trimmed(lines[i]);
        if (lines[i].rfind(kMarkerOpen, 0) != 0) continue;  // an indented marker is an example
        const std::string where = "line " + std::to_string(i + 1) + ": ";
        Excerpt e;
        e.marker_line = static_cast<int>(i + 1);
        std::istringstream words(t.substr(kMarkerOpen.size()));
        std::string close;
        words >> e.file >> e.symbol >> close;
        if (e.symbol.empty() || close != kMarkerClose) {
            error = where + "an excerpt marker is <!-- excerpt: FILE SYMBOL -->";
            continue;
        }
        if (i + 1 >= lines.size() || lines[i + 1].rfind("```", 0) != 0) {
            error = where + "an excerpt marker must stand right above a fenced block";
            continue;
        }
        e.begin = i + 2;
        std::size_t j = e.begin;
        while (j < lines.size() && lines[j].rfind("```", 0) != 0) e.lines.push_back(lines[j++]);
        if (j == lines.size()) {
            error = where + "the excerpt's fenced block is not closed";
            continue;
        }
        e.end = j;
        found.push_back(e);
        i = j;
    }
    return found;
}

std::vector<std::string> definition_of(const std::string& source, const std::string& symbol) {
    const std::vector<std::string> lines = lines_of(source);
    bool in_block = false;
    for (std::size_t i = 0; i < lines.size(); ++i) {
        const char kind = defines(code_only(lines[i], in_block), symbol);
        if (kind == 0) continue;
        const auto last = definition_end(lines, i, kind);
        if (last) return {lines.begin() + static_cast<long>(i), lines.begin() + static_cast<long>(*last) + 1};
    }
    return {};
}

std::optional<std::string> excerpt_problem(const std::vector<std::string>& shown, const std::vector<std::string>& definition) {
    if (definition.empty()) return "no definition of the symbol in the file";
    Matcher m{shown, definition, {}};
    if (m.from(0, -1, false)) return std::nullopt;
    for (const std::string& line : shown) {
        bool present = is_ellipsis(line);
        for (const std::string& d : definition) present = present || d == line;
        if (!present) return "this line is not in the code: \"" + trimmed(line) + "\"";
    }
    return std::string("lines left out without a `...` line, a `...` where nothing is left out, or lines out of order");
}

ExcerptCheck check_excerpt(const Excerpt& e, const fs::path& root) {
    ExcerptCheck c;
    bool found = false;
    const std::string source = read_text(root / e.file, &found);
    if (!found) {
        c.problem = "no file " + e.file;
        return c;
    }
    c.definition = definition_of(source, e.symbol);
    c.problem = excerpt_problem(e.lines, c.definition);
    return c;
}

long excerpt_mutants_accepted(const std::vector<std::string>& shown, const std::vector<std::string>& definition) {
    long accepted = 0;
    for (std::size_t k = 0; k < shown.size(); ++k) {
        if (is_ellipsis(shown[k])) continue;
        std::vector<std::string> changed = shown;
        changed[k] += "x";
        accepted += !excerpt_problem(changed, definition).has_value();
        const bool next_to_ellipsis = (k > 0 && is_ellipsis(shown[k - 1])) || (k + 1 < shown.size() && is_ellipsis(shown[k + 1]));
        if (next_to_ellipsis) continue;  // dropping it widens a marked gap: still an excerpt
        std::vector<std::string> dropped = shown;
        dropped.erase(dropped.begin() + static_cast<long>(k));
        accepted += !excerpt_problem(dropped, definition).has_value();
    }
    return accepted;
}

std::string with_fresh_excerpts(const std::string& page, const fs::path& root, int& rewritten) {
    std::string error;
    const std::vector<Excerpt> found = excerpts_of(page, error);
    const std::vector<std::string> lines = lines_of(page);
    std::vector<std::string> out;
    std::size_t next = 0;
    for (const Excerpt& e : found) {
        const ExcerptCheck c = check_excerpt(e, root);
        if (!c.problem || c.definition.empty()) continue;
        out.insert(out.end(), lines.begin() + static_cast<long>(next), lines.begin() + static_cast<long>(e.begin));
        out.insert(out.end(), c.definition.begin(), c.definition.end());
        next = e.end;
        ++rewritten;
    }
    out.insert(out.end(), lines.begin() + static_cast<long>(next), lines.end());
    std::string text;
    for (const std::string& line : out) text += line + '\n';
    return text;
}

}  // namespace granseg::verify::docs
