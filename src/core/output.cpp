#include "core/output.hpp"

#include "core/error.hpp"

#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>

namespace granseg {

DataTable::DataTable(std::vector<std::string> columns) : columns_(std::move(columns)) {}

void DataTable::comment(const std::string& text) { comments_.push_back(text); }

void DataTable::row(const std::vector<double>& values) {
    if (values.size() != columns_.size())
        throw InputError("DataTable::row: " + std::to_string(values.size()) +
                                    " values for " + std::to_string(columns_.size()) + " columns");
    char buf[32];
    for (std::size_t i = 0; i < values.size(); ++i) {
        std::snprintf(buf, sizeof buf, "%.12g", values[i]);
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

void OutputSet::add(const std::string& path, std::string content) {
    files_.emplace_back(path, std::move(content));
}

void OutputSet::commit() const {
    for (const auto& [path, content] : files_) write_file_atomically(path, content);
}

}  // namespace granseg
