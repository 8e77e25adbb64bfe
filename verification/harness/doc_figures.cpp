#include "harness/doc_figures.hpp"

#include "harness/doc_blocks.hpp"
#include "harness/text_pattern.hpp"
#include "run/output.hpp"

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <sstream>

namespace fs = std::filesystem;

namespace granseg::verify::docs {

namespace {

// A figure of 800 pixels cannot show a relative change below 1e-4: numbers are compared to 4
// significant digits, and values below 1e-9 of their column's largest magnitude count as 0
// (round-off at that level may differ between machines and compilers).
constexpr int kDigits = 4;
constexpr double kColumnFloor = 1e-9;

class Fnv1a {
public:
    void add(const std::string& s) {
        for (unsigned char c : s) hash_ = (hash_ ^ c) * 0x100000001b3ULL;
        hash_ = (hash_ ^ 0xff) * 0x100000001b3ULL;  // separator: "ab" "c" differs from "a" "bc"
    }
    std::string hex() const {
        char buf[17];
        std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(hash_));
        return buf;
    }

private:
    std::uint64_t hash_ = 0xcbf29ce484222325ULL;
};

bool parse_number(const std::string& token, double& x) {
    char* end = nullptr;
    x = std::strtod(token.c_str(), &end);
    return end != token.c_str() && *end == '\0';
}

/// The data lines of a file as tokens (comment lines dropped; a blank line is kept as a block
/// separator, which gnuplot reads).
std::vector<std::vector<std::string>> data_rows(const std::string& text) {
    std::vector<std::vector<std::string>> rows;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);) {
        const auto first = line.find_first_not_of(" \t\r");
        if (first != std::string::npos && line[first] == '#') continue;
        std::istringstream words(line);
        std::vector<std::string> row;
        for (std::string w; words >> w;) row.push_back(w);
        rows.push_back(row);
    }
    return rows;
}

/// The files a script loads (`load 'figures/x.gnuplot'`), relative to the repository's top.
std::vector<std::string> loaded_scripts(const std::string& script) {
    static const Pattern load(R"(^\s*load\s+['"]([^'"]+)['"])");
    std::vector<std::string> files;
    std::istringstream in(script);
    for (std::string line; std::getline(in, line);)
        if (const auto m = load.first_in(line)) files.push_back((*m)[1]);
    return files;
}

/// The data files of the script's `# reads:` line.
std::vector<std::string> read_files(const std::string& script, bool& has_line) {
    std::vector<std::string> files;
    has_line = false;
    std::istringstream in(script);
    for (std::string line; std::getline(in, line);) {
        if (line.rfind("# reads:", 0) != 0) continue;
        has_line = true;
        std::istringstream words(line.substr(8));
        for (std::string w; words >> w;) files.push_back(w);
    }
    return files;
}

}  // namespace

std::vector<std::string> figure_reads(const fs::path& root, const std::string& name) {
    bool has_reads = false;
    return read_files(read_text(root / "figures" / (name + ".gp")), has_reads);
}

namespace {

bool needs_matching(const fs::path& root, const std::string& name, const Pattern& needs) {
    std::istringstream in(read_text(root / "figures" / (name + ".gp")));
    for (std::string line; std::getline(in, line);)
        if (needs.found_in(line)) return true;
    return false;
}

}  // namespace

bool plots_benchmark(const fs::path& root, const std::string& name) {
    static const Pattern needs(R"(^# needs:.*\bbench_)");
    return needs_matching(root, name, needs);
}

bool plots_run(const fs::path& root, const std::string& name) {
    static const Pattern needs(R"(^# needs:.*\brun_)");
    return needs_matching(root, name, needs);
}

std::string data_fingerprint(const std::string& text) {
    const auto rows = data_rows(text);
    std::vector<double> largest;
    for (const auto& row : rows)
        for (std::size_t j = 0; j < row.size(); ++j) {
            double x;
            if (j >= largest.size()) largest.resize(j + 1, 0.0);
            if (parse_number(row[j], x) && std::isfinite(x)) largest[j] = std::max(largest[j], std::fabs(x));
        }
    Fnv1a h;
    for (const auto& row : rows) {
        std::string line;
        for (std::size_t j = 0; j < row.size(); ++j) {
            double x;
            if (!parse_number(row[j], x) || !std::isfinite(x)) {
                line += row[j] + " ";
                continue;
            }
            if (std::fabs(x) < kColumnFloor * largest[j]) x = 0.0;
            char buf[40];
            std::snprintf(buf, sizeof buf, "%.*g ", kDigits, x == 0.0 ? 0.0 : x);  // -0 prints as 0
            line += buf;
        }
        h.add(line);
    }
    return h.hex();
}

std::string figure_fingerprint(const fs::path& root, const std::string& name, const fs::path& data_dir, std::string& error) {
    bool found = false;
    const std::string script = read_text(root / "figures" / (name + ".gp"), &found);
    if (!found) {
        error = "no script figures/" + name + ".gp";
        return "";
    }
    bool has_reads = false;
    const std::vector<std::string> data = read_files(script, has_reads);
    if (!has_reads || data.empty()) {
        error = "figures/" + name + ".gp has no line '# reads: FILE ...'";
        return "";
    }
    Fnv1a h;
    h.add(script);
    for (const std::string& loaded : loaded_scripts(script)) {
        const std::string text = read_text(root / loaded, &found);
        if (!found) {
            error = "figures/" + name + ".gp loads " + loaded + ", which does not exist";
            return "";
        }
        h.add(text);
    }
    for (const std::string& file : data) {
        const std::string text = read_text(data_dir / file, &found);
        if (!found) {
            error = "no data file " + (data_dir / file).string() + " (run make verify first)";
            return "";
        }
        h.add(file);
        h.add(data_fingerprint(text));
    }
    return h.hex();
}

std::map<std::string, std::string> read_fingerprints(const fs::path& file) {
    std::map<std::string, std::string> out;
    std::istringstream in(read_text(file));
    for (std::string name, fingerprint; in >> name >> fingerprint;) out[name] = fingerprint;
    return out;
}

void write_fingerprints(const fs::path& file, const std::map<std::string, std::string>& fingerprints) {
    std::string text;
    for (const auto& [name, fingerprint] : fingerprints) text += name + " " + fingerprint + "\n";
    write_file_atomically(file.string(), text);
}

}  // namespace granseg::verify::docs
