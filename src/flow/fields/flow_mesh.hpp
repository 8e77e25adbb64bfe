// The cells and faces the flow kernels loop over (docs/flow_solver.md Sect. 2): which cells are
// inside (grid.inside), which axes are active (more than one cell), what kind each face is
// (interior, wall below or above, none), where the cells of each row meet their neighbours, and
// the loops over rows of cells that the kernels share (rows among OpenMP threads, the cells of a
// row vectorised). Built once from the grid; every kernel takes it as a const input.
//
//   solves      nothing: the geometry and loops every flow kernel shares
//   inputs      a Grid (inside flags, periodic axes)
//   outputs     FlowMesh: inside cells, active axes, face kinds and lists, rows, the loops
//   invariants  built once and read only; a face is interior, a wall or none; on a wall both
//               cells of a MeshFace name the inside cell
//
// Rows: the ny * nz rows of cells along x, row r = j + ny k. An axis with one cell is inactive
// (the fields do not vary along it); a periodic axis joins its first and last layer.
#pragma once

#include "core/grid.hpp"
#include "core/threads.hpp"

#include <array>
#include <cstddef>
#include <vector>

namespace granseg {

/// Kind of a face: a wall below/above means the face is a wall and the inside cell is above/below it.
enum FaceKind : unsigned char { kNoFace = 0, kInterior, kWallBelow, kWallAbove };

/// Where the cells of one row meet their neighbours along one axis: cell i of the row has its
/// lower face at face0 + i and its upper face face_step further; its neighbour cells are
/// c + lo_at(i) and c + hi_at(i) (0 on a wall of the domain boundary, the partner cell on a
/// periodic boundary).
struct AxisRow {
    std::size_t face0, face_step;
    long lo, hi, first_lo, last_hi;
    int last;
    long lo_at(int i) const { return i == 0 ? first_lo : lo; }
    long hi_at(int i) const { return i == last ? last_hi : hi; }
};

/// A face of one axis with the cells on its two sides, lo below and hi above (on a wall both
/// name the inside cell, as the hydrostatic reconstruction and the mirror state expect).
struct MeshFace {
    std::size_t f, lo, hi;
    FaceKind kind;
    bool repeat;  // the last layer of a periodic axis: the same face as the first layer
};

struct FlowMesh {
    explicit FlowMesh(Grid grid);

    Grid grid;
    std::array<bool, 3> active{};                         // n[axis] > 1
    std::size_t rows = 0;                                 // ny * nz rows of cells along x
    bool parallel = false;                                // loops on the OpenMP threads (core/threads.hpp)
    std::vector<int> row_lo, row_hi;                      // inside cells of row r lie in [row_lo[r], row_hi[r])
    std::vector<unsigned char> inside;                    // 1 for inside cells (grid.inside or all)
    std::vector<std::size_t> inside_cells;                // their indices, in index order
    std::array<std::vector<unsigned char>, 3> face_kind;  // per axis and face: FaceKind
    std::array<std::vector<double>, 3> position;          // cell centres
    std::array<std::vector<MeshFace>, 3> faces;           // per axis: every interior and wall face

    /// The neighbours and faces of the cells of row r along `axis`.
    AxisRow axis_row(int axis, std::size_t row) const;

    /// Calls body(c, i, row) for every cell c = i + nx r of every row's inside range, rows shared
    /// among threads, the cells of a row vectorised (body masks outside cells itself).
    template <class Body>
    void parallel_for_row_cells(int axis, Body&& body) const {
        const std::size_t nx = grid.n[0];
        parallel_for(parallel, rows, [&](std::size_t r) {
            const AxisRow row = axis_row(axis, r);
#pragma omp simd
            for (int i = row_lo[r]; i < row_hi[r]; ++i) body(nx * r + i, i, row);
        });
    }

    /// Calls body(c, i, rows) for every inside cell, with the AxisRow of each axis in rows[3].
    template <class Body>
    void parallel_for_inside_cells(Body&& body) const {
        const std::size_t nx = grid.n[0];
        parallel_for(parallel, rows, [&](std::size_t r) {
            AxisRow ar[3];
            for (int a = 0; a < 3; ++a) ar[a] = axis_row(a, r);
            for (int i = row_lo[r]; i < row_hi[r]; ++i)
                if (inside[nx * r + i]) body(nx * r + i, i, ar);
        });
    }

    /// Calls body(face) for every interior and wall face of `axis` (a MeshFace), the list shared
    /// among threads.
    template <class Body>
    void parallel_for_faces(int axis, Body&& body) const {
        const std::vector<MeshFace>& list = faces[axis];
        parallel_for(parallel, static_cast<long>(list.size()), [&](long q) { body(list[q]); });
    }

    /// Calls body(c) for every inside cell, the list shared among threads.
    template <class Body>
    void parallel_for_inside(Body&& body) const {
        parallel_for(parallel, inside_cells.size(), [&](std::size_t q) { body(inside_cells[q]); });
    }
};

}  // namespace granseg
