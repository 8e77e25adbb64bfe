#include "harness/same_outputs.hpp"

#include "harness/doc_blocks.hpp"

#include <filesystem>
#include <set>
#include <sstream>

namespace granseg::verify {

namespace {

namespace fs = std::filesystem;

std::vector<std::string> lines_of(const std::string& text) {
    std::vector<std::string> lines;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);) lines.push_back(line);
    return lines;
}

std::vector<std::string> words_of(const std::string& line) {
    std::istringstream in(line);
    std::vector<std::string> words;
    for (std::string w; in >> w;) words.push_back(w);
    return words;
}

/// The output files below `dir`, as paths relative to it.
std::set<std::string> output_files(const fs::path& dir) {
    std::set<std::string> files;
    if (!fs::exists(dir)) return files;
    for (const auto& e : fs::recursive_directory_iterator(dir))
        if (e.is_regular_file() && e.path().filename() != "checkpoint.gsc") files.insert(fs::relative(e.path(), dir).string());
    return files;
}

/// "" if the two texts agree but for timing columns, else where they first differ.
std::string first_difference(const std::string& a, const std::string& b) {
    if (a == b) return "";
    const std::vector<std::string> la = lines_of(a), lb = lines_of(b);
    if (la.size() != lb.size()) return std::to_string(la.size()) + " lines against " + std::to_string(lb.size());
    const std::vector<std::string> columns =
        la.empty() || la[0].rfind("#", 0) != 0 ? std::vector<std::string>{} : words_of(la[0].substr(1));
    for (std::size_t i = 0; i < la.size(); ++i) {
        if (la[i] == lb[i]) continue;
        const std::vector<std::string> wa = words_of(la[i]), wb = words_of(lb[i]);
        bool timing_only = la[i][0] != '#' && wa.size() == columns.size() && wb.size() == columns.size();
        for (std::size_t k = 0; timing_only && k < wa.size(); ++k) timing_only = wa[k] == wb[k] || timing_column(columns[k]);
        if (!timing_only) return "line " + std::to_string(i + 1) + " differs";
    }
    return "";
}

}  // namespace

long files_below(const std::string& dir) {
    if (!fs::exists(dir)) return 0;
    long n = 0;
    for (const auto& e : fs::recursive_directory_iterator(dir)) n += e.is_regular_file();
    return n;
}

bool timing_column(const std::string& name) {
    return name == "wall_seconds" || name == "cpu_seconds" || name.rfind("seconds_", 0) == 0;
}

std::vector<std::string> differing_outputs(const std::string& a, const std::string& b, long* files) {
    const std::set<std::string> fa = output_files(a), fb = output_files(b);
    if (files) *files = static_cast<long>(fa.size());
    std::vector<std::string> out;
    for (const std::string& f : fa) {
        if (!fb.count(f)) {
            out.push_back(f + ": only in " + a);
            continue;
        }
        const std::string d = first_difference(docs::read_text(fs::path(a) / f), docs::read_text(fs::path(b) / f));
        if (!d.empty()) out.push_back(f + ": " + d);
    }
    for (const std::string& f : fb)
        if (!fa.count(f)) out.push_back(f + ": only in " + b);
    return out;
}

}  // namespace granseg::verify
