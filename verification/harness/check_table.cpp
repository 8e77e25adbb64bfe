#include "harness/check_table.hpp"

#include <cmath>
#include <cstdio>
#include <iostream>

namespace granseg::verify {

namespace {
constexpr int kCheckWidth = 64;
constexpr int kNumberWidth = 12;

std::string pad(const std::string& s, int width) {
    return s.size() >= static_cast<std::size_t>(width) ? s : s + std::string(width - s.size(), ' ');
}
}  // namespace

std::string format(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.4g", v);
    return buf;
}

CheckTable::CheckTable(const std::string& title, std::ostream& out) : out_(out), title_(title) {
    out_ << "== " << title_ << " ==\n"
         << pad("check", kCheckWidth) << " | " << pad("measured", kNumberWidth) << " | " << pad("expected", kNumberWidth) << " | "
         << pad("tolerance", kNumberWidth) << " | PASS/FAIL\n"
         << std::string(kCheckWidth + 3 * (kNumberWidth + 3) + 12, '-') << '\n';
}

CheckTable::CheckTable(const std::string& title) : CheckTable(title, std::cout) {}

bool CheckTable::record(const std::string& check, const std::string& measured, const std::string& expected,
                        const std::string& tolerance, bool ok) {
    out_ << pad(check, kCheckWidth) << " | " << pad(measured, kNumberWidth) << " | " << pad(expected, kNumberWidth) << " | "
         << pad(tolerance, kNumberWidth) << " | " << (ok ? "PASS" : "FAIL") << '\n';
    (ok ? passed_ : failed_) += 1;
    return ok;
}

bool CheckTable::near(const std::string& check, double measured, double expected, double tolerance) {
    const bool ok = std::isfinite(measured) && std::fabs(measured - expected) <= tolerance;
    return record(check, format(measured), format(expected), format(tolerance), ok);
}

bool CheckTable::near_relative(const std::string& check, double measured, double expected, double tolerance) {
    const bool ok = std::isfinite(measured) && std::fabs(measured - expected) <= tolerance * std::fabs(expected);
    return record(check, format(measured), format(expected), "rel " + format(tolerance), ok);
}

bool CheckTable::at_most(const std::string& check, double measured, double bound) {
    const bool ok = std::isfinite(measured) && measured <= bound;
    return record(check, format(measured), "0", "<= " + format(bound), ok);
}

bool CheckTable::at_least(const std::string& check, double measured, double bound) {
    const bool ok = std::isfinite(measured) && measured >= bound;
    return record(check, format(measured), ">= " + format(bound), "-", ok);
}

bool CheckTable::count(const std::string& check, long measured, long expected) {
    return record(check, std::to_string(measured), std::to_string(expected), "0", measured == expected);
}

void CheckTable::note(const std::string& text) { out_ << "# " << text << '\n'; }

int CheckTable::finish() {
    out_ << title_ << ": " << passed_ + failed_ << " checks, " << failed_ << " failed\n";
    return failed_ == 0 ? 0 : 1;
}

}  // namespace granseg::verify
