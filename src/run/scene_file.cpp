#include "run/scene_file.hpp"

#include "core/error.hpp"
#include "core/format.hpp"

#include <toml++/toml.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

namespace granseg {

namespace {

/// The names sorted, each once, separated by ", ".
template <class Names>
std::string sorted_list(const Names& names) {
    return comma_list(std::set<std::string>(names.begin(), names.end()));
}

/// What a TOML node is, for "expected X, got Y" messages.
std::string describe_node(const toml::node& node) {
    switch (node.type()) {
        case toml::node_type::string:
            return "the string \"" + *node.value<std::string>() + "\"";
        case toml::node_type::integer:
            return "the integer " + std::to_string(*node.value<int64_t>());
        case toml::node_type::floating_point:
            return "the number " + format_number(*node.value<double>());
        case toml::node_type::boolean:
            return *node.value<bool>() ? "true" : "false";
        case toml::node_type::array:
            return "an array";
        case toml::node_type::table:
            return "a table";
        default:
            return "a date or time";
    }
}

}  // namespace

bool Range::contains(double v) const {
    if (!std::isfinite(v)) return false;
    const bool lo_ok = lo_open ? v > lo : v >= lo;
    const bool hi_ok = hi_open ? v < hi : v <= hi;
    return lo_ok && hi_ok;
}

std::string Range::describe(const std::string& name) const {
    std::string out;
    if (std::isfinite(lo)) out += format_number(lo) + (lo_open ? " < " : " <= ");
    out += name;
    if (std::isfinite(hi)) out += (hi_open ? " < " : " <= ") + format_number(hi);
    if (!std::isfinite(lo) && !std::isfinite(hi)) out = "any finite " + name;
    return out;
}

struct SceneFile::Impl {
    toml::table root;
    std::map<std::string, std::set<std::string>> asked;               // keys some accessor asked for
    std::map<std::pair<std::string, std::string>, std::string> used;  // (section, key) -> the value used, as text

    /// Marks (section, key) as known and returns its node, or nullptr if absent.
    const toml::node* lookup(const std::string& section, const std::string& key) {
        asked[section].insert(key);
        const toml::table* table = root[section].as_table();
        return table ? table->get(key) : nullptr;
    }
};

SceneFile::SceneFile(std::unique_ptr<Impl> impl, std::string name) : impl_(std::move(impl)), name_(std::move(name)) {}
SceneFile::SceneFile(SceneFile&&) noexcept = default;
SceneFile& SceneFile::operator=(SceneFile&&) noexcept = default;
SceneFile::~SceneFile() = default;

SceneFile SceneFile::load(const std::string& path) {
    std::ifstream in(path);
    if (!in) throw InputError(path + ": cannot open the scene file");
    std::ostringstream text;
    text << in.rdbuf();
    return parse(text.str(), path);
}

SceneFile SceneFile::parse(const std::string& text, const std::string& name) {
    auto impl = std::make_unique<Impl>();
    try {
        impl->root = toml::parse(text, name);
    } catch (const toml::parse_error& e) {
        std::string what(e.description());
        for (auto& c : what)
            if (c == '\n') c = ' ';
        throw InputError(name + ": TOML syntax error at line " + std::to_string(e.source().begin.line) + ", column " +
                         std::to_string(e.source().begin.column) + ": " + what);
    }
    return SceneFile(std::move(impl), name);
}

void SceneFile::fail(const std::string& section, const std::string& key, const std::string& what,
                     const std::string& allowed) const {
    throw InputError(name_ + ": [" + section + "] " + key + ": " + what + " (allowed: " + allowed + ")");
}

bool SceneFile::has(const std::string& section, const std::string& key) const {
    const toml::table* table = impl_->root[section].as_table();
    return table && table->get(key);
}

double SceneFile::number(const std::string& section, const std::string& key, const Range& range) const {
    const auto* node = impl_->lookup(section, key);
    const std::string allowed = "number, " + range.describe(key);
    if (!node) fail(section, key, "missing", allowed);
    if (!node->is_number()) fail(section, key, "expected a number, got " + describe_node(*node), allowed);
    const double v = *node->value<double>();
    if (!range.contains(v)) fail(section, key, format_number(v) + " is out of range", allowed);
    return note(section, key, v);
}

double SceneFile::number(const std::string& section, const std::string& key, const Range& range, double fallback) const {
    return impl_->lookup(section, key) ? number(section, key, range) : note(section, key, fallback);
}

long SceneFile::integer(const std::string& section, const std::string& key, long lo, long hi) const {
    const auto* node = impl_->lookup(section, key);
    const std::string allowed = "integer, " + std::to_string(lo) + " <= " + key + " <= " + std::to_string(hi);
    if (!node) fail(section, key, "missing", allowed);
    if (!node->is_integer()) fail(section, key, "expected an integer, got " + describe_node(*node), allowed);
    const int64_t v = *node->value<int64_t>();
    if (v < lo || v > hi) fail(section, key, std::to_string(v) + " is out of range", allowed);
    return note(section, key, static_cast<long>(v));
}

long SceneFile::integer(const std::string& section, const std::string& key, long lo, long hi, long fallback) const {
    return impl_->lookup(section, key) ? integer(section, key, lo, hi) : note(section, key, fallback);
}

bool SceneFile::flag(const std::string& section, const std::string& key, bool fallback) const {
    const auto* node = impl_->lookup(section, key);
    if (!node) return note(section, key, fallback);
    if (!node->is_boolean()) fail(section, key, "expected true or false, got " + describe_node(*node), "true, false");
    return note(section, key, *node->value<bool>());
}

std::string SceneFile::choice(const std::string& section, const std::string& key, const std::vector<std::string>& allowed) const {
    const auto* node = impl_->lookup(section, key);
    if (!node) fail(section, key, "missing", sorted_list(allowed));
    if (!node->is_string()) fail(section, key, "expected a string, got " + describe_node(*node), sorted_list(allowed));
    const std::string v = *node->value<std::string>();
    for (const auto& a : allowed)
        if (a == v) return note(section, key, v);
    fail(section, key, "unknown value \"" + v + "\"", sorted_list(allowed));
}

std::string SceneFile::choice(const std::string& section, const std::string& key, const std::vector<std::string>& allowed,
                              const std::string& fallback) const {
    return impl_->lookup(section, key) ? choice(section, key, allowed) : note(section, key, fallback);
}

std::string SceneFile::text(const std::string& section, const std::string& key, const std::string& fallback) const {
    const auto* node = impl_->lookup(section, key);
    if (!node) return note(section, key, fallback);
    if (!node->is_string()) fail(section, key, "expected a string, got " + describe_node(*node), "a string");
    return note(section, key, *node->value<std::string>());
}

std::vector<double> SceneFile::numbers(const std::string& section, const std::string& key, const Range& range) const {
    const auto* node = impl_->lookup(section, key);
    const std::string allowed = "non-empty array of numbers, each " + range.describe("value");
    if (!node) fail(section, key, "missing", allowed);
    const toml::array* array = node->as_array();
    if (!array || array->empty()) fail(section, key, "expected " + allowed + ", got " + describe_node(*node), allowed);
    std::vector<double> out;
    for (std::size_t i = 0; i < array->size(); ++i) {
        const toml::node& item = *array->get(i);
        const std::string where = "element " + std::to_string(i + 1);
        if (!item.is_number()) fail(section, key, where + ": expected a number, got " + describe_node(item), allowed);
        const double v = *item.value<double>();
        if (!range.contains(v)) fail(section, key, where + ": " + format_number(v) + " is out of range", allowed);
        out.push_back(v);
    }
    return note(section, key, out);
}

std::vector<double> SceneFile::numbers(const std::string& section, const std::string& key, const Range& range,
                                       const std::vector<double>& fallback) const {
    return impl_->lookup(section, key) ? numbers(section, key, range) : note(section, key, fallback);
}

Expression SceneFile::expression(const std::string& section, const std::string& key,
                                 const std::vector<std::string>& variables) const {
    const auto* node = impl_->lookup(section, key);
    const std::string allowed = "muparser expression in " + sorted_list(variables);
    if (!node) fail(section, key, "missing", allowed);
    std::string text;
    if (node->is_string())
        text = *node->value<std::string>();
    else if (node->is_number())
        text = format_number(*node->value<double>());
    else
        fail(section, key, "expected an expression string, got " + describe_node(*node), allowed);
    try {
        Expression e(text, variables);
        note(section, key, text);
        return e;
    } catch (const InputError& e) {
        fail(section, key, e.what(), allowed);
    }
}

Expression SceneFile::expression(const std::string& section, const std::string& key, const std::vector<std::string>& variables,
                                 const std::string& fallback) const {
    if (impl_->lookup(section, key)) return expression(section, key, variables);
    note(section, key, fallback);
    return Expression(fallback, variables);
}

double SceneFile::note(const std::string& section, const std::string& key, double v) const {
    impl_->used[{section, key}] = format_exact(v);
    return v;
}

long SceneFile::note(const std::string& section, const std::string& key, long v) const {
    impl_->used[{section, key}] = std::to_string(v);
    return v;
}

bool SceneFile::note(const std::string& section, const std::string& key, bool v) const {
    impl_->used[{section, key}] = v ? "true" : "false";
    return v;
}

std::string SceneFile::note(const std::string& section, const std::string& key, const std::string& v) const {
    impl_->used[{section, key}] = "\"" + v + "\"";
    return v;
}

std::vector<double> SceneFile::note(const std::string& section, const std::string& key, const std::vector<double>& v) const {
    std::string text = "[";
    for (double x : v) text += (text.size() > 1 ? ", " : "") + format_exact(x);
    impl_->used[{section, key}] = text + "]";
    return v;
}

std::string SceneFile::settings(const std::vector<std::string>& ignored) const {
    std::string out;
    for (const auto& [where, value] : impl_->used) {
        const std::string name = "[" + where.first + "] " + where.second;
        if (std::find(ignored.begin(), ignored.end(), name) == ignored.end()) out += name + " = " + value + "\n";
    }
    return out;
}

std::string first_setting_missing(const std::string& a, const std::string& b) {
    std::istringstream in(a);
    for (std::string line; std::getline(in, line);)
        if (("\n" + b).find("\n" + line + "\n") == std::string::npos) return line;
    return "";
}

void SceneFile::finish() const {
    // Collect every offending entry with its line, then report the first one in the file.
    struct Problem {
        std::size_t line;
        std::string message;
    };
    std::vector<Problem> problems;
    std::set<std::string> sections;
    for (const auto& [name, known] : impl_->asked) sections.insert(name);
    for (const auto& [section_key, node] : impl_->root) {
        const std::string section(section_key.str());
        const std::size_t line = node.source().begin.line;
        const toml::table* table = node.as_table();
        if (!table) {
            problems.push_back(
                {line, name_ + ": " + section + ": key outside any section (allowed: sections " + sorted_list(sections) + ")"});
            continue;
        }
        auto known = impl_->asked.find(section);
        if (known == impl_->asked.end()) {
            problems.push_back({line, name_ + ": [" + section + "]: unknown section (allowed: " + sorted_list(sections) + ")"});
            continue;
        }
        for (const auto& [key, value] : *table) {
            if (known->second.count(std::string(key.str()))) continue;
            problems.push_back({value.source().begin.line, name_ + ": [" + section + "] " + std::string(key.str()) +
                                                               ": unknown key (allowed: " + sorted_list(known->second) + ")"});
        }
    }
    if (problems.empty()) return;
    const auto first =
        std::min_element(problems.begin(), problems.end(), [](const Problem& a, const Problem& b) { return a.line < b.line; });
    throw InputError(first->message);
}

}  // namespace granseg
