// The reference figures the pages show on a fresh clone (docs/figures/NAME.png, rendered by
// `make docs-figures` from figures/NAME.gp): each is recorded in docs/figures/fingerprints.txt
// with a fingerprint of what it was drawn from, so that verify_docs can tell a stale image
// without comparing pixels.
//
// What a figure was drawn from: its script, the scripts it loads (`load '...'`), and the data
// files its line `# reads: FILE ...` names (relative to the data directory). The fingerprint is
// FNV-1a (64 bit) over the scripts' text and the data files' numbers, each rounded to 4
// significant digits and set to 0 below 1e-9 of its column's largest magnitude, comment lines
// skipped: a picture cannot show smaller changes, and round-off that differs between machines
// (or timings in comment lines) does not make an image stale.
#pragma once

#include "harness/check_table.hpp"

#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace granseg::verify::docs {

/// The fingerprint of figure `name` (16 hexadecimal digits), or "" with `error` set when its
/// script, its `# reads:` line or a data file is missing.
std::string figure_fingerprint(const std::filesystem::path& root, const std::string& name, const std::filesystem::path& data_dir,
                               std::string& error);

/// The data files figure `name` reads (its `# reads:` line; empty if none).
std::vector<std::string> figure_reads(const std::filesystem::path& root, const std::string& name);

/// Whether figure `name` plots a benchmark's data (its `# needs:` line names a bench_*): its
/// files are then in the build's bench-data directory, and exist only once the benchmark ran.
bool plots_benchmark(const std::filesystem::path& root, const std::string& name);

/// True if figures/NAME.gp plots a scene run by make (a line '# needs: run_SCENE'): its data lies
/// under the build's runs directory.
bool plots_run(const std::filesystem::path& root, const std::string& name);

/// The fingerprint of a data file's text alone (the data part of figure_fingerprint).
std::string data_fingerprint(const std::string& text);

/// The recorded fingerprints (NAME -> fingerprint) of docs/figures/fingerprints.txt.
std::map<std::string, std::string> read_fingerprints(const std::filesystem::path& file);

/// Writes `fingerprints` as docs/figures/fingerprints.txt (one line "NAME FINGERPRINT" each).
void write_fingerprints(const std::filesystem::path& file, const std::map<std::string, std::string>& fingerprints);

/// The reference figures' checks (verify_docs): every docs/figures/NAME.png is small, recorded,
/// and drawn from the data it would be drawn from now, read from `data_dir` (a verification
/// program's), `build`/bench-data (a benchmark's, only where it has run) or `build`/runs (make
/// fig7's); `mutants_unchanged` counts recorded figures whose fingerprint misses a changed digit.
void check_figures(CheckTable& t, const std::filesystem::path& root, const std::filesystem::path& build,
                   const std::filesystem::path& data_dir, long& mutants_unchanged);

/// `make docs-figures` (verify_docs --fingerprint NAME...): records the fingerprints of figures
/// just drawn; 2 with a message on stderr if one cannot be computed.
int record_fingerprints(const std::filesystem::path& root, const std::filesystem::path& build,
                        const std::vector<std::string>& names, const std::filesystem::path& data_dir);

}  // namespace granseg::verify::docs
