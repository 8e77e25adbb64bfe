#include "harness/doc_words.hpp"

#include <array>
#include <cmath>
#include <cstdio>
#include <string>
#include <utility>

namespace granseg::verify::docs {

namespace {

const std::array<const char*, 20> kCounts = {"zero",     "one",     "two",     "three",     "four",     "five",    "six",
                                             "seven",    "eight",   "nine",    "ten",       "eleven",   "twelve",  "thirteen",
                                             "fourteen", "fifteen", "sixteen", "seventeen", "eighteen", "nineteen"};
const std::array<const char*, 10> kTens = {"",      "ten",   "twenty",  "thirty", "forty",
                                           "fifty", "sixty", "seventy", "eighty", "ninety"};

struct Fraction {
    const char* words;
    int p, q;
};
const std::array<Fraction, 11> kFractions = {{{"a half", 1, 2},
                                              {"half", 1, 2},
                                              {"a third", 1, 3},
                                              {"two thirds", 2, 3},
                                              {"a quarter", 1, 4},
                                              {"three quarters", 3, 4},
                                              {"a fifth", 1, 5},
                                              {"two fifths", 2, 5},
                                              {"three fifths", 3, 5},
                                              {"four fifths", 4, 5},
                                              {"a tenth", 1, 10}}};

/// A whole number in words (zero ... nineteen, then twenty ... ninety in tens) and the width it
/// stands for.
std::optional<WordNumber> count_of(const std::string& w) {
    for (std::size_t n = 0; n < kCounts.size(); ++n)
        if (w == kCounts[n]) return WordNumber{static_cast<double>(n), 1.0};
    for (std::size_t n = 2; n < kTens.size(); ++n)
        if (w == kTens[n]) return WordNumber{10.0 * static_cast<double>(n), 10.0};
    return std::nullopt;
}

std::string count_words(long n) {
    if (n >= 0 && n < static_cast<long>(kCounts.size())) return kCounts[static_cast<std::size_t>(n)];
    if (n % 10 == 0 && n >= 20 && n < 100) return kTens[static_cast<std::size_t>(n / 10)];
    return std::to_string(n);
}

/// A whole number as words can say it: to the unit below twenty, to the ten from there.
long spoken(double value) {
    const long n = std::lround(value);
    return n < 20 ? n : 10 * std::lround(value / 10.0);
}

bool ends_with(const std::string& s, const std::string& tail) {
    return s.size() > tail.size() && s.compare(s.size() - tail.size(), tail.size(), tail) == 0;
}

}  // namespace

std::optional<WordNumber> word_number(const std::string& text) {
    if (text == "twice") return WordNumber{2.0, 1.0};
    for (const Fraction& f : kFractions)
        if (text == f.words) return WordNumber{static_cast<double>(f.p) / f.q, 1.0 / (f.q * f.q)};
    if (ends_with(text, " times")) return count_of(text.substr(0, text.size() - 6));
    if (ends_with(text, " hundredths") || ends_with(text, " hundredth")) {
        const auto n = count_of(text.substr(0, text.rfind(' ')));
        if (n && n->unit == 1.0) return WordNumber{n->value / 100.0, 0.01};
        return std::nullopt;
    }
    return count_of(text);
}

std::optional<std::string> in_words_like(double value, const std::string& like) {
    const auto shown = word_number(like);
    if (!shown) return std::nullopt;
    if (like == "twice" || ends_with(like, " times")) {
        const long n = spoken(value);
        return n == 2 ? std::string("twice") : count_words(n) + " times";
    }
    if (ends_with(like, "hundredths") || ends_with(like, "hundredth")) {
        const long n = std::lround(100.0 * value);
        return count_words(n) + (n == 1 ? " hundredth" : " hundredths");
    }
    for (const Fraction& f : kFractions)
        if (like == f.words) {
            // The nearest fraction that stands for the value, in the page's own spelling of a half.
            const Fraction* best = nullptr;
            for (const Fraction& g : kFractions) {
                if (std::string(g.words) == (like == "half" ? "a half" : "half")) continue;
                const double d = std::fabs(value - static_cast<double>(g.p) / g.q);
                if (d <= 0.5 / (g.q * g.q) && (!best || d < std::fabs(value - static_cast<double>(best->p) / best->q))) best = &g;
            }
            if (best) return std::string(best->words);
            char buf[32];
            std::snprintf(buf, sizeof buf, "%.2f", value);
            return std::string(buf);
        }
    return count_words(spoken(value));
}

}  // namespace granseg::verify::docs
