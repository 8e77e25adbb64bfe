// User expressions such as `Phi = "0.62 - 0.08*cos(_pi*z)^2"` in scene files, parsed by muparser.
//
// An Expression is compiled once with a fixed list of variable names and then evaluated with
// values given in that order. muparser syntax: + - * / ^, sin cos tan exp log sqrt abs min max
// sum avg, the ternary `a < b ? x : y`, constants _pi and _e.
#pragma once

#include <memory>
#include <string>
#include <vector>

namespace granseg {

class Expression {
public:
    /// Compiles `text` with the given variable names; throws InputError with a
    /// one-line reason for a syntax error or a variable outside `variables`.
    Expression(const std::string& text, const std::vector<std::string>& variables);
    Expression(const Expression& other);
    Expression& operator=(const Expression& other);
    Expression(Expression&&) noexcept;
    Expression& operator=(Expression&&) noexcept;
    ~Expression();

    /// Value for `values` (one per variable, in constructor order). Not thread-safe.
    double operator()(const std::vector<double>& values) const;

    const std::string& text() const { return text_; }
    const std::vector<std::string>& variables() const { return variables_; }

private:
    struct Impl;
    std::string text_;
    std::vector<std::string> variables_;
    std::unique_ptr<Impl> impl_;
};

}  // namespace granseg
