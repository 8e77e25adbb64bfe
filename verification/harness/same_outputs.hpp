// Whether two runs wrote the same files: every file of one output directory byte-identical to the
// other's, but for the columns that time the run (a resumed run's checks, verify_resume and
// tests/run/run_checkpoints.cpp).
#pragma once

#include <string>
#include <vector>

namespace granseg::verify {

/// A data file's column that times the run (wall_seconds, cpu_seconds, seconds_*): a resumed run
/// spends other seconds on the same steps.
bool timing_column(const std::string& name);

/// Regular files below `dir`, every one (0 if it does not exist).
long files_below(const std::string& dir);

/// The files of directory `a` and `b` (recursively, the checkpoint.gsc files left out) that
/// differ, one line each ("history.dat: line 12 differs", "vtk/x.vtk: only in b"): empty if every
/// file is byte-identical, or differs in the values of timing columns only (a table's rows are
/// compared value by value; the column line and the comments must be equal). `files`: how many
/// files `a` holds.
std::vector<std::string> differing_outputs(const std::string& a, const std::string& b, long* files = nullptr);

}  // namespace granseg::verify
