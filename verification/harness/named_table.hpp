// A data file of the project's format (run/output.hpp: a first line "# name1 name2 ...", further
// "#" lines, then rows of numbers) read back by column name: the studies and verification programs
// that read what a run wrote.
#pragma once

#include <map>
#include <string>
#include <vector>

namespace granseg::verify {

/// A data file's columns by name (from its first line) and rows; "nan" and "inf" read as such.
struct NamedTable {
    std::string name;  // the file, for messages
    std::map<std::string, std::size_t> index;
    std::vector<std::vector<double>> rows;

    const std::vector<double>& last() const { return rows.back(); }
    /// The value of `column` in `row`; InputError naming the file if it has no such column.
    double at(const std::vector<double>& row, const std::string& column) const;
};

/// Parses the text of a data file; InputError naming `name` if it has no rows.
NamedTable parse_named(const std::string& text, const std::string& name);

/// Reads and parses the file at `path`; InputError if it cannot be read.
NamedTable read_named(const std::string& path);

}  // namespace granseg::verify
