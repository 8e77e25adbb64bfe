// Data files compiled into the library (every src/**/*.dat, see the Makefile), so programs
// find them wherever they run.
#pragma once

#include <string_view>

namespace granseg {

/// Text of the embedded data file `name` (path relative to src/, e.g.
/// "closures/packing_binary_r2.dat"); throws InvariantError if there is none (a build error).
std::string_view embedded_file(std::string_view name);

}  // namespace granseg
