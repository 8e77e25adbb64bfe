// Output files: gnuplot-ready data tables and all-or-nothing writing.
//
// Every data file starts with one line "# name1 name2 ..." naming its columns (further "# "
// lines may follow), then whitespace-separated rows. Files are written to a temporary name in
// the target directory and renamed, so a reader never sees half a file, and a run that stops
// early (bad input, broken invariant) leaves no output at all.
#pragma once

#include <string>
#include <utility>
#include <vector>

namespace granseg {

/// A table of numbers with named columns, rendered as text for gnuplot.
class DataTable {
public:
    explicit DataTable(std::vector<std::string> columns);
    /// Adds a "# text" line below the column line (provenance, parameters).
    void comment(const std::string& text);
    /// Appends a row; throws InputError if its length differs from the columns.
    void row(const std::vector<double>& values);
    /// Appends an empty line (gnuplot block separator, e.g. between curves or surface rows).
    void blank();
    std::size_t rows() const { return rows_; }
    /// The whole table as text.
    std::string str() const;

private:
    std::vector<std::string> columns_;
    std::vector<std::string> comments_;
    std::string body_;
    std::size_t rows_ = 0;
};

/// Writes `content` to `path` via a temporary file and rename; creates parent directories.
/// Throws InputError naming the path on failure.
void write_file_atomically(const std::string& path, const std::string& content);

/// The files of one run, held in memory and written together by commit().
class OutputSet {
public:
    void add(const std::string& path, std::string content);
    void add(const std::string& path, const DataTable& table) { add(path, table.str()); }
    /// Writes every file atomically, in the order added.
    void commit() const;
    const std::vector<std::pair<std::string, std::string>>& files() const { return files_; }

private:
    std::vector<std::pair<std::string, std::string>> files_;
};

}  // namespace granseg
