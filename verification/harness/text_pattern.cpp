#include "harness/text_pattern.hpp"

#include <regex>

namespace granseg::verify {

struct Pattern::Impl {
    std::regex re;
};

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
          Impl{ignore_case ? std::regex(expression, std::regex::ECMAScript | std::regex::icase) : std::regex(expression)})) {}
Pattern::~Pattern() = default;
Pattern::Pattern(Pattern&&) noexcept = default;
Pattern& Pattern::operator=(Pattern&&) noexcept = default;

bool Pattern::found_in(const std::string& text) const { return std::regex_search(text, impl_->re); }

bool Pattern::matches(const std::string& text) const { return std::regex_match(text, impl_->re); }

std::optional<PatternMatch> Pattern::first_in(const std::string& text) const {
    std::smatch m;
    if (!std::regex_search(text, m, impl_->re)) return std::nullopt;
    return to_match(m);
}

std::optional<PatternMatch> Pattern::match_of(const std::string& text) const {
    std::smatch m;
    if (!std::regex_match(text, m, impl_->re)) return std::nullopt;
    return to_match(m);
}

std::vector<PatternMatch> Pattern::all_in(const std::string& text) const {
    std::vector<PatternMatch> out;
    for (std::sregex_iterator it(text.begin(), text.end(), impl_->re), end; it != end; ++it) out.push_back(to_match(*it));
    return out;
}

std::string Pattern::removed_from(const std::string& text) const { return std::regex_replace(text, impl_->re, ""); }

}  // namespace granseg::verify
