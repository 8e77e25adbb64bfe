#include "harness/doc_names.hpp"

#include "harness/doc_blocks.hpp"
#include "harness/text_pattern.hpp"

#include <cctype>
#include <optional>
#include <sstream>

namespace fs = std::filesystem;

namespace granseg::verify::docs {

namespace {

bool word_char(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

/// The identifiers of a text.
void add_words(const std::string& text, std::set<std::string>& words) {
    for (std::size_t i = 0; i < text.size();) {
        if (!word_char(text[i])) {
            ++i;
            continue;
        }
        std::size_t j = i;
        while (j < text.size() && word_char(text[j])) ++j;
        words.insert(text.substr(i, j - i));
        i = j;
    }
}

/// The Makefile's targets: the names before a ':' (not ':=') at the start of a line, and the
/// words of its .PHONY lines.
std::set<std::string> make_targets(const std::string& makefile) {
    static const Pattern rule(R"(^([A-Za-z0-9_.-]+)\s*:(?!=))");
    std::set<std::string> targets;
    std::istringstream in(makefile);
    bool phony = false;
    for (std::string line; std::getline(in, line);) {
        if (line.rfind(".PHONY:", 0) == 0) phony = true, line = line.substr(7);
        if (phony) {
            std::istringstream words(line);
            for (std::string w; words >> w;)
                if (w != "\\") targets.insert(w);
            phony = !line.empty() && line.back() == '\\';
        } else if (const auto m = rule.first_in(line)) {
            targets.insert((*m)[1]);
        }
    }
    return targets;
}

/// s with each {a,b,...} alternative expanded.
std::vector<std::string> expand(const std::string& s) {
    const auto open = s.find('{'), close = s.find('}', open == std::string::npos ? 0 : open);
    if (open == std::string::npos || close == std::string::npos) return {s};
    std::vector<std::string> out;
    std::istringstream alternatives(s.substr(open + 1, close - open - 1));
    for (std::string a; std::getline(alternatives, a, ',');)
        for (const std::string& rest : expand(s.substr(close + 1))) out.push_back(s.substr(0, open) + a + rest);
    return out;
}

const Pattern kExtension(R"(\.(cpp|hpp|h|toml|md|gp|dat|png|gif|txt|sh|vtk|csv|log|rc|seconds|xml)$)");
const Pattern kPlaceholder(R"(\b[A-Z]{3,}\b|\*)");

bool known_path(std::string p, const std::string& page, const TreeNames& tree) {
    if (kPlaceholder.found_in(p)) return true;
    while (!p.empty() && p.back() == '/') p.pop_back();
    if (fs::exists(tree.root / p) || fs::exists(tree.root / fs::path(page).parent_path() / p)) return true;
    const std::string name = fs::path(p).filename().string();
    const std::string stem = kExtension.removed_from(name);
    return tree.files.count(name) || (!stem.empty() && tree.text.find(stem) != std::string::npos);
}

/// A word of the tree, or "prefix_" in the tree's text followed by a word ("steps_" + bound).
bool known_word(const std::string& w, const TreeNames& tree) {
    if (tree.words.count(w)) return true;
    for (std::size_t u = w.find('_'); u != std::string::npos && u + 1 < w.size(); u = w.find('_', u + 1))
        if (tree.text.find('"' + w.substr(0, u + 1) + '"') != std::string::npos && tree.words.count(w.substr(u + 1))) return true;
    return false;
}

/// The names of one backticked span that the tree does not hold.
std::vector<std::string> unknown_in(const std::string& span, const std::string& page, const TreeNames& tree) {
    static const Pattern make(R"(^make\s+(.*)$)"), section(R"(^\[([A-Za-z_]\w*)\](?:\s+([A-Za-z_]\w*))?)"),
        option(R"(^--([a-z][a-z0-9-]*))"), pathlike(R"(^[A-Za-z0-9_./{},*-]+$)"),
        identifier(R"(^([A-Za-z_]\w*(?:::~?[A-Za-z_]\w*)*)(\(\))?$)"), quoted(R"re(^"([A-Za-z0-9_-]+)"$)re"),
        hyphenated(R"(^([a-z][a-z0-9]*(?:-[a-z0-9]+)+)$)"), assignment(R"(^([A-Za-z]\w*_\w*)\s*=\s*\S)");
    std::vector<std::string> unknown;
    std::optional<PatternMatch> m;
    if ((m = make.match_of(span))) {
        std::istringstream words((*m)[1]);
        for (std::string w; words >> w;)
            if (w != "&&" && w != "make" && w.find('=') == std::string::npos && w[0] != '-' && !tree.targets.count(w))
                unknown.push_back(w);
    } else if ((m = section.first_in(span))) {
        for (int g : {1, 2})
            if (m->took_part[g] && !tree.words.count((*m)[g])) unknown.push_back((*m)[g]);
    } else if ((m = option.first_in(span))) {
        if (tree.text.find((*m)[1]) == std::string::npos) unknown.push_back("--" + (*m)[1]);
    } else if (pathlike.matches(span) && (span.find('/') != std::string::npos || kExtension.found_in(span))) {
        if (span[0] != '.')  // a bare extension (.md) is no file
            for (const std::string& p : expand(span))
                if (!known_path(p, page, tree)) unknown.push_back(p);
    } else if ((m = identifier.match_of(span))) {
        const std::string parts = (*m)[1];
        for (std::size_t start = 0;;) {
            const auto end = parts.find("::", start);
            std::string part = parts.substr(start, end == std::string::npos ? std::string::npos : end - start);
            if (!part.empty() && part[0] == '~') part.erase(0, 1);
            if (!known_word(part, tree)) unknown.push_back(part);
            if (end == std::string::npos) break;
            start = end + 2;
        }
    } else if ((m = quoted.match_of(span)) || (m = hyphenated.match_of(span))) {
        if (tree.text.find((*m)[1]) == std::string::npos) unknown.push_back((*m)[1]);
    } else if ((m = assignment.first_in(span))) {
        if (!known_word((*m)[1], tree)) unknown.push_back((*m)[1]);
    }
    return unknown;
}

}  // namespace

TreeNames tree_names(const fs::path& root) {
    TreeNames tree;
    tree.root = root;
    for (const char* dir : {"src", "verification", "tests", "figures", "docs"})
        for (const auto& e : fs::recursive_directory_iterator(root / dir)) {
            if (!e.is_regular_file()) continue;
            tree.files.insert(e.path().filename().string());
            if (std::string(dir) != "docs") tree.text += read_text(e.path()) + "\n";
        }
    // The Makefile and what it includes from mk/ (its sanitizer, page and speed rules).
    std::string makefile = read_text(root / "Makefile");
    if (fs::is_directory(root / "mk"))
        for (const auto& e : fs::directory_iterator(root / "mk"))
            if (e.path().extension() == ".mk") {
                makefile += "\n" + read_text(e.path());
                tree.files.insert(e.path().filename().string());
            }
    tree.text += makefile;
    tree.files.insert({"Makefile", "README.md"});
    add_words(tree.text, tree.words);
    tree.targets = make_targets(makefile);
    return tree;
}

std::vector<Finding> unknown_names(const std::string& text, const std::string& page, const TreeNames& tree) {
    static const Pattern span(R"(`([^`]+)`)");
    std::vector<Finding> found;
    std::istringstream in(text);
    int number = 0;
    bool fenced = false, exercise = false;
    for (std::string line; std::getline(in, line);) {
        ++number;
        if (line.rfind("```", 0) == 0) fenced = !fenced;
        if (line.find("**Your turn.**") != std::string::npos) exercise = true;
        if (line.find_first_not_of(" \t") == std::string::npos) exercise = false;
        if (fenced || exercise) continue;
        for (const PatternMatch& m : span.all_in(line))
            for (const std::string& name : unknown_in(m[1], page, tree))
                found.push_back({number, "unknown name", "`" + m[1] + "`: " + name});
    }
    return found;
}

}  // namespace granseg::verify::docs
