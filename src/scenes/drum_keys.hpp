// Keys the drum kinds that segregate (tumbler, tumbler-kinematic) read alike: the bounded rows of
// the scheme table, and the shares of the [initial] section checked on the drum's bed cells.
#pragma once

#include "core/grid.hpp"
#include "run/scene_file.hpp"
#include "segregation/segregation_solver.hpp"

#include <functional>
#include <string>

namespace granseg {

/// [segregation] scheme and limiter of a kind that checks 0 <= phi <= Phi while it runs: an
/// unbounded row of the scheme table (classic, Rusanov) fails naming the bounded ones.
void read_bounded_scheme(const SceneFile& scene, SegregationOptions& options);

/// Fails with "[initial] KEY: KEY = v at x = .., z = .. (allowed: `allowed`)" at the first bed cell
/// of `grid` (and of those `where` accepts, if given) at which share(x, z) lies outside [0, 1].
void require_share(const SceneFile& scene, const Grid& grid, const char* key, const std::function<double(double, double)>& share,
                   const std::string& allowed, const std::function<bool(std::size_t cell)>& where = {});

}  // namespace granseg
