// Scene files: TOML (toml++) read through a validating reader.
//
// A scene is a TOML file of top-level sections ([scene], [grid], [material], ...) holding scalar
// keys. Scene code asks for every key it understands, each with its type and allowed range;
// finish() then rejects any section or key nobody asked for. Every problem becomes one
// InputError line of the form
//
//     FILE: [section] key: what is wrong (allowed: ...)
//
// so a typo, a string where a number belongs or an out-of-range value stops the run before any
// output is written. The keys of each scene kind are documented in docs/scenes.md.
#pragma once

#include "run/expression.hpp"

#include <limits>
#include <memory>
#include <string>
#include <vector>

namespace granseg {

/// An allowed interval for a number, printed in error messages (e.g. "0 < length").
struct Range {
    double lo = -std::numeric_limits<double>::infinity();
    double hi = std::numeric_limits<double>::infinity();
    bool lo_open = false;
    bool hi_open = false;

    static Range any() { return {}; }
    static Range closed(double a, double b) { return {a, b, false, false}; }     // [a, b]
    static Range open(double a, double b) { return {a, b, true, true}; }         // (a, b)
    static Range left_open(double a, double b) { return {a, b, true, false}; }   // (a, b]
    static Range right_open(double a, double b) { return {a, b, false, true}; }  // [a, b)
    static Range at_least(double a) { return {a, std::numeric_limits<double>::infinity(), false, false}; }
    static Range above(double a) { return {a, std::numeric_limits<double>::infinity(), true, false}; }

    /// True for a finite v inside the interval (NaN and infinities are never inside).
    bool contains(double v) const;
    /// Human-readable form using `name` for the value, e.g. "0 < Phi < 1".
    std::string describe(const std::string& name) const;
};

class SceneFile {
public:
    /// Reads and parses a TOML file; InputError for an unreadable file or a TOML syntax error.
    static SceneFile load(const std::string& path);
    /// Parses TOML text; `name` stands for the file name in messages.
    static SceneFile parse(const std::string& text, const std::string& name);

    SceneFile(SceneFile&&) noexcept;
    SceneFile& operator=(SceneFile&&) noexcept;
    ~SceneFile();

    const std::string& name() const { return name_; }

    /// A required number inside `range` (TOML integers are accepted).
    double number(const std::string& section, const std::string& key, const Range& range) const;
    /// An optional number; `fallback` when the key is absent.
    double number(const std::string& section, const std::string& key, const Range& range, double fallback) const;
    /// A required integer in [lo, hi].
    long integer(const std::string& section, const std::string& key, long lo, long hi) const;
    long integer(const std::string& section, const std::string& key, long lo, long hi, long fallback) const;
    /// An optional boolean.
    bool flag(const std::string& section, const std::string& key, bool fallback) const;
    /// A required string that must be one of `allowed`.
    std::string choice(const std::string& section, const std::string& key, const std::vector<std::string>& allowed) const;
    std::string choice(const std::string& section, const std::string& key, const std::vector<std::string>& allowed,
                       const std::string& fallback) const;
    /// An optional free-form string (a path, a label).
    std::string text(const std::string& section, const std::string& key, const std::string& fallback) const;
    /// A required array of numbers, each inside `range`, with at least one element.
    std::vector<double> numbers(const std::string& section, const std::string& key, const Range& range) const;
    std::vector<double> numbers(const std::string& section, const std::string& key, const Range& range,
                                const std::vector<double>& fallback) const;
    /// A required muparser expression in `variables` (a plain number is accepted too).
    Expression expression(const std::string& section, const std::string& key, const std::vector<std::string>& variables) const;
    Expression expression(const std::string& section, const std::string& key, const std::vector<std::string>& variables,
                          const std::string& fallback) const;

    /// True if the file has this key (does not count as asking for it).
    bool has(const std::string& section, const std::string& key) const;

    /// Rejects the first (in file order) section or key that no accessor asked for.
    void finish() const;

    /// Every key asked for so far with the value it resolved to (its default where the file has
    /// none), one line "[section] key = value" each, sorted; the keys in `ignored` (written
    /// "[section] key") left out. Two scene files with the same settings describe the same run
    /// (checkpoints compare them, run/checkpoint_file.hpp).
    std::string settings(const std::vector<std::string>& ignored = {}) const;

    /// Throws the one-line InputError "NAME: [section] key: what (allowed: allowed)".
    [[noreturn]] void fail(const std::string& section, const std::string& key, const std::string& what,
                           const std::string& allowed) const;

private:
    struct Impl;
    /// Records the value `key` resolved to (settings()) and returns it.
    double note(const std::string& section, const std::string& key, double v) const;
    long note(const std::string& section, const std::string& key, long v) const;
    bool note(const std::string& section, const std::string& key, bool v) const;
    std::string note(const std::string& section, const std::string& key, const std::string& v) const;
    std::vector<double> note(const std::string& section, const std::string& key, const std::vector<double>& v) const;

    SceneFile(std::unique_ptr<Impl> impl, std::string name);

    std::unique_ptr<Impl> impl_;  // the parsed TOML and the keys asked for so far
    std::string name_;
};

/// The first line of settings `a` (SceneFile::settings) that `b` lacks, "" if none: how two runs'
/// settings differ, for messages.
std::string first_setting_missing(const std::string& a, const std::string& b);

}  // namespace granseg
