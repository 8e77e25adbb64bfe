// Face fields on a Grid and the flux-differencing update of eq. (64), shared by the bulk
// transport and the segregation sub-step (and by anything else in conservative form).
//
// A face normal to `axis` lies between a lower and an upper cell along that axis. A face is a
// wall when a side is missing (a non-periodic domain boundary) or is an outside cell
// (Grid::inside == 0); the segregation fluxes vanish there. Eq. (64), for every inside cell,
//     u_i <- u_i - dt/h_axis (F[upper face] - F[lower face]),
// telescopes, so the sum of u over the inside cells changes only by the fluxes through open
// domain-boundary faces (none for walls, where F = 0).
#pragma once

#include "core/grid.hpp"

#include <array>
#include <cstddef>
#include <limits>
#include <vector>

namespace granseg {

/// One face field per axis (grid.faces(axis) values, grid.face_index order); an empty vector
/// means "nothing along this axis".
using FaceFields = std::array<std::vector<double>, 3>;

/// Marks a missing neighbour (non-periodic domain boundary).
constexpr std::size_t kNoCell = std::numeric_limits<std::size_t>::max();

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

/// Calls visit(FaceCells) for every face normal to `axis`, in face-index order. On a periodic
/// axis the first and last layer are the same physical face and both get the wrapped cells.
template <class Visit>
void for_each_face(const Grid& grid, int axis, Visit&& visit) {
    const int n = grid.n[axis];
    const std::size_t stride = grid.stride(axis);
    std::array<int, 3> c{0, 0, 0}, last = grid.n;
    last[axis] = n + 1;  // face layers 0..n along the axis
    for (c[2] = 0; c[2] < last[2]; ++c[2])
        for (c[1] = 0; c[1] < last[1]; ++c[1])
            for (c[0] = 0; c[0] < last[0]; ++c[0]) {
                const int layer = c[axis];
                std::array<int, 3> cell = c;
                cell[axis] = layer < n ? layer : 0;
                const std::size_t first = grid.index(cell[0], cell[1], cell[2]);  // cell `layer` (or 0)
                std::size_t lower = kNoCell, upper = kNoCell;
                if (layer > 0) lower = layer < n ? first - stride : first + (n - 1) * stride;
                if (layer < n) upper = first;
                if (grid.periodic[axis]) {
                    if (layer == 0) lower = first + (n - 1) * stride;
                    if (layer == n) upper = first;
                }
                visit(FaceCells{grid.face_index(axis, c[0], c[1], c[2]), lower, upper, grid.periodic[axis] && layer == n});
            }
}

/// Eq. (64) along `axis` in every inside cell: u -= dt/h_axis (F[upper face] - F[lower face]).
void apply_flux_difference(const Grid& grid, int axis, const std::vector<double>& F, double dt,
                           std::vector<double>& u);

/// The face field of arithmetic means (u_lower + u_upper)/2 of a cell field along `axis`;
/// on a wall face, the value of the inside neighbour (0 if there is none).
std::vector<double> arithmetic_mean_faces(const Grid& grid, int axis, const std::vector<double>& u);

}  // namespace granseg
