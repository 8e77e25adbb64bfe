// Where a generated table came from (docs/checked_pages.md, "Where a table came from"): every
// table a program writes for the pages (NAME.md, copied into docs/generated/) ends with a record
//
//   <!-- provenance
//   program: bench_time_step
//   command: build/bench/bench_time_step --data build/bench-data --grids 50:2e-3,1e-3
//   commit: 1a2b3c4d5e6f (uncommitted changes)
//   physics: flow=0123456789abcdef drum=... segregation=... closures=... study=...
//   -->
//
// the program and its command line, the commit of the tree it was built from, and the
// fingerprints (physics_fingerprint.hpp) of the parts of the code its numbers depend on. The
// record is an HTML comment after the table: the pages show the table without it, and verify_docs
// compares its fingerprints with the build's own (doc_provenance.hpp). A fingerprint `unknown`
// (a table made before tables recorded their physics) matches no build.
#pragma once

#include "harness/physics_fingerprint.hpp"

#include <optional>
#include <string>
#include <vector>

namespace granseg::verify {

/// The parts a drum table's numbers depend on, and those of a study's tables (their uncertainty
/// procedure besides).
extern const std::vector<std::string> kDrumParts, kDrumStudyParts;

/// What a record says.
struct Provenance {
    std::string program, command, commit;
    Fingerprints physics;  // part -> fingerprint or "unknown"
};

/// Fingerprints as one line "closures=... drum=... ..." (the record's physics line).
std::string physics_line(const Fingerprints& physics);

/// The record's text (the comment block of the header, ending in a newline).
std::string provenance_record(const Provenance& p);

/// The record at the end of a table's text, if it has one.
std::optional<Provenance> parse_provenance(const std::string& table_text);

/// The table as the pages show it: its text without the record.
std::string shown_part(const std::string& table_text);

/// What differs between a record's physics and the build's, one line per part: "the flow step
/// (recorded 0123..., this build 4567...)"; "not recorded" for `unknown`. Empty: the table is
/// made by this build's physics.
std::vector<std::string> physics_changes(const Fingerprints& recorded, const Fingerprints& now);

/// Remembers this program's command line and the tree's commit for the tables it writes (the
/// programs' option parsers call it).
void remember_command_line(int argc, char** argv);

/// The commit of the repository at `root` ("abbreviated hash", with "(uncommitted changes)" if
/// tracked files differ from it), or "unknown" without git.
std::string commit_of(const std::filesystem::path& root);

/// The top of the repository a program runs in: the first folder above its binary (or, failing
/// that, the working directory) that holds verification/scenes/physics_flow.toml.
std::filesystem::path repository_root(const std::string& argv0);

/// This build's fingerprints of every part (computed once per program, by the canonical runs of
/// the repository the program runs in), as physics_line writes them.
std::string this_build_physics_line();

/// Writes a generated table to `path`: `markdown`, then the record of this program (its command
/// line as remembered), the commit and this build's fingerprints of `parts` (computed once per
/// program, by the canonical runs).
void write_generated_table(const std::string& path, const std::string& markdown, const std::vector<std::string>& parts);

}  // namespace granseg::verify
