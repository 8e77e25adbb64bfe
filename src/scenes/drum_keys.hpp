// Keys the drum kinds read alike: the bounded rows of the scheme table, the shares of the
// [initial] section checked on the drum's bed cells, and the two names of the drum's rotation rate
// and fill (the kinematic drum's rotation_rate and fill_fraction, the coupled drum's rps and
// fill_height), each kind accepting both.
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

/// A [drum] key that has a second name in the other drum kind (docs/scenes.md): `key` if the file
/// has it (else `fallback`), or `other`, converted to `key`'s meaning by `to_key`. `other` is asked
/// for only when the file has it, so the resolved settings of a file that does not use it are as
/// before; a file with both names fails naming `other`.
double read_drum_key_or_other(const SceneFile& scene, const std::string& key, const Range& range, double fallback,
                              const std::string& other, const Range& other_range, const std::function<double(double)>& to_key);

/// Fails with "[initial] KEY: KEY = v at x = .., z = .. (allowed: `allowed`)" at the first bed cell
/// of `grid` (and of those `where` accepts, if given) at which share(x, z) lies outside [0, 1].
void require_share(const SceneFile& scene, const Grid& grid, const char* key, const std::function<double(double, double)>& share,
                   const std::string& allowed, const std::function<bool(std::size_t cell)>& where = {});

}  // namespace granseg
