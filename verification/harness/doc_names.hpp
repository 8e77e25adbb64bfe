// Names a page shows in backticks must exist (verify_docs; docs/checked_pages.md): a file, a
// function, a type, a scene key, a command-line option or a make target that a page names but
// that is nowhere in the tree (src/, verification/, tests/, figures/, the Makefile, mk/) has been
// renamed or removed, or never existed, and the page teaches something the code does not have.
//
// What counts as a name, span by span (the text between two backticks, outside fenced blocks):
//   make T ...            each T must be a target of the Makefile;
//   [section] key ...     section and key must occur in the tree (scene keys are strings there);
//   --option ...          the option (without its dashes) must occur in the tree;
//   a path (has a / or a file extension; {a,b} alternatives expanded): the file exists (from the
//                         top or from the page's folder), or a file of that name exists anywhere
//                         in the tree, or its stem occurs there (files programs write);
//   A::b(), name_1, CamelCase: every ::-separated part must be a word of the tree, or a prefix
//                         that occurs as a string "prefix_" plus a word (generated column names);
//   "value", hyphen-ated: must occur in the tree's text.
// Anything else (formulas, phrases, numbers) is not a name. Placeholders in capitals (NAME, NNN)
// and * patterns are not checked, nor the exercises of a "**Your turn.**" paragraph, which name
// what the reader is to create.
#pragma once

#include "harness/doc_hygiene.hpp"

#include <filesystem>
#include <set>
#include <string>

namespace granseg::verify::docs {

/// What the tree holds, read once.
struct TreeNames {
    std::filesystem::path root;
    std::string text;                             // every file of the tree, concatenated
    std::set<std::string> words, targets, files;  // identifiers; Makefile targets; file names
};

/// Reads src/, verification/, tests/, figures/, the Makefile and mk/*.mk under `root`.
TreeNames tree_names(const std::filesystem::path& root);

/// The backticked names of `text` (a page at `page`, relative to tree.root) that exist nowhere
/// in the tree (see the header comment); one Finding ("unknown name") per name.
std::vector<Finding> unknown_names(const std::string& text, const std::string& page, const TreeNames& tree);

}  // namespace granseg::verify::docs
