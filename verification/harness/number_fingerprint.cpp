#include "harness/number_fingerprint.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <vector>

namespace granseg::verify {

namespace {

// Below this share of its column's largest magnitude a value counts as 0: round-off at that level
// may differ between machines and compilers.
constexpr double kColumnFloor = 1e-9;

bool parse_number(const std::string& token, double& x) {
    char* end = nullptr;
    x = std::strtod(token.c_str(), &end);
    return end != token.c_str() && *end == '\0';
}

struct DataLines {
    std::vector<std::string> names;              // from the first line "# name ...", if any
    std::vector<std::vector<std::string>> rows;  // data lines as tokens; a blank line is an empty row
};

DataLines data_lines(const std::string& text) {
    DataLines d;
    std::istringstream in(text);
    bool first = true;
    for (std::string line; std::getline(in, line); first = false) {
        const auto at = line.find_first_not_of(" \t\r");
        if (at != std::string::npos && line[at] == '#') {
            if (first) {
                std::istringstream words(line.substr(at + 1));
                for (std::string w; words >> w;) d.names.push_back(w);
            }
            continue;
        }
        std::istringstream words(line);
        std::vector<std::string> row;
        for (std::string w; words >> w;) row.push_back(w);
        d.rows.push_back(row);
    }
    return d;
}

}  // namespace

void Fnv1a::add(const std::string& s) {
    for (unsigned char c : s) hash_ = (hash_ ^ c) * 0x100000001b3ULL;
    hash_ = (hash_ ^ 0xff) * 0x100000001b3ULL;
}

std::string Fnv1a::hex() const {
    char buf[17];
    std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(hash_));
    return buf;
}

std::string numbers_fingerprint(const std::string& text, int digits, const std::function<bool(const std::string&)>& counts) {
    const DataLines d = data_lines(text);
    std::vector<bool> kept;
    std::vector<double> largest;
    for (const auto& row : d.rows)
        for (std::size_t j = 0; j < row.size(); ++j) {
            if (j >= largest.size()) {
                largest.resize(j + 1, 0.0);
                kept.resize(j + 1, true);
                if (counts && j < d.names.size()) kept[j] = counts(d.names[j]);
            }
            double x;
            if (parse_number(row[j], x) && std::isfinite(x)) largest[j] = std::max(largest[j], std::fabs(x));
        }
    Fnv1a h;
    for (const auto& row : d.rows) {
        std::string line;
        for (std::size_t j = 0; j < row.size(); ++j) {
            if (!kept[j]) continue;
            double x;
            if (!parse_number(row[j], x) || !std::isfinite(x)) {
                line += row[j] + " ";
                continue;
            }
            if (std::fabs(x) < kColumnFloor * largest[j]) x = 0.0;
            char buf[40];
            std::snprintf(buf, sizeof buf, "%.*g ", digits, x == 0.0 ? 0.0 : x);  // -0 prints as 0
            line += buf;
        }
        h.add(line);
    }
    return h.hex();
}

}  // namespace granseg::verify
