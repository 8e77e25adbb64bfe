// What a teaching page must not hold (verify_docs; docs/checked_pages.md): history (a date, a
// commit hash, a machine name), references to files outside the repository (the team's notes,
// which a user's clone does not have), and links that do not lead to a file of the repository.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace granseg::verify::docs {

/// One offending line of a text.
struct Finding {
    int line = 0;
    std::string what;  // "date", "commit hash", "machine", "outside the repository", "broken link"
    std::string text;  // the offending part of the line
};

/// Lines holding a date (2 December 2026, December 2026, 2026-12-02, "today"), a commit hash (7
/// to 40 hexadecimal digits with at least one digit and a letter other than e) or a machine name
/// (Xeon, EPYC, vCPU, "this machine", "load average", ...). Years alone (citations) are not dates.
std::vector<Finding> history_findings(const std::string& text);

/// References to files outside the repository: the team's notes on the paper and the model by
/// name, or paths into a directory beside the repository.
std::vector<Finding> outside_references(const std::string& text);

/// Markdown links and images of a page in `page_dir` that are not web addresses and do not
/// resolve to an existing file of the repository at `root`, or point into build/ (which a fresh
/// clone does not have), or name an anchor (#heading) the target page does not have.
std::vector<Finding> broken_links(const std::string& text, const std::filesystem::path& page_dir,
                                  const std::filesystem::path& root);

}  // namespace granseg::verify::docs
