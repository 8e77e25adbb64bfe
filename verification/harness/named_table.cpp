#include "harness/named_table.hpp"

#include "core/error.hpp"

#include <cstdlib>
#include <fstream>
#include <sstream>

namespace granseg::verify {

double NamedTable::at(const std::vector<double>& row, const std::string& column) const {
    const auto it = index.find(column);
    if (it == index.end() || it->second >= row.size()) throw InputError(name + ": no column " + column);
    return row[it->second];
}

NamedTable parse_named(const std::string& text, const std::string& name) {
    NamedTable t;
    t.name = name;
    std::istringstream in(text);
    std::string line;
    std::getline(in, line);
    std::istringstream names(line.substr(line.empty() ? 0 : 1));
    for (std::string column; names >> column;) t.index.emplace(column, t.index.size());
    while (std::getline(in, line)) {
        if (line.empty() || line[0] == '#') continue;
        std::istringstream row(line);
        std::vector<double> v;
        for (std::string token; row >> token;) v.push_back(std::strtod(token.c_str(), nullptr));
        t.rows.push_back(v);
    }
    if (t.rows.empty()) throw InputError(name + ": no rows");
    return t;
}

NamedTable read_named(const std::string& path) {
    std::ifstream in(path);
    if (!in) throw InputError("cannot read " + path);
    std::ostringstream text;
    text << in.rdbuf();
    return parse_named(text.str(), path);
}

}  // namespace granseg::verify
