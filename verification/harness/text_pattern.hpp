// Regular expressions for the checks of pages and messages (verify_docs, the unit tests).
//
//   provides    Pattern: an ECMAScript regular expression (std::regex) with the few questions the
//               checks ask of a text; PatternMatch: one match's groups and surroundings
//   why         std::regex is a header-only template library whose matching code costs seconds
//               of compile time in every file that instantiates it; behind this interface it is
//               compiled once (text_pattern.cpp)
//   speed       std::regex matches slowly (verify_docs asks some 60 expressions of each of 4,000
//               lines), so a Pattern first looks for the literal text every match must contain
//               (required_literals): a text without it is answered "no match" without the regex
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace granseg::verify {

/// One match: its groups (0: the whole match; a group that took no part is empty and not
/// took_part) and the text before and after it.
struct PatternMatch {
    std::vector<std::string> groups;
    std::vector<bool> took_part;
    std::string prefix, suffix;
    const std::string& operator[](std::size_t g) const { return groups[g]; }
};

/// Texts of which every match of the ECMAScript expression contains at least one: the longest
/// run of literal characters that each top-level alternative must match (outside groups, classes
/// and optional or repeated characters). Empty when some alternative has no such run: then no
/// text can be ruled out. Lower case if ignore_case.
std::vector<std::string> required_literals(const std::string& expression, bool ignore_case);

/// An ECMAScript regular expression, optionally ignoring case.
class Pattern {
public:
    explicit Pattern(const std::string& expression, bool ignore_case = false);
    ~Pattern();
    Pattern(Pattern&&) noexcept;
    Pattern& operator=(Pattern&&) noexcept;

    /// A match anywhere in text.
    bool found_in(const std::string& text) const;
    /// The whole text matches.
    bool matches(const std::string& text) const;
    /// The first match in text, if any.
    std::optional<PatternMatch> first_in(const std::string& text) const;
    /// The match of the whole text, if it matches.
    std::optional<PatternMatch> match_of(const std::string& text) const;
    /// Every match in text, in order.
    std::vector<PatternMatch> all_in(const std::string& text) const;
    /// text with every match removed.
    std::string removed_from(const std::string& text) const;

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace granseg::verify
