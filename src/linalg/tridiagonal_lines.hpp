// Batched tridiagonal solves along every grid line of one axis.
//
//   solves      diag x - lower x[-s] - upper x[+s] = rhs on every line of one axis (cyclic on a
//               periodic axis)
//   inputs      lower, diag, upper per cell (once per factor()), right-hand sides
//   outputs     the solutions, overwriting the right-hand sides
//   invariants  no pivoting: diag >= lower + upper (an M-matrix)
//
// Used by the implicit, dimension-split (Lie/ADI) viscosity and conduction steps of the flow solver (docs/flow_solver_choices.md,
// "The explicit step").
//
// Along a line with cells 0..n-1 the system is
//     diag[c] x[c] - lower[c] x[c - s] - upper[c] x[c + s] = rhs[c]      (s: stride of the axis)
// with lower, upper >= 0 and diag >= lower + upper (an M-matrix), so the Thomas recursion needs
// no pivoting and a non-negative right-hand side gives a non-negative solution. On a periodic axis
// the first cell's `lower` couples to the last cell and the last cell's `upper` to the first; the
// cyclic system is solved with the Sherman-Morrison correction (Numerical Recipes, Sect. 2.7).
// Coefficients are one value per grid cell, in grid index order (core/grid.hpp).
#pragma once

#include "core/grid.hpp"

#include <vector>

namespace granseg {

class TridiagonalLines {
public:
    /// Factorises the systems of every line along `axis` (an axis with n[axis] >= 2).
    void factor(const Grid& grid, int axis, const std::vector<double>& lower, const std::vector<double>& diag,
                const std::vector<double>& upper);
    /// Overwrites x (the right-hand side on entry) with the solution; any number of calls per factor().
    void solve(std::vector<double>& x) const;
    /// Whether blocks of lines are shared among OpenMP threads (worth it on larger grids only).
    void set_parallel(bool parallel) { parallel_ = parallel; }

private:
    /// Thomas forward elimination and back substitution of the lines q0 <= q < q1 of block o.
    void sweep(double* x, std::size_t o, std::size_t q0, std::size_t q1) const;
    const Grid* grid_ = nullptr;
    int axis_ = 0;
    bool cyclic_ = false, parallel_ = false;
    std::vector<double> lower_, inv_pivot_, ratio_;  // Thomas: 1/pivot and upper/pivot per cell
    std::vector<double> z_;                          // cyclic: solution for the correction vector
    std::vector<double> corner_lo_, denom_;          // cyclic: beta/gamma and the Sherman-Morrison denominator per line
};

}  // namespace granseg
