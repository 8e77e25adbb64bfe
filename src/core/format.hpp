// Number formatting for messages and `name = value` output.
#pragma once

#include <cstdio>
#include <cstdlib>
#include <string>

namespace granseg {

/// v in %g style with `digits` significant digits ("nan", "inf" for non-finite values; a
/// negative zero prints as "0").
inline std::string format_number(double v, int digits = 6) {
    char buf[40];
    std::snprintf(buf, sizeof buf, "%.*g", digits, v == 0.0 ? 0.0 : v);
    return buf;
}

/// v with the fewest significant digits that read back as v exactly (0.1, not
/// 0.10000000000000001): for messages and records that must identify a value to the bit.
inline std::string format_exact(double v) {
    std::string text;
    for (int digits = 1; digits <= 17; ++digits) {
        text = format_number(v, digits);
        if (std::strtod(text.c_str(), nullptr) == v) break;
    }
    return text;
}

/// The names separated by ", ", in the order of the container ("none" if it is empty).
template <class Names>
std::string comma_list(const Names& names) {
    std::string out;
    for (const auto& n : names) out += (out.empty() ? "" : ", ") + n;
    return out.empty() ? "none" : out;
}

}  // namespace granseg
