#include "segregation/scheme.hpp"

namespace granseg {

SegregationScheme parse_scheme(const std::string& name) {
    choice_position(kSegregationSchemes, name, "segregation scheme");  // InputError for an unknown name
    return SegregationScheme::named(name);
}

std::string bounded_scheme_names() {
    std::string names;
    for (const SchemeRow& row : kSegregationSchemes)
        if (row.bounded) names += (names.empty() ? "" : ", ") + std::string(row.name);
    return names;
}

}  // namespace granseg
