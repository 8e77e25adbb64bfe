// Code on the page (verify_docs; docs/checked_pages.md, "Code excerpts"): a page shows a few lines
// of the code under a marker that names the file and the symbol they come from,
//
//   <!-- excerpt: src/riemann/segregation_flux.cpp modified_godunov_flux -->
//   ```cpp
//   double modified_godunov_flux(const InterfaceStates& q) {
//       ...
//   }
//   ```
//
// and the block must be the symbol's definition with lines left out only where a line `...` (any
// indentation, optionally followed by a comment) stands for them: every other line equals a line of
// the definition, in order, and two shown lines that are not neighbours in the code have a `...`
// between them (so do a first shown line that is not the definition's first, and a last that is
// not its last). So an excerpt cannot drift from the code, and cannot hide that it leaves lines out.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace granseg::verify::docs {

/// One excerpt of a page: the marker's file and symbol, and the fenced block after it.
struct Excerpt {
    std::string file, symbol;
    std::vector<std::string> lines;
    int marker_line = 0;             // line number of the marker
    std::size_t begin = 0, end = 0;  // the block's lines (fences excluded) as offsets into the page
};

/// The excerpts of a page; `error` names a marker that is malformed or not followed by a fence.
std::vector<Excerpt> excerpts_of(const std::string& page, std::string& error);

/// The lines of the definition of `symbol` in a source text: from the first line that defines it
/// (a function, `Class::method`, a struct, class, enum, or a constant or array with an initialiser; a
/// declaration ending in `;` is skipped) to the line that closes its braces. Empty if none.
std::vector<std::string> definition_of(const std::string& source, const std::string& symbol);

/// Why the shown lines are not an excerpt of the definition (nullopt when they are): a line not in
/// the definition after the previous one, or lines left out where no `...` says so.
std::optional<std::string> excerpt_problem(const std::vector<std::string>& shown, const std::vector<std::string>& definition);

/// The result of checking one excerpt against the tree under `root`.
struct ExcerptCheck {
    std::optional<std::string> problem;  // nullopt: the block is an excerpt of the definition
    std::vector<std::string> definition;
};
ExcerptCheck check_excerpt(const Excerpt& e, const std::filesystem::path& root);

/// Self-check: of the excerpt's shown lines whose removal leaves a gap with no `...`, or whose text
/// changed by one character, how many variants the check still accepts (must be 0).
long excerpt_mutants_accepted(const std::vector<std::string>& shown, const std::vector<std::string>& definition);

/// The page with every excerpt that no longer matches its code replaced by the whole definition
/// (make docs-refresh); `rewritten` counts them, and the author trims them again with `...` lines.
std::string with_fresh_excerpts(const std::string& page, const std::filesystem::path& root, int& rewritten);

}  // namespace granseg::verify::docs
