// Number formatting for messages and `name = value` output.
#pragma once

#include <cstdio>
#include <string>

namespace granseg {

/// v in %g style with `digits` significant digits ("nan", "inf" for non-finite values; a
/// negative zero prints as "0").
inline std::string format_number(double v, int digits = 6) {
    char buf[40];
    std::snprintf(buf, sizeof buf, "%.*g", digits, v == 0.0 ? 0.0 : v);
    return buf;
}

/// The names separated by ", ", in the order of the container ("none" if it is empty).
template <class Names>
std::string comma_list(const Names& names) {
    std::string out;
    for (const auto& n : names) out += (out.empty() ? "" : ", ") + n;
    return out.empty() ? "none" : out;
}

}  // namespace granseg
