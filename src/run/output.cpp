#include "run/output.hpp"

#include "core/error.hpp"

#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>

namespace granseg {

TableRow::TableRow(std::initializer_list<Cell> cells) {
    names_.reserve(cells.size()), values_.reserve(cells.size());
    for (const Cell& c : cells) names_.emplace_back(c.name), values_.push_back(c.value);
}

TableRow& TableRow::add(std::string name, double value) {
    names_.push_back(std::move(name)), values_.push_back(value);
    return *this;
}

TableRow& TableRow::add(const TableRow& more) {
    names_.insert(names_.end(), more.names_.begin(), more.names_.end());
    values_.insert(values_.end(), more.values_.begin(), more.values_.end());
    return *this;
}

void DataTable::comment(const std::string& text) { comments_.push_back(text); }

void DataTable::row(const TableRow& r) {
    if (rows_ == 0) columns_ = r.names();
    if (r.names() != columns_) {
        std::size_t i = 0;
        while (i < r.size() && i < columns_.size() && r.names()[i] == columns_[i]) ++i;
        throw InvariantError("DataTable::row: column " + std::to_string(i + 1) + " is named \"" +
                             (i < r.size() ? r.names()[i] : "") + "\", the table's \"" +
                             (i < columns_.size() ? columns_[i] : "") + "\"");
    }
    char buf[32];
    for (std::size_t i = 0; i < r.size(); ++i) {
        std::snprintf(buf, sizeof buf, "%.12g", r.values()[i]);
        body_ += (i ? " " : "") + std::string(buf);
    }
    body_ += '\n';
    ++rows_;
}

void DataTable::blank() { body_ += '\n'; }

std::string DataTable::str() const {
    std::string out = "#";
    for (const auto& c : columns_) out += " " + c;
    out += '\n';
    for (const auto& c : comments_) out += "# " + c + '\n';
    return out + body_;
}

void write_file_atomically(const std::string& path, const std::string& content) {
    namespace fs = std::filesystem;
    const fs::path target(path);
    std::error_code ec;
    if (target.has_parent_path()) fs::create_directories(target.parent_path(), ec);
    if (ec) throw InputError("cannot create directory " + target.parent_path().string() + ": " + ec.message());
    const std::string tmp = path + ".tmp." + std::to_string(::getpid());
    {
        std::ofstream out(tmp, std::ios::binary);
        out << content;
        out.close();
        if (!out) {
            std::remove(tmp.c_str());
            throw InputError("cannot write " + path);
        }
    }
    fs::rename(tmp, target, ec);
    if (ec) {
        std::remove(tmp.c_str());
        throw InputError("cannot rename " + tmp + " to " + path + ": " + ec.message());
    }
}

void OutputSet::add(const std::string& path, std::string content) { files_.emplace_back(path, std::move(content)); }

void OutputSet::checkpoint(StateIO& io) {
    std::uint64_t n = files_.size();
    io("files", n);
    files_.resize(static_cast<std::size_t>(n));
    for (auto& [path, content] : files_) io("file.path", path).blob("file.content", content);
}

void OutputSet::commit() const {
    for (const auto& [path, content] : files_) write_file_atomically(path, content);
}

}  // namespace granseg
