// Face fields on a Grid and the flux-differencing update of eq. (64), shared by the bulk
// transport and the segregation sub-step (and by anything else in conservative form).
//
//   solves      the update of eq. (64), u_i <- u_i - dt/h (F_upper - F_lower), along one axis
//   inputs      the grid, F on every face normal to the axis, dt, u
//   outputs     u in every inside cell
//   invariants  the sum of u over the inside cells changes only through open domain-boundary faces
//
// A face normal to `axis` lies between a lower and an upper cell along that axis. A face is a
// wall when a side is missing (a non-periodic domain boundary) or is an outside cell
// (Grid::inside == 0); the segregation fluxes vanish there. Eq. (64), for every inside cell,
//     u_i <- u_i - dt/h_axis (F[upper face] - F[lower face]),
// telescopes, so the sum of u over the inside cells changes only by the fluxes through open
// domain-boundary faces (none for walls, where F = 0).
#pragma once

#include "core/face_fields.hpp"
#include "core/grid.hpp"

#include <array>
#include <cstddef>
#include <vector>

namespace granseg {

/// A face and the cells below and above it along its axis (kNoCell at a domain boundary).
/// `duplicate` marks the last face layer of a periodic axis, the same physical face as layer 0.
struct FaceCells {
    std::size_t face, lower, upper;
    bool duplicate;
};

/// True if material can cross the face: both neighbours exist and are inside cells.
inline bool is_open_face(const Grid& grid, const FaceCells& f) {
    return f.lower != kNoCell && f.upper != kNoCell && grid.is_inside(f.lower) && grid.is_inside(f.upper);
}

/// Calls line(first_cell, first_face) for every line of cells along `axis`: the cell and the
/// face with axis coordinate 0; the next ones follow at grid.stride(axis), grid.face_stride(axis).
template <class Line>
void for_each_line(const Grid& grid, int axis, Line&& line) {
    const int a = axis == 0 ? 1 : 0, b = axis == 2 ? 1 : 2;  // the two other axes
    std::array<int, 3> c{0, 0, 0};
    for (c[b] = 0; c[b] < grid.n[b]; ++c[b])
        for (c[a] = 0; c[a] < grid.n[a]; ++c[a]) {
            c[axis] = 0;
            line(grid.index(c[0], c[1], c[2]), grid.face_index(axis, c[0], c[1], c[2]));
        }
}

/// Calls visit(FaceCells) for every face normal to `axis`, line by line. On a periodic axis the
/// first and last face layer are the same physical face and both get the wrapped cells.
template <class Visit>
void for_each_face(const Grid& grid, int axis, Visit&& visit) {
    const std::size_t n = static_cast<std::size_t>(grid.n[axis]);
    const std::size_t stride = grid.stride(axis), face_stride = grid.face_stride(axis);
    const bool periodic = grid.periodic[axis];
    for_each_line(grid, axis, [&](std::size_t cell0, std::size_t face0) {
        const std::size_t last = cell0 + (n - 1) * stride;
        visit(FaceCells{face0, periodic ? last : kNoCell, cell0, false});
        for (std::size_t l = 1; l < n; ++l) {
            const std::size_t upper = cell0 + l * stride;
            visit(FaceCells{face0 + l * face_stride, upper - stride, upper, false});
        }
        visit(FaceCells{face0 + n * face_stride, last, periodic ? cell0 : kNoCell, periodic});
    });
}

/// Eq. (64) along `axis` in every inside cell: u -= dt/h_axis (F[upper face] - F[lower face]).
void apply_flux_difference(const Grid& grid, int axis, const std::vector<double>& F, double dt, std::vector<double>& u);

/// The face field of arithmetic means (u_lower + u_upper)/2 of a cell field along `axis`;
/// on a wall face, the value of the inside neighbour (0 if there is none).
std::vector<double> arithmetic_mean_faces(const Grid& grid, int axis, const std::vector<double>& u);

}  // namespace granseg
