#include "harness/doc_hygiene.hpp"

#include "harness/doc_blocks.hpp"
#include "harness/text_pattern.hpp"

#include <algorithm>
#include <cctype>
#include <set>
#include <sstream>

namespace fs = std::filesystem;

namespace granseg::verify::docs {

namespace {

struct NamedPattern {
    std::string what;
    Pattern re;
};

const std::string kMonths =
    "(January|February|March|April|May|June|July|August|September|October|November|December|"
    "Jan|Feb|Mar|Apr|Jun|Jul|Aug|Sep|Sept|Oct|Nov|Dec)\\.?";

std::vector<NamedPattern> history_list() {
    std::vector<NamedPattern> p;
    p.push_back({"date", Pattern("\\b\\d{1,2} " + kMonths + ",? \\d{4}\\b")});
    p.push_back({"date", Pattern("\\b" + kMonths + " \\d{1,2},? \\d{4}\\b")});
    p.push_back({"date", Pattern("\\b" + kMonths + " \\d{4}\\b")});
    p.push_back({"date", Pattern(R"(\b\d{4}-\d{2}-\d{2}\b)")});
    p.push_back({"date", Pattern(R"(\b(today|yesterday)\b)", true)});
    // A hexadecimal word with a digit and a letter other than e (1.046400526e-05 is a number).
    p.push_back({"commit hash", Pattern(R"(\b(?=[0-9a-f]*[a-df])(?=[0-9a-f]*[0-9])[0-9a-f]{7,40}\b)")});
    p.push_back({"machine", Pattern(R"(\b(Xeon|EPYC|Epyc|Intel|AMD|Ryzen|Graviton|vCPUs?|microVM)\b)")});
    p.push_back({"machine", Pattern(R"(\b(this|the project|an idle|the idle|a shared|the shared|today's) machine\b)", true)});
    p.push_back({"machine", Pattern(R"(\b(load average|freshly booted)\b)", true)});
    return p;
}

const std::vector<NamedPattern>& history_patterns() {
    static const std::vector<NamedPattern> p = history_list();
    return p;
}

// The names are split by a character class so that this file does not match itself.
std::vector<NamedPattern> outside_list() {
    std::vector<NamedPattern> p;
    p.push_back({"outside the repository", Pattern(R"(\.\.[/]shared|/work[/]|\bshared[/](paper|research)\b)")});
    p.push_back({"outside the repository",
                 Pattern(R"(\b(NOTES|model|semi_implicit|aesthetics|performance|anchors|solution_verification)[.]md\b)")});
    p.push_back({"outside the repository", Pattern(R"(\bresearch[/]|\bresearch notes\b|\bpaper notes of the team\b)")});
    return p;
}

const std::vector<NamedPattern>& outside_patterns() {
    static const std::vector<NamedPattern> p = outside_list();
    return p;
}

std::vector<Finding> scan(const std::string& text, const std::vector<NamedPattern>& patterns) {
    std::vector<Finding> found;
    std::istringstream in(text);
    int number = 0;
    for (std::string line; std::getline(in, line);) {
        ++number;
        for (const NamedPattern& p : patterns) {
            if (const auto m = p.re.first_in(line)) {
                found.push_back({number, p.what, (*m)[0]});
                break;
            }
        }
    }
    return found;
}

/// GitHub's anchor of a heading: lower case, punctuation dropped, blanks to hyphens.
std::string anchor_of(const std::string& heading) {
    std::string out;
    for (std::size_t i = 0; i < heading.size(); ++i) {
        const unsigned char c = heading[i];
        if (c == 0xE2 && i + 2 < heading.size() && static_cast<unsigned char>(heading[i + 1]) == 0x80) {
            i += 2;  // en and em dashes, typographic quotes: punctuation
            continue;
        }
        if (c >= 0x80 || std::isalnum(c) || c == '_' || c == '-')
            out += static_cast<char>(std::tolower(c));
        else if (c == ' ')
            out += '-';
    }
    return out;
}

std::set<std::string> anchors_of(const std::string& page) {
    std::set<std::string> anchors;
    std::istringstream in(page);
    bool fenced = false;
    for (std::string line; std::getline(in, line);) {
        if (line.rfind("```", 0) == 0) fenced = !fenced;
        if (fenced || line.empty() || line[0] != '#') continue;
        const auto start = line.find_first_not_of('#');
        if (start == std::string::npos || line[start] != ' ') continue;
        anchors.insert(anchor_of(line.substr(start + 1)));
    }
    return anchors;
}

}  // namespace

std::vector<Finding> history_findings(const std::string& text) { return scan(text, history_patterns()); }

std::vector<Finding> outside_references(const std::string& text) { return scan(text, outside_patterns()); }

std::vector<Finding> broken_links(const std::string& text, const fs::path& page_dir, const fs::path& root) {
    static const Pattern link(R"(\]\(([^)\s]*)\))");
    std::vector<Finding> found;
    std::istringstream in(text);
    int number = 0;
    bool fenced = false;
    for (std::string line; std::getline(in, line);) {
        ++number;
        if (line.rfind("```", 0) == 0) fenced = !fenced;
        if (fenced) continue;
        for (const PatternMatch& m : link.all_in(line)) {
            const std::string target = m[1];
            if (target.rfind("http://", 0) == 0 || target.rfind("https://", 0) == 0 || target.rfind("mailto:", 0) == 0) continue;
            const auto hash = target.find('#');
            const std::string file = target.substr(0, hash), anchor = hash == std::string::npos ? "" : target.substr(hash + 1);
            const fs::path resolved = file.empty() ? fs::path() : fs::weakly_canonical(page_dir / file);
            const std::string rel = file.empty() ? "" : resolved.lexically_relative(root).generic_string();
            std::string problem;
            if (!file.empty() && (rel.empty() || rel.rfind("..", 0) == 0))
                problem = "outside the repository";
            else if (!file.empty() && rel.rfind("build/", 0) == 0)
                problem = "into build/, which a fresh clone does not have";
            else if (!file.empty() && !fs::exists(resolved))
                problem = "no such file";
            else if (!anchor.empty()) {
                const std::string page = file.empty() ? text : read_text(resolved);
                if (!anchors_of(page).count(anchor)) problem = "no heading with this anchor";
            }
            if (!problem.empty()) found.push_back({number, "broken link", target + " (" + problem + ")"});
        }
    }
    return found;
}

}  // namespace granseg::verify::docs
