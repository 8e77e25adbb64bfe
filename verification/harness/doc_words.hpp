// Numbers a page writes in words (verify_docs; docs/checked_pages.md, "Numbers in prose"): a
// ratio, share or count of a result reads better as "twice", "a third" or "two hundredths" than as
// 2.1, 0.34 or 0.018, and is checked like a number when it stands in a value span:
//
//   <!-- value: docs/generated/t.md "a" | b / docs/generated/t.md "c" | b -->twice<!-- /value -->
//
// A word stands for the values that round to it: a whole number (one ... nineteen, then twenty ...
// ninety in tens; "twice", "N times") for +- half its unit (1, or 10 for the tens); a simple fraction p/q
// (a half, a third, two thirds, a quarter, three quarters, a fifth, two to four fifths,
// a tenth) for +- 1/(2 q^2),
// which keeps neighbouring fractions apart; "N hundredths" for +- half a hundredth. `make
// docs-refresh` rewrites the span in the same kind of words ("three times", "a quarter"), or in
// digits where no word of that kind is near.
#pragma once

#include <optional>
#include <string>

namespace granseg::verify::docs {

/// A number in words: its value, and the width `unit` of the values it stands for (the span
/// check's "one unit of the last digit": it shows v when |v - value| <= unit/2).
struct WordNumber {
    double value = 0, unit = 1;
};

/// The number `text` says in words ("twice", "three times", "a third", "two hundredths",
/// "seven"), or nothing.
std::optional<WordNumber> word_number(const std::string& text);

/// `value` in words of the kind `like` uses (a multiple, a fraction, hundredths or a count), or
/// nothing if `like` is not a number in words.
std::optional<std::string> in_words_like(double value, const std::string& like);

}  // namespace granseg::verify::docs
