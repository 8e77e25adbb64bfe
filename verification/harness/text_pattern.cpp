#include "harness/text_pattern.hpp"

#include <algorithm>
#include <cstdlib>
#include <regex>

namespace granseg::verify {

struct Pattern::Impl {
    std::regex re;
    std::vector<std::string> literals;  // required_literals(), empty: none known
    bool ignore_case;
    /// False only if the text contains none of the literals, so that no match is possible.
    bool may_match(const std::string& text) const;
};

namespace {

std::string lower(std::string text) {
    for (char& c : text)
        if (c >= 'A' && c <= 'Z') c = static_cast<char>(c - 'A' + 'a');
    return text;
}

// Escapes that stand for one literal character (\. for '.'); any other escape is a class
// (\d), an assertion (\b) or a reference and ends a literal run.
bool escaped_literal(char c) { return std::string(".()[]{}*+?|^$\\/-").find(c) != std::string::npos; }

/// The index just past the character class that opens at expression[at] ('[').
std::size_t past_class(const std::string& e, std::size_t at) {
    std::size_t i = at + 1;
    if (i < e.size() && e[i] == '^') ++i;
    if (i < e.size() && e[i] == ']') ++i;  // a ']' first is literal
    for (; i < e.size() && e[i] != ']'; ++i)
        if (e[i] == '\\') ++i;
    return i + 1;
}

using Literals = std::vector<std::string>;  // a match contains at least one of them

Literals required(const std::string& e, std::size_t begin, std::size_t end);

/// The index just past the group that opens at e[at] ('('), nested groups and classes included.
std::size_t past_group(const std::string& e, std::size_t at, std::size_t end) {
    int depth = 0;
    for (std::size_t i = at; i < end; ++i) {
        if (e[i] == '\\')
            ++i;
        else if (e[i] == '[')
            i = past_class(e, i) - 1;
        else if (e[i] == '(')
            ++depth;
        else if (e[i] == ')' && --depth == 0)
            return i + 1;
    }
    return end;
}

/// What follows an atom ending at e[at]: 0 if nothing, 1 if a quantifier that allows no copy
/// (?, *, {0...}), 2 if one that allows more copies (+, {n...} with n >= 1); `next` past it.
int quantifier(const std::string& e, std::size_t at, std::size_t end, std::size_t& next) {
    next = at;
    if (at >= end) return 0;
    if (e[at] == '?' || e[at] == '*') return next = at + 1, 1;
    if (e[at] == '+') return next = at + 1, 2;
    if (e[at] != '{') return 0;
    const std::size_t close = e.find('}', at);
    next = close == std::string::npos || close >= end ? end : close + 1;
    return std::strtol(e.c_str() + at + 1, nullptr, 10) >= 1 ? 2 : 1;
}

/// The better of two requirements: the longer shortest literal, then the fewer literals.
bool better(const Literals& a, const Literals& b) {
    auto shortest = [](const Literals& l) {
        std::size_t n = l.empty() ? 0 : l[0].size();
        for (const std::string& x : l) n = std::min(n, x.size());
        return n;
    };
    if (shortest(a) != shortest(b)) return shortest(a) > shortest(b);
    return !a.empty() && a.size() < b.size();
}

/// What alternative e[begin, end) (no top-level '|') requires: its best literal run, group or
/// digit (\d) that cannot be skipped. Empty if nothing is required.
Literals alternative_required(const std::string& e, std::size_t begin, std::size_t end) {
    Literals best;
    std::string run;
    auto offer = [&](const Literals& candidate) {
        if (better(candidate, best)) best = candidate;
    };
    auto close_run = [&] {
        if (!run.empty()) offer({run});
        run.clear();
    };
    for (std::size_t i = begin; i < end;) {
        const char c = e[i];
        char literal = 0;
        Literals inner;  // what a group or a class escape requires
        std::size_t atom_end = i + 1;
        if (c == '\\' && i + 1 < end && escaped_literal(e[i + 1])) {
            literal = e[i + 1], atom_end = i + 2;
        } else if (c == '\\') {
            if (i + 1 < end && e[i + 1] == 'd') inner = {"0", "1", "2", "3", "4", "5", "6", "7", "8", "9"};
            atom_end = i + 2;
        } else if (c == '[') {
            atom_end = past_class(e, i);
        } else if (c == '(') {
            atom_end = past_group(e, i, end);
            const bool lookaround = e.compare(i, 3, "(?=") == 0 || e.compare(i, 3, "(?!") == 0;
            const std::size_t content = e.compare(i, 3, "(?:") == 0 ? i + 3 : i + 1;
            if (!lookaround && atom_end - 1 > content) inner = required(e, content, atom_end - 1);
        } else if (std::string(".^$?*+{)").find(c) == std::string::npos) {
            literal = c;
        }
        std::size_t next = atom_end;
        const int q = quantifier(e, atom_end, end, next);
        if (literal != 0 && q != 1) run += literal;
        if (literal == 0 || q != 0) close_run();
        if (q != 1 && !inner.empty()) offer(inner);
        i = next;
    }
    close_run();
    return best;
}

/// What e[begin, end) requires: one requirement per top-level alternative, joined; empty if an
/// alternative requires nothing.
Literals required(const std::string& e, std::size_t begin, std::size_t end) {
    Literals out;
    std::size_t from = begin;
    int depth = 0;
    for (std::size_t i = begin;; ++i) {
        const bool last = i >= end;
        if (!last) {
            if (e[i] == '\\') {
                ++i;
                continue;
            }
            if (e[i] == '[') {
                i = past_class(e, i) - 1;
                continue;
            }
            if (e[i] == '(') ++depth;
            if (e[i] == ')') --depth;
            if (e[i] != '|' || depth != 0) continue;
        }
        const Literals alternative = alternative_required(e, from, std::min(i, end));
        if (alternative.empty()) return {};
        out.insert(out.end(), alternative.begin(), alternative.end());
        if (last) return out;
        from = i + 1;
    }
}

}  // namespace

std::vector<std::string> required_literals(const std::string& expression, bool ignore_case) {
    Literals out = required(expression, 0, expression.size());
    for (std::string& l : out) l = ignore_case ? lower(l) : l;
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
    return out;
}

bool Pattern::Impl::may_match(const std::string& text) const {
    if (literals.empty()) return true;
    const std::string& t = ignore_case ? lower(text) : text;
    for (const std::string& l : literals)
        if (t.find(l) != std::string::npos) return true;
    return false;
}

namespace {

PatternMatch to_match(const std::smatch& m) {
    PatternMatch out;
    for (std::size_t g = 0; g < m.size(); ++g) out.groups.push_back(m[g].str()), out.took_part.push_back(m[g].matched);
    out.prefix = m.prefix().str(), out.suffix = m.suffix().str();
    return out;
}

}  // namespace

Pattern::Pattern(const std::string& expression, bool ignore_case)
    : impl_(std::make_unique<Impl>(
          Impl{ignore_case ? std::regex(expression, std::regex::ECMAScript | std::regex::icase) : std::regex(expression),
               required_literals(expression, ignore_case), ignore_case})) {}
Pattern::~Pattern() = default;
Pattern::Pattern(Pattern&&) noexcept = default;
Pattern& Pattern::operator=(Pattern&&) noexcept = default;

bool Pattern::found_in(const std::string& text) const { return impl_->may_match(text) && std::regex_search(text, impl_->re); }

bool Pattern::matches(const std::string& text) const { return impl_->may_match(text) && std::regex_match(text, impl_->re); }

std::optional<PatternMatch> Pattern::first_in(const std::string& text) const {
    std::smatch m;
    if (!impl_->may_match(text) || !std::regex_search(text, m, impl_->re)) return std::nullopt;
    return to_match(m);
}

std::optional<PatternMatch> Pattern::match_of(const std::string& text) const {
    std::smatch m;
    if (!impl_->may_match(text) || !std::regex_match(text, m, impl_->re)) return std::nullopt;
    return to_match(m);
}

std::vector<PatternMatch> Pattern::all_in(const std::string& text) const {
    std::vector<PatternMatch> out;
    if (!impl_->may_match(text)) return out;
    for (std::sregex_iterator it(text.begin(), text.end(), impl_->re), end; it != end; ++it) out.push_back(to_match(*it));
    return out;
}

std::string Pattern::removed_from(const std::string& text) const {
    return impl_->may_match(text) ? std::regex_replace(text, impl_->re, "") : text;
}

}  // namespace granseg::verify
