// Fingerprints of numbers: a short hash that tells two data files apart when their numbers
// differ at the digits that matter, and not when they differ only below them.
//
//   hashes      FNV-1a (64 bit, 16 hexadecimal digits) of the data lines' numbers, each rounded to
//               a number of significant digits and set to 0 below 1e-9 of its column's largest
//               magnitude; comment lines ("#") are skipped, blank lines (gnuplot's block
//               separators) kept
//   why         a reference figure (doc_figures.hpp) cannot show a change below its 4 digits, and a
//               generated table's physics (physics_fingerprint.hpp) is told by 9; round-off that
//               differs between machines, or timings in comment lines, must not change either
//   columns     a data file whose first line is "# name name ..." may leave columns out by name
//               (a run's wall-clock seconds in its summary)
#pragma once

#include <cstdint>
#include <functional>
#include <string>

namespace granseg::verify {

/// FNV-1a, 64 bit, over pieces of text (each followed by a separator, so that "ab" "c" differs
/// from "a" "bc").
class Fnv1a {
public:
    void add(const std::string& s);
    /// The hash as 16 hexadecimal digits.
    std::string hex() const;

private:
    std::uint64_t hash_ = 0xcbf29ce484222325ULL;
};

/// The fingerprint of a data file's numbers at `digits` significant digits; a column whose name
/// (from the first line "# name ...") `counts` rejects is left out.
std::string numbers_fingerprint(const std::string& text, int digits,
                                const std::function<bool(const std::string& column)>& counts = {});

}  // namespace granseg::verify
