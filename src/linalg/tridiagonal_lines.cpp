#include "linalg/tridiagonal_lines.hpp"

#include "core/error.hpp"
#include "core/threads.hpp"

#include <algorithm>

namespace granseg {

namespace {

/// The lines along `axis`: line (o, q) starts at cell o*outer + q*inner and steps by `step`;
/// q is the innermost loop (contiguous in memory for the y and z axes).
struct LineLayout {
    std::size_t outer, inner, n_outer, n_inner, step;
    int n;
};

LineLayout layout(const Grid& g, int axis) {
    const std::size_t nx = g.n[0], ny = g.n[1], nz = g.n[2];
    if (axis == 0) return {0, nx, 1, ny * nz, 1, g.n[0]};
    if (axis == 1) return {nx * ny, 1, nz, nx, nx, g.n[1]};
    return {nx, 1, ny, nx, nx * ny, g.n[2]};
}

// Lines are processed in blocks of kBlock (vectorised across a block, blocks across threads).
constexpr std::size_t kBlock = 64;

}  // namespace

// Thomas factorisation of the tridiagonal part. A cyclic line takes the Numerical Recipes choice
// gamma = -diag[0], which changes the first and the last pivot, and gets the correction vector
// (gamma, 0, ..., 0, alpha) with alpha = -upper[n-1] (the coupling of cell n-1 to cell 0);
// beta = -lower[0] couples cell 0 to cell n-1.
void TridiagonalLines::factor(const Grid& grid, int axis, const std::vector<double>& lower, const std::vector<double>& diag,
                              const std::vector<double>& upper) {
    grid_ = &grid;
    axis_ = axis;
    const LineLayout L = layout(grid, axis);
    if (L.n < 2) throw InputError("TridiagonalLines: axis with fewer than 2 cells");
    cyclic_ = grid.periodic[axis] && L.n >= 3;
    const bool merged = grid.periodic[axis] && L.n == 2;  // both faces join the same two cells
    const std::size_t cells = grid.cells(), lines = L.n_outer * L.n_inner;
    lower_.resize(cells);
    inv_pivot_.resize(cells);
    ratio_.resize(cells);
    if (cyclic_) corner_lo_.resize(lines), denom_.resize(lines), z_.resize(cells);
    const std::size_t last = static_cast<std::size_t>(L.n - 1) * L.step, blocks = (L.n_inner + kBlock - 1) / kBlock;
    parallel_for_pairs(parallel_, L.n_outer, blocks, [&](std::size_t o, std::size_t b) {
        const std::size_t q0 = b * kBlock, q1 = std::min(L.n_inner, q0 + kBlock);
        for (int m = 0; m < L.n; ++m) {
            const std::size_t row = o * L.outer + m * L.step;
            const bool first = m == 0, end = m == L.n - 1;
#pragma omp simd
            for (std::size_t q = q0; q < q1; ++q) {
                const std::size_t c = row + q * L.inner, base = c - m * L.step;
                double l = first ? 0.0 : lower[c];
                double u = end ? 0.0 : upper[c];
                double d = diag[c];
                if (merged) {
                    if (first)
                        u += lower[c];
                    else
                        l += upper[c];
                }
                if (cyclic_ && first) d *= 2.0;
                if (cyclic_ && end) d += upper[c] * lower[base] / diag[base];
                const double prev_ratio = first ? 0.0 : ratio_[c - L.step];
                const double w = 1.0 / (d - l * prev_ratio);
                lower_[c] = l;
                inv_pivot_[c] = w;
                ratio_[c] = u * w;
            }
        }
        if (!cyclic_) return;
        for (std::size_t q = q0; q < q1; ++q) {
            const std::size_t base = o * L.outer + q * L.inner, line = o * L.n_inner + q;
            for (int m = 0; m < L.n; ++m) z_[base + m * L.step] = 0.0;
            corner_lo_[line] = lower[base];
            z_[base] = -diag[base];
            z_[base + last] = -upper[base + last];
        }
        sweep(z_.data(), o, q0, q1);
        for (std::size_t q = q0; q < q1; ++q) {
            const std::size_t base = o * L.outer + q * L.inner, line = o * L.n_inner + q;
            const double kappa = corner_lo_[line] / diag[base];  // beta / gamma
            denom_[line] = 1.0 + z_[base] + kappa * z_[base + last];
            corner_lo_[line] = kappa;
        }
    });
}

void TridiagonalLines::sweep(double* x, std::size_t o, std::size_t q0, std::size_t q1) const {
    const LineLayout L = layout(*grid_, axis_);
    const std::size_t first = o * L.outer;
#pragma omp simd
    for (std::size_t q = q0; q < q1; ++q) x[first + q * L.inner] *= inv_pivot_[first + q * L.inner];
    for (int m = 1; m < L.n; ++m) {  // forward elimination
        const std::size_t row = first + m * L.step;
#pragma omp simd
        for (std::size_t q = q0; q < q1; ++q) {
            const std::size_t c = row + q * L.inner;
            x[c] = (x[c] + lower_[c] * x[c - L.step]) * inv_pivot_[c];
        }
    }
    for (int m = L.n - 2; m >= 0; --m) {  // back substitution
        const std::size_t row = first + m * L.step;
#pragma omp simd
        for (std::size_t q = q0; q < q1; ++q) {
            const std::size_t c = row + q * L.inner;
            x[c] += ratio_[c] * x[c + L.step];
        }
    }
}

void TridiagonalLines::solve(std::vector<double>& x) const {
    const LineLayout L = layout(*grid_, axis_);
    const std::size_t last = static_cast<std::size_t>(L.n - 1) * L.step, blocks = (L.n_inner + kBlock - 1) / kBlock;
    double* data = x.data();
    parallel_for_pairs(parallel_, L.n_outer, blocks, [&](std::size_t o, std::size_t b) {
        const std::size_t q0 = b * kBlock, q1 = std::min(L.n_inner, q0 + kBlock);
        sweep(data, o, q0, q1);
        if (!cyclic_) return;
        for (std::size_t q = q0; q < q1; ++q) {  // Sherman-Morrison correction
            const std::size_t base = o * L.outer + q * L.inner, line = o * L.n_inner + q;
            const double fact = (data[base] + corner_lo_[line] * data[base + last]) / denom_[line];
            for (int m = 0; m < L.n; ++m) data[base + m * L.step] -= fact * z_[base + m * L.step];
        }
    });
}

}  // namespace granseg
