// The uniform Cartesian grid shared by every solver (segregation, flow, tumbler), so fields from
// one can be handed to another without conversion.
//
// Axes x, y, z with z pointing up (gravity along -z in every built-in scene):
//   1-D columns use nz cells along z (nx = ny = 1), as in eqs. (49) and (66);
//   2-D problems use the x-z plane (ny = 1), e.g. the chute and the drum cross-section;
//   a thin 3-D slab adds a few periodic cells along y (the drum axis).
// Cell (i, j, k) has linear index i + nx*(j + ny*k); fields are std::vector<double> in that order.
// Embedded walls: a cell whose `inside` flag is 0 holds no material; faces between an inside
// and an outside cell, and faces on a non-periodic domain boundary, are walls.
// Face fields (fluxes): the faces normal to `axis` form a grid with n[axis] + 1 layers along that
// axis; face_index(axis, i, j, k) is the lower face of cell (i, j, k) along `axis` and the upper
// face is the lower face of the next cell (index + face_stride(axis)). On a periodic axis the
// last layer is the same physical face as the first and must hold the same value.
#pragma once

#include <array>
#include <cstddef>
#include <vector>

namespace granseg {

struct Grid {
    std::array<int, 3> n{1, 1, 1};                // cells per axis
    std::array<double, 3> h{1.0, 1.0, 1.0};       // cell size per axis
    std::array<double, 3> origin{0.0, 0.0, 0.0};  // lower corner of the domain
    std::array<bool, 3> periodic{false, false, false};
    std::vector<unsigned char> inside;  // one flag per cell; empty means all inside

    /// A 1-D column of `nz` cells on [0, length] along z.
    static Grid column(int nz, double length);
    /// A 2-D grid of nx x nz cells covering [x0, x0+lx] x [z0, z0+lz] in the x-z plane.
    static Grid plane_xz(int nx, int nz, double x0, double z0, double lx, double lz);

    std::size_t cells() const { return static_cast<std::size_t>(n[0]) * n[1] * n[2]; }
    std::size_t index(int i, int j, int k) const {
        return static_cast<std::size_t>(i) + static_cast<std::size_t>(n[0]) * (j + static_cast<std::size_t>(n[1]) * k);
    }
    /// Cell-centre coordinate along `axis` of the cell with index `i` on that axis.
    double center(int axis, int i) const { return origin[axis] + (i + 0.5) * h[axis]; }
    /// Stride of the linear index along `axis` (1, nx or nx*ny).
    std::size_t stride(int axis) const {
        return axis == 0 ? 1 : axis == 1 ? static_cast<std::size_t>(n[0]) : static_cast<std::size_t>(n[0]) * n[1];
    }
    bool is_inside(std::size_t cell) const { return inside.empty() || inside[cell] != 0; }
    /// Number of inside cells.
    std::size_t inside_cells() const {
        std::size_t count = 0;
        for (std::size_t c = 0; c < cells(); ++c) count += is_inside(c);
        return count;
    }
    /// Number of faces normal to `axis`.
    std::size_t faces(int axis) const { return cells() / n[axis] * (n[axis] + 1); }
    /// Index of the lower face along `axis` of cell (i, j, k) in a face field of that axis.
    std::size_t face_index(int axis, int i, int j, int k) const {
        const std::size_t m0 = n[0] + (axis == 0), m1 = n[1] + (axis == 1);
        return static_cast<std::size_t>(i) + m0 * (j + m1 * static_cast<std::size_t>(k));
    }
    /// Step in a face field of `axis` from the lower to the upper face of a cell.
    std::size_t face_stride(int axis) const {
        return axis == 0 ? 1 : axis == 1 ? static_cast<std::size_t>(n[0]) : static_cast<std::size_t>(n[0]) * (n[1]);
    }
    /// Volume of one cell (h_x h_y h_z).
    double cell_volume() const { return h[0] * h[1] * h[2]; }
};

/// A bed cell (an inside cell) of an x-z plane grid: its linear index, column i, layer k, centre.
struct BedCell {
    std::size_t c;
    int i, k;
    double x, z;
};

/// Calls visit(const BedCell&) for every inside cell of an x-z plane grid (ny = 1), layer by
/// layer from the bottom, each layer in increasing x: the order of the linear index.
template <class Visit>
void for_each_bed_cell(const Grid& grid, Visit&& visit) {
    for (int k = 0; k < grid.n[2]; ++k)
        for (int i = 0; i < grid.n[0]; ++i) {
            const std::size_t c = grid.index(i, 0, k);
            if (grid.is_inside(c)) visit(BedCell{c, i, k, grid.center(0, i), grid.center(2, k)});
        }
}

}  // namespace granseg
