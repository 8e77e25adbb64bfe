#include "segregation/scheme.hpp"

#include <stdexcept>

namespace granseg {

namespace {

template <class E>
E parse(const std::string& name, const std::vector<std::string>& names, const char* what) {
    for (std::size_t i = 0; i < names.size(); ++i)
        if (names[i] == name) return static_cast<E>(i);
    std::string allowed;
    for (const auto& n : names) allowed += (allowed.empty() ? "" : ", ") + n;
    throw std::invalid_argument(std::string("unknown ") + what + " \"" + name + "\" (allowed: " + allowed + ")");
}

}  // namespace

// The order of the names follows the order of the enumerators.
const std::vector<std::string>& scheme_names() {
    static const std::vector<std::string> names = {"modified-godunov", "modified-godunov-2", "classic-upwind",
                                                   "classic-godunov"};
    return names;
}

const std::vector<std::string>& limiter_names() {
    static const std::vector<std::string> names = {"minmod", "mc"};
    return names;
}

SegregationScheme parse_scheme(const std::string& name) {
    return parse<SegregationScheme>(name, scheme_names(), "segregation scheme");
}

std::string scheme_name(SegregationScheme scheme) { return scheme_names().at(static_cast<std::size_t>(scheme)); }

Limiter parse_limiter(const std::string& name) { return parse<Limiter>(name, limiter_names(), "limiter"); }

std::string limiter_name(Limiter limiter) { return limiter_names().at(static_cast<std::size_t>(limiter)); }

const std::vector<std::string>& bulk_scheme_names() {
    static const std::vector<std::string> names = {"donor-cell", "fct"};
    return names;
}

BulkScheme parse_bulk_scheme(const std::string& name) { return parse<BulkScheme>(name, bulk_scheme_names(), "bulk scheme"); }

}  // namespace granseg
