// Face fields on a Grid (core/grid.hpp): per axis one value per face normal to it, in
// grid.face_index order, as the fluxes of every solver are stored.
#pragma once

#include <array>
#include <cstddef>
#include <limits>
#include <vector>

namespace granseg {

/// Marks a missing neighbour (a non-periodic domain boundary, or a wall).
constexpr std::size_t kNoCell = std::numeric_limits<std::size_t>::max();

/// One face field per axis (grid.faces(axis) values, grid.face_index order); an empty vector
/// means "nothing along this axis".
using FaceFields = std::array<std::vector<double>, 3>;

/// Read-only face fields, one pointer per axis (nullptr or an empty vector: nothing along that
/// axis), so that a solver's fields are read where they are, without a copy per step.
using FaceFieldRefs = std::array<const std::vector<double>*, 3>;
inline FaceFieldRefs refs(const FaceFields& f) { return {&f[0], &f[1], &f[2]}; }

}  // namespace granseg
