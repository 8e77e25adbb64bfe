#include "harness/doc_figures.hpp"

#include "harness/doc_blocks.hpp"
#include "harness/number_fingerprint.hpp"
#include "harness/text_pattern.hpp"
#include "run/output.hpp"

#include <iostream>
#include <sstream>

namespace fs = std::filesystem;

namespace granseg::verify::docs {

namespace {

// A figure of 800 pixels cannot show a relative change below 1e-4: numbers are compared to 4
// significant digits (harness/number_fingerprint.hpp).
constexpr int kDigits = 4;

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

std::string data_fingerprint(const std::string& text) { return numbers_fingerprint(text, kDigits); }

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

namespace {

// A reference figure is a small image for reading on a fresh clone, not a print master.
constexpr long kLargestFigureBytes = 200 * 1024;

/// Changes the first digit of a data file's first data line (comment lines start with #).
void change_first_data_digit(std::string& data) {
    std::size_t line = 0;
    while (line < data.size() && data[line] == '#') {
        const auto end = data.find('\n', line);
        line = end == std::string::npos ? data.size() : end + 1;
    }
    const auto at = data.find_first_of("0123456789", line);
    if (at != std::string::npos) data[at] = data[at] == '9' ? '0' : static_cast<char>(data[at] + 1);
}

/// Where figure `name` reads its data: the build's bench-data directory for a benchmark's
/// figure, its runs directory for a scene run by make (make fig7), else `data_dir`.
fs::path figure_data_dir(const fs::path& root, const fs::path& build, const std::string& name, const fs::path& data_dir) {
    if (plots_benchmark(root, name)) return build / "bench-data";
    return plots_run(root, name) ? build / "runs" : data_dir;
}

}  // namespace

/// Reference figures: recorded, small, and drawn from the data as it is now (a benchmark's or a
/// make run's figure only where it has run).
void check_figures(CheckTable& t, const fs::path& root, const fs::path& build, const fs::path& data_dir,
                   long& mutants_unchanged) {
    const fs::path dir = root / "docs" / "figures";
    const auto recorded = read_fingerprints(dir / "fingerprints.txt");
    long images = 0;
    for (const auto& e : fs::directory_iterator(dir)) {
        if (e.path().extension() != ".png") continue;
        ++images;
        const std::string name = e.path().stem().string();
        t.at_most("docs/figures/" + name + ".png: bytes", static_cast<double>(fs::file_size(e.path())), kLargestFigureBytes);
        t.count("docs/figures/" + name + ".png: recorded in fingerprints.txt", recorded.count(name) ? 1 : 0, 1);
    }
    for (const auto& [name, fingerprint] : recorded) {
        const fs::path from = figure_data_dir(root, build, name, data_dir);
        if ((plots_benchmark(root, name) || plots_run(root, name)) && !fs::exists(from / figure_reads(root, name).front())) {
            t.note("  " + name + ": its benchmark or run has not run in this build; the image is not compared with data");
            t.count("docs/figures/" + name + ".png exists", fs::exists(dir / (name + ".png")) ? 1 : 0, 1);
            continue;
        }
        std::string error;
        const std::string now = figure_fingerprint(root, name, from, error);
        if (!error.empty()) t.note("  " + name + ": " + error);
        t.count("docs/figures/" + name + ".png: drawn from the current data (else make docs-figures)",
                !now.empty() && now == fingerprint ? 0 : 1, 0);
        t.count("docs/figures/" + name + ".png exists", fs::exists(dir / (name + ".png")) ? 1 : 0, 1);
        if (now.empty()) continue;
        std::string data = read_text(from / figure_reads(root, name).front());
        const std::string before = data_fingerprint(data);
        change_first_data_digit(data);
        mutants_unchanged += data_fingerprint(data) == before;
    }
    t.at_least("reference figures in docs/figures", images, 1);
}

/// --fingerprint NAME...: records the fingerprints of reference figures just drawn.
int record_fingerprints(const fs::path& root, const fs::path& build, const std::vector<std::string>& names,
                        const fs::path& data_dir) {
    const fs::path file = root / "docs" / "figures" / "fingerprints.txt";
    auto recorded = read_fingerprints(file);
    for (const std::string& name : names) {
        std::string error;
        recorded[name] = figure_fingerprint(root, name, figure_data_dir(root, build, name, data_dir), error);
        if (!error.empty()) {
            std::cerr << "docs-figures: " << name << ": " << error << '\n';
            return 2;
        }
    }
    write_fingerprints(file, recorded);
    return 0;
}

}  // namespace granseg::verify::docs
