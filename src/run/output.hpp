// Output files: gnuplot-ready data tables and all-or-nothing writing.
//
// Every data file starts with one line "# name1 name2 ..." naming its columns (further "# "
// lines may follow), then whitespace-separated rows. Files are written to a temporary name in
// the target directory and renamed, so a reader never sees half a file, and a run that stops
// early (bad input, broken invariant) leaves no output at all.
#pragma once

#include "run/state_io.hpp"

#include <initializer_list>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace granseg {

/// One row of a DataTable: its values in column order, each with the name of its column, so that
/// a value cannot drift from its name:
///     table.row({{"x", x}, {"z", z}});     or     TableRow r; r.add("t", t).add("steps", n);
class TableRow {
public:
    /// A cell: a column's name and its value.
    struct Cell {
        std::string_view name;
        double value;
    };
    TableRow() = default;
    TableRow(std::initializer_list<Cell> cells);
    /// Appends a column.
    TableRow& add(std::string name, double value);
    /// Appends the columns of `more` (a group of columns built elsewhere).
    TableRow& add(const TableRow& more);
    std::size_t size() const { return values_.size(); }
    const std::vector<std::string>& names() const { return names_; }
    const std::vector<double>& values() const { return values_; }

private:
    std::vector<std::string> names_;
    std::vector<double> values_;
};

/// A table of numbers with named columns, rendered as text for gnuplot. Its first row names the
/// columns; every later row must name the same columns in the same order.
class DataTable {
public:
    /// Adds a "# text" line below the column line (provenance, parameters).
    void comment(const std::string& text);
    /// Appends a row; throws InvariantError, naming the column, if its names differ from the
    /// first row's.
    void row(const TableRow& values);
    /// Appends an empty line (gnuplot block separator, e.g. between curves or surface rows).
    void blank();
    std::size_t rows() const { return rows_; }
    /// The whole table as text.
    std::string str() const;
    /// Saves or restores (run/state_io.hpp) the table so far.
    void checkpoint(StateIO& io) {
        io("table.columns", columns_)("table.comments", comments_)("table.body", body_)("table.rows", rows_);
    }

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
    /// Saves or restores (run/state_io.hpp) the files so far.
    void checkpoint(StateIO& io);

private:
    std::vector<std::pair<std::string, std::string>> files_;
};

}  // namespace granseg
