// The verification harness: every verification program prints its checks as one fixed-width
// table and returns non-zero if any check failed.
//
//   check                                    | measured     | expected     | tolerance  | result
//   dilute limit: |g - 1| at Phi = 1e-6      | 1.577e-06    | 0            | 3.155e-06  | PASS
//
// A check passes when |measured - expected| <= tolerance. A NaN or infinite measured value always
// fails. Expected values must be computed independently of the code under test (exact solution,
// another algorithm, a conservation law); every tolerance is a named constant with its reason.
#pragma once

#include <iosfwd>
#include <string>

namespace granseg::verify {

class CheckTable {
public:
    /// Prints the program title and the column header on `out`.
    explicit CheckTable(const std::string& title, std::ostream& out);
    explicit CheckTable(const std::string& title);  // prints on std::cout

    /// Passes if |measured - expected| <= tolerance.
    bool near(const std::string& check, double measured, double expected, double tolerance);
    /// Passes if |measured - expected| <= tolerance * |expected| (tolerance printed as "rel ...").
    bool near_relative(const std::string& check, double measured, double expected, double tolerance);
    /// Passes if measured <= bound (a one-sided error bound; expected is printed as 0).
    bool at_most(const std::string& check, double measured, double bound);
    /// Passes if measured >= bound.
    bool at_least(const std::string& check, double measured, double bound);
    /// Passes if `count` (of violations, say) is exactly `expected`.
    bool count(const std::string& check, long measured, long expected);

    /// Prints a free-form note line (e.g. a sub-table heading); never affects the result.
    void note(const std::string& text);

    int passed() const { return passed_; }
    int failed() const { return failed_; }
    /// Prints the summary line and returns the process exit status (0 if nothing failed).
    int finish();

private:
    bool record(const std::string& check, const std::string& measured, const std::string& expected, const std::string& tolerance,
                bool ok);
    std::ostream& out_;
    std::string title_;
    int passed_ = 0;
    int failed_ = 0;
};

/// Formats a number for the table (%.4g, or "nan"/"inf").
std::string format(double v);

}  // namespace granseg::verify
