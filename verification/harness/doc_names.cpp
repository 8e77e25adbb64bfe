#include "harness/doc_names.hpp"

#include "harness/doc_blocks.hpp"

#include <cctype>
#include <regex>
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
    static const std::regex rule(R"(^([A-Za-z0-9_.-]+)\s*:(?!=))");
    std::set<std::string> targets;
    std::istringstream in(makefile);
    bool phony = false;
    for (std::string line; std::getline(in, line);) {
        std::smatch m;
        if (line.rfind(".PHONY:", 0) == 0) phony = true, line = line.substr(7);
        if (phony) {
            std::istringstream words(line);
            for (std::string w; words >> w;)
                if (w != "\\") targets.insert(w);
            phony = !line.empty() && line.back() == '\\';
        } else if (std::regex_search(line, m, rule)) {
            targets.insert(m[1]);
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

const std::regex kExtension(R"(\.(cpp|hpp|h|toml|md|gp|dat|png|gif|txt|sh|vtk|csv|log|rc|seconds|xml)$)");
const std::regex kPlaceholder(R"(\b[A-Z]{3,}\b|\*)");

bool known_path(std::string p, const std::string& page, const TreeNames& tree) {
    if (std::regex_search(p, kPlaceholder)) return true;
    while (!p.empty() && p.back() == '/') p.pop_back();
    if (fs::exists(tree.root / p) || fs::exists(tree.root / fs::path(page).parent_path() / p)) return true;
    const std::string name = fs::path(p).filename().string();
    const std::string stem = std::regex_replace(name, kExtension, "");
    return tree.files.count(name) || (!stem.empty() && tree.text.find(stem) != std::string::npos);
}

/// A word of the tree, or "prefix_" in the tree's text followed by a word ("steps_" + bound).
bool known_word(const std::string& w, const TreeNames& tree) {
    if (tree.words.count(w)) return true;
    for (std::size_t u = w.find('_'); u != std::string::npos && u + 1 < w.size(); u = w.find('_', u + 1))
        if (tree.text.find('"' + w.substr(0, u + 1) + '"') != std::string::npos && tree.words.count(w.substr(u + 1)))
            return true;
    return false;
}

/// The names of one backticked span that the tree does not hold.
std::vector<std::string> unknown_in(const std::string& span, const std::string& page, const TreeNames& tree) {
    static const std::regex make(R"(^make\s+(.*)$)"), section(R"(^\[([A-Za-z_]\w*)\](?:\s+([A-Za-z_]\w*))?)"),
        option(R"(^--([a-z][a-z0-9-]*))"), pathlike(R"(^[A-Za-z0-9_./{},*-]+$)"),
        identifier(R"(^([A-Za-z_]\w*(?:::~?[A-Za-z_]\w*)*)(\(\))?$)"), quoted(R"re(^"([A-Za-z0-9_-]+)"$)re"),
        hyphenated(R"(^([a-z][a-z0-9]*(?:-[a-z0-9]+)+)$)"), assignment(R"(^([A-Za-z]\w*_\w*)\s*=\s*\S)");
    std::vector<std::string> unknown;
    std::smatch m;
    if (std::regex_match(span, m, make)) {
        std::istringstream words(m[1].str());
        for (std::string w; words >> w;)
            if (w != "&&" && w != "make" && w.find('=') == std::string::npos && w[0] != '-' && !tree.targets.count(w))
                unknown.push_back(w);
    } else if (std::regex_search(span, m, section)) {
        for (int g : {1, 2})
            if (m[g].matched && !tree.words.count(m[g])) unknown.push_back(m[g]);
    } else if (std::regex_search(span, m, option)) {
        if (tree.text.find(m[1].str()) == std::string::npos) unknown.push_back("--" + m[1].str());
    } else if (std::regex_match(span, pathlike) && (span.find('/') != std::string::npos || std::regex_search(span, kExtension))) {
        if (span[0] != '.')  // a bare extension (.md) is no file
            for (const std::string& p : expand(span))
                if (!known_path(p, page, tree)) unknown.push_back(p);
    } else if (std::regex_match(span, m, identifier)) {
        std::string parts = m[1];
        for (std::size_t start = 0;;) {
            const auto end = parts.find("::", start);
            std::string part = parts.substr(start, end == std::string::npos ? std::string::npos : end - start);
            if (!part.empty() && part[0] == '~') part.erase(0, 1);
            if (!known_word(part, tree)) unknown.push_back(part);
            if (end == std::string::npos) break;
            start = end + 2;
        }
    } else if (std::regex_match(span, m, quoted) || std::regex_match(span, m, hyphenated)) {
        if (tree.text.find(m[1].str()) == std::string::npos) unknown.push_back(m[1]);
    } else if (std::regex_search(span, m, assignment)) {
        if (!known_word(m[1], tree)) unknown.push_back(m[1]);
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
    const std::string makefile = read_text(root / "Makefile");
    tree.text += makefile;
    tree.files.insert({"Makefile", "README.md"});
    add_words(tree.text, tree.words);
    tree.targets = make_targets(makefile);
    return tree;
}

std::vector<Finding> unknown_names(const std::string& text, const std::string& page, const TreeNames& tree) {
    static const std::regex span(R"(`([^`]+)`)");
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
        for (std::sregex_iterator it(line.begin(), line.end(), span), end; it != end; ++it)
            for (const std::string& name : unknown_in((*it)[1], page, tree))
                found.push_back({number, "unknown name", "`" + (*it)[1].str() + "`: " + name});
    }
    return found;
}

}  // namespace granseg::verify::docs
