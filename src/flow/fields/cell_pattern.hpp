// The sparsity pattern of the implicit cell systems of the flow solver.
//
//   solves      nothing: numbers the unknowns and locates every entry of the matrix's values
//   inputs      a FlowMesh (once)
//   outputs     cell -> row, the value index of every diagonal and of each face's two entries
//   invariants  one row per inside cell, symmetric: a face's two off-diagonal entries are set
//               together (couple())
//
// Shared by the pressure
// equation, flow/pressure/pressure_solver.hpp, and the coupled viscosity, flow/diffusion/coupled_viscosity.hpp): one
// row per inside cell, an entry on the diagonal and one for each pair of cells meeting at an
// interior face (a weighted graph Laplacian plus a diagonal), built once per mesh with zero values;
// and where each row's diagonal and each face's two off-diagonal entries sit in the value array, so
// that the values can be rewritten every step without touching the pattern.
#pragma once

#include "flow/fields/flow_mesh.hpp"

#include <Eigen/SparseCore>

#include <array>
#include <vector>

namespace granseg {

template <class Matrix>
struct CellPattern {
    std::vector<long> unknown;                // grid cell -> row (-1 outside)
    std::array<std::vector<long>, 3> entry;   // per axis and interior face: value index of (lo, hi), or -1
    std::array<std::vector<long>, 3> mirror;  // and of (hi, lo)
    std::vector<long> diagonal;               // value index of each row's diagonal
    Matrix matrix;                            // the pattern, compressed (values 0 until a user writes them)

    /// Adds the weight w of the interior face f of `axis` between its two cells to the values of
    /// `matrix` (value = matrix.valuePtr()): +w on both diagonals, -w on both off-diagonal entries.
    void couple(double* value, int axis, const MeshFace& f, double w) const {
        value[diagonal[unknown[f.lo]]] += w;
        value[diagonal[unknown[f.hi]]] += w;
        value[entry[axis][f.f]] -= w;
        value[mirror[axis][f.f]] -= w;
    }
};

/// The pattern of `mesh` in a sparse matrix of type Matrix (row- or column-major).
template <class Matrix>
CellPattern<Matrix> cell_pattern(const FlowMesh& mesh) {
    CellPattern<Matrix> p;
    const Grid& grid = mesh.grid;
    p.unknown.assign(grid.cells(), -1);
    long rows = 0;
    for (std::size_t c : mesh.inside_cells) p.unknown[c] = rows++;
    std::vector<Eigen::Triplet<double>> pattern;
    for (long r = 0; r < rows; ++r) pattern.emplace_back(r, r, 0.0);
    for (int a = 0; a < 3; ++a)
        for (const MeshFace& f : mesh.faces[a])
            if (f.kind == kInterior && !f.repeat) {
                pattern.emplace_back(p.unknown[f.lo], p.unknown[f.hi], 0.0);
                pattern.emplace_back(p.unknown[f.hi], p.unknown[f.lo], 0.0);
            }
    p.matrix.resize(rows, rows);
    p.matrix.setFromTriplets(pattern.begin(), pattern.end());
    p.matrix.makeCompressed();
    const Matrix& m = p.matrix;
    auto position = [&m](long row, long col) {
        const long outer = Matrix::IsRowMajor ? row : col, inner = Matrix::IsRowMajor ? col : row;
        for (long k = m.outerIndexPtr()[outer]; k < m.outerIndexPtr()[outer + 1]; ++k)
            if (m.innerIndexPtr()[k] == inner) return k;
        return -1L;
    };
    p.diagonal.resize(rows);
    for (long r = 0; r < rows; ++r) p.diagonal[r] = position(r, r);
    for (int a = 0; a < 3; ++a) {
        p.entry[a].assign(grid.faces(a), -1);
        p.mirror[a].assign(grid.faces(a), -1);
        for (const MeshFace& f : mesh.faces[a])
            if (f.kind == kInterior && !f.repeat) {
                p.entry[a][f.f] = position(p.unknown[f.lo], p.unknown[f.hi]);
                p.mirror[a][f.f] = position(p.unknown[f.hi], p.unknown[f.lo]);
            }
    }
    return p;
}

}  // namespace granseg
