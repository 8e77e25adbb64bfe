// `make docs-refresh` (verify_docs --refresh; docs/checked_pages.md): after a program's numbers
// change, every fresh generated table goes into docs/generated/ and into the pages' blocks that
// show it, then every value span whose source can be read is rewritten from it.
#pragma once

#include "harness/physics_fingerprint.hpp"

#include <filesystem>
#include <string>
#include <vector>

namespace granseg::verify::docs {

/// The fresh output build/data/NAME, build/bench-data/NAME or build/runs/NAME (make fig7) of the
/// program that writes table NAME, if it has run in the build tree `build`; else an empty path.
std::filesystem::path fresh_table(const std::filesystem::path& build, const std::string& name);

/// Whether a fresh table is compared with its committed copy: all but a run's cost (NAME_cost.md),
/// which is the machine's that ran it; `make docs-refresh` copies those too.
bool compared(const std::string& name);

/// Refreshes the generated tables, then the value spans, of `pages` (paths from `root`); prints
/// what it changed, and for each table copied whether this build's physics (`now`) made it, and
/// returns 0. A table keeps the provenance record its program wrote: copying a table made by
/// other physics leaves it stale (doc_provenance.hpp).
int refresh_pages(const std::filesystem::path& root, const std::filesystem::path& build, const std::vector<std::string>& pages,
                  const Fingerprints& now);

}  // namespace granseg::verify::docs
