#include "transport/muscl_hancock.hpp"

#include "core/error.hpp"
#include "core/threads.hpp"

#include <algorithm>

namespace granseg {

MusclHancock::MusclHancock(const Grid& grid, Limiter limiter)
    : h_(grid.h), limiter_(limiter), parallel_(threads_pay(grid.cells())) {
    for (int a = 0; a < 3; ++a) {
        active_[a] = grid.n[a] > 1;
        if (active_[a]) from_lower_[a].assign(grid.faces(a), 0.0), from_upper_[a].assign(grid.faces(a), 0.0);
    }
    for (int k = 0; k < grid.n[2]; ++k)
        for (int j = 0; j < grid.n[1]; ++j)
            for (int i = 0; i < grid.n[0]; ++i) {
                const std::size_t c = grid.index(i, j, k);
                if (!grid.is_inside(c)) continue;
                Cell cell{c, {}, {}, {}, {}, {}, {}};
                const int at[3] = {i, j, k};
                for (int a = 0; a < 3; ++a) {
                    cell.below[a] = cell.above[a] = cell.lower_alias[a] = cell.upper_alias[a] = kNoCell;
                    cell.lower_face[a] = grid.face_index(a, i, j, k);
                    cell.upper_face[a] = cell.lower_face[a] + grid.face_stride(a);
                    if (!active_[a]) continue;
                    const int n = grid.n[a], l = at[a];
                    const std::size_t stride = grid.stride(a), wrap = (n - 1) * stride, faces = n * grid.face_stride(a);
                    const bool periodic = grid.periodic[a];
                    std::size_t below = l > 0 ? c - stride : periodic ? c + wrap : kNoCell;
                    std::size_t above = l < n - 1 ? c + stride : periodic ? c - wrap : kNoCell;
                    cell.below[a] = below != kNoCell && grid.is_inside(below) ? below : kNoCell;
                    cell.above[a] = above != kNoCell && grid.is_inside(above) ? above : kNoCell;
                    if (periodic && l == 0) cell.lower_alias[a] = cell.lower_face[a] + faces;
                    if (periodic && l == n - 1) cell.upper_alias[a] = cell.upper_face[a] - faces;
                }
                cells_.push_back(cell);
            }
}

void MusclHancock::face_values(const std::vector<double>& q, const FaceFieldRefs& U, double dt, Form form) {
    for (int a = 0; a < 3; ++a)
        if (active_[a] && (U[a] == nullptr || U[a]->size() != from_lower_[a].size()))
            throw InvariantError("MUSCL-Hancock: a face velocity field of the wrong size");
    const double* field = q.data();
    const double* velocity[3] = {active_[0] ? U[0]->data() : nullptr, active_[1] ? U[1]->data() : nullptr,
                                 active_[2] ? U[2]->data() : nullptr};
    double* lower[3] = {from_lower_[0].data(), from_lower_[1].data(), from_lower_[2].data()};
    double* upper[3] = {from_upper_[0].data(), from_upper_[1].data(), from_upper_[2].data()};
    const bool conservative = form == Form::conservative;
    parallel_for(parallel_, cells_.size(), [&](std::size_t p) {
        const Cell& cell = cells_[p];
        const double qc = field[cell.c];
        double slope[3] = {0.0, 0.0, 0.0}, lowest = qc, highest = qc, rate = 0.0;
        for (int a = 0; a < 3; ++a) {
            if (!active_[a]) continue;
            const std::size_t b = cell.below[a], t = cell.above[a];
            if (b != kNoCell) lowest = std::min(lowest, field[b]), highest = std::max(highest, field[b]);
            if (t != kNoCell) lowest = std::min(lowest, field[t]), highest = std::max(highest, field[t]);
            if (b != kNoCell && t != kNoCell) slope[a] = limited_slope(qc - field[b], field[t] - qc, limiter_);
            const double U_lo = velocity[a][cell.lower_face[a]], U_hi = velocity[a][cell.upper_face[a]];
            rate +=
                (conservative ? U_hi * (qc + 0.5 * slope[a]) - U_lo * (qc - 0.5 * slope[a]) : 0.5 * (U_lo + U_hi) * slope[a]) /
                h_[a];
        }
        const double half_step = qc - 0.5 * dt * rate;  // q half-way through the step
        for (int a = 0; a < 3; ++a) {
            if (!active_[a]) continue;
            const double up = std::clamp(half_step + 0.5 * slope[a], lowest, highest);
            const double down = std::clamp(half_step - 0.5 * slope[a], lowest, highest);
            lower[a][cell.upper_face[a]] = up;
            upper[a][cell.lower_face[a]] = down;
            if (cell.upper_alias[a] != kNoCell) lower[a][cell.upper_alias[a]] = up;
            if (cell.lower_alias[a] != kNoCell) upper[a][cell.lower_alias[a]] = down;
        }
    });
}

}  // namespace granseg
