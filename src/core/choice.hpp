// Tables of named choices (schemes, limiters, laws, rules): one row per choice holding its
// scene-file name and a one-line summary, so that the names a scene file accepts, the parser,
// the error message and the help text of `granseg run --help` all come from the one table.
//
// A table is a constexpr array of rows; a row has at least `name` and `summary`. Rows of an
// enumerated choice are Choice<E>, which adds the enumerator (so the order of the rows and of
// the enumerators need not match).
#pragma once

#include "core/error.hpp"

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace granseg {

/// A row of an enumerated choice.
template <class E>
struct Choice {
    E value;
    std::string_view name;     // the scene-file value
    std::string_view summary;  // one line for the help text
};

/// The names of a table's rows, in its order.
template <class Row, std::size_t N>
std::vector<std::string> choice_names(const Row (&table)[N]) {
    std::vector<std::string> names;
    for (const Row& row : table) names.emplace_back(row.name);
    return names;
}

/// The position of the row called `name`; InputError "unknown WHAT "NAME" (allowed: ...)" if none.
template <class Row, std::size_t N>
std::size_t choice_position(const Row (&table)[N], std::string_view name, std::string_view what) {
    std::string allowed;
    for (std::size_t i = 0; i < N; ++i) {
        if (table[i].name == name) return i;
        allowed += (i ? ", " : "") + std::string(table[i].name);
    }
    throw InputError("unknown " + std::string(what) + " \"" + std::string(name) + "\" (allowed: " + allowed + ")");
}

/// The enumerator of the row called `name` (InputError as above).
template <class E, std::size_t N>
E parse_choice(const Choice<E> (&table)[N], std::string_view name, std::string_view what) {
    return table[choice_position(table, name, what)].value;
}

/// The name of the row holding `value` (every enumerator has a row; an empty name otherwise).
template <class E, std::size_t N>
std::string choice_name(const Choice<E> (&table)[N], E value) {
    for (const Choice<E>& row : table)
        if (row.value == value) return std::string(row.name);
    return {};
}

/// Help text: one line "  name: summary" per row.
template <class Row, std::size_t N>
std::string describe_choices(const Row (&table)[N]) {
    std::string text;
    for (const Row& row : table) text += "    " + std::string(row.name) + ": " + std::string(row.summary) + "\n";
    return text;
}

}  // namespace granseg
