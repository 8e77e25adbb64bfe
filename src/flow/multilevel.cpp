#include "flow/multilevel.hpp"

#include <algorithm>
#include <map>

namespace granseg {

namespace {
/// A level with at most this many rows is solved directly (a dense factorisation of 100 rows
/// costs less than one sweep over the finest level of a 50-cell drum, ~2 000 rows).
constexpr long kCoarsestRows = 100;
/// A colour of fewer rows is swept on one thread (FlowMesh's rule: a loop over fewer than 2 048
/// cells costs less than waking a second thread; a level of 2 048 rows has two colours of 1 024).
constexpr long kParallelRows = 1024;
/// Scale of the coarse correction (header comment). CG iterations to 1e-8 on the disc of
/// tests/test_multilevel.cpp at 50 / 100 / 200 cells: 16 / 23 / 32 with 1.0, 13 / 16 / 22 with
/// 1.3, 13 / 15 / 18 with 1.5, 13 / 15 / 16 with 1.7 and 1.8, 15 / 16 / 17 with 1.9.
constexpr double kOverCorrection = 1.8;

/// Value index of entry (row, col) of a compressed row-major matrix, -1 if not in the pattern.
long position(const Multilevel::Matrix& A, long row, long col) {
    const int* begin = A.innerIndexPtr() + A.outerIndexPtr()[row];
    const int* end = A.innerIndexPtr() + A.outerIndexPtr()[row + 1];
    const int* at = std::lower_bound(begin, end, static_cast<int>(col));
    return at != end && *at == col ? at - A.innerIndexPtr() : -1;
}

/// Greedy colouring in row order: each row takes the smallest colour none of its neighbours in
/// the pattern has taken (on a Cartesian stencil in grid order: red and black).
std::vector<std::vector<long>> colour_rows(const Multilevel::Matrix& A) {
    std::vector<int> colour(A.rows(), -1);
    std::vector<std::vector<long>> rows;
    for (long r = 0; r < A.rows(); ++r) {
        std::vector<bool> taken(rows.size() + 1, false);
        for (long k = A.outerIndexPtr()[r]; k < A.outerIndexPtr()[r + 1]; ++k) {
            const int c = colour[A.innerIndexPtr()[k]];
            if (c >= 0) taken[c] = true;
        }
        const int c = static_cast<int>(std::find(taken.begin(), taken.end(), false) - taken.begin());
        if (c == static_cast<int>(rows.size())) rows.emplace_back();
        colour[r] = c;
        rows[c].push_back(r);
    }
    return rows;
}
}  // namespace

void Multilevel::build(const Matrix& pattern, const std::vector<std::array<int, 3>>& cell, bool parallel) {
    parallel_ = parallel;
    level_.clear();
    level_.emplace_back();
    level_[0].A = pattern;
    level_[0].A.makeCompressed();
    std::vector<std::array<int, 3>> at = cell;
    for (;;) {
        Level& fine = level_.back();
        const long n = fine.A.rows();
        fine.diagonal.resize(n);
        for (long r = 0; r < n; ++r) fine.diagonal[r] = position(fine.A, r, r);
        fine.colour = colour_rows(fine.A);
        fine.x.setZero(n), fine.r.setZero(n), fine.b.setZero(n);
        if (n <= kCoarsestRows) break;
        // Coarse cells: the 2 x 2 x 2 blocks that hold a fine row, numbered in grid order (z, y, x
        // lexicographic, so that the greedy colouring of the coarse grid is red-black again).
        std::map<std::array<int, 3>, long> block;
        for (const auto& c : at) block.emplace(std::array<int, 3>{c[2] / 2, c[1] / 2, c[0] / 2}, 0L);
        if (static_cast<long>(block.size()) == n) break;  // nothing to aggregate
        std::vector<std::array<int, 3>> coarse_at;
        for (auto& [key, id] : block) {
            id = static_cast<long>(coarse_at.size());
            coarse_at.push_back({key[2], key[1], key[0]});
        }
        fine.aggregate.resize(n);
        for (long r = 0; r < n; ++r) fine.aggregate[r] = block.at({at[r][2] / 2, at[r][1] / 2, at[r][0] / 2});
        std::vector<Eigen::Triplet<double>> entries;
        for (long r = 0; r < n; ++r)
            for (long k = fine.A.outerIndexPtr()[r]; k < fine.A.outerIndexPtr()[r + 1]; ++k)
                entries.emplace_back(fine.aggregate[r], fine.aggregate[fine.A.innerIndexPtr()[k]], 0.0);
        Matrix coarse(static_cast<long>(coarse_at.size()), static_cast<long>(coarse_at.size()));
        coarse.setFromTriplets(entries.begin(), entries.end());
        coarse.makeCompressed();
        fine.galerkin.resize(fine.A.nonZeros());
        for (long r = 0; r < n; ++r)
            for (long k = fine.A.outerIndexPtr()[r]; k < fine.A.outerIndexPtr()[r + 1]; ++k)
                fine.galerkin[k] = position(coarse, fine.aggregate[r], fine.aggregate[fine.A.innerIndexPtr()[k]]);
        Level next;
        next.A = std::move(coarse);
        level_.push_back(std::move(next));
        at = std::move(coarse_at);
    }
}

Multilevel& Multilevel::take_values(const double* value) {
    std::copy(value, value + level_[0].A.nonZeros(), level_[0].A.valuePtr());
    for (std::size_t l = 0; l + 1 < level_.size(); ++l) {
        const Level& fine = level_[l];
        Matrix& coarse = level_[l + 1].A;
        std::fill(coarse.valuePtr(), coarse.valuePtr() + coarse.nonZeros(), 0.0);
        for (long k = 0; k < fine.A.nonZeros(); ++k) coarse.valuePtr()[fine.galerkin[k]] += fine.A.valuePtr()[k];
    }
    coarsest_.compute(Eigen::MatrixXd(level_.back().A));
    return *this;
}

void Multilevel::sweep(const Level& L, bool backward) const {
    const int colours = static_cast<int>(L.colour.size());
    const int* outer = L.A.outerIndexPtr();
    const int* inner = L.A.innerIndexPtr();
    const double* a = L.A.valuePtr();
    for (int q = 0; q < colours; ++q) {
        const std::vector<long>& rows = L.colour[backward ? colours - 1 - q : q];
        const long m = static_cast<long>(rows.size());
#pragma omp parallel for schedule(static) if (parallel_ && m >= kParallelRows)
        for (long s = 0; s < m; ++s) {
            const long r = rows[s];
            double sum = L.b[r];
            for (int k = outer[r]; k < outer[r + 1]; ++k) sum -= a[k] * L.x[inner[k]];
            L.x[r] += sum / a[L.diagonal[r]];
        }
    }
}

void Multilevel::cycle(std::size_t l) const {
    const Level& L = level_[l];
    if (l + 1 == level_.size()) {
        L.x = coarsest_.solve(L.b);
        return;
    }
    const Level& C = level_[l + 1];
    L.x.setZero();
    sweep(L, false);
    L.r.noalias() = L.b - L.A * L.x;
    C.b.setZero();
    for (long r = 0; r < L.A.rows(); ++r) C.b[L.aggregate[r]] += L.r[r];  // P^T r
    cycle(l + 1);
    for (long r = 0; r < L.A.rows(); ++r) L.x[r] += kOverCorrection * C.x[L.aggregate[r]];
    sweep(L, true);
}

Multilevel::Vector Multilevel::solve(const Vector& b) const {
    level_[0].b = b;
    cycle(0);
    return level_[0].x;
}

}  // namespace granseg
