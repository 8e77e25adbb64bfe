#include "linalg/multilevel.hpp"

#include "core/threads.hpp"

#include <algorithm>
#include <cmath>
#include <map>

#include <cstdlib>

namespace granseg {

namespace {
/// A level with at most this many rows is solved directly: its dense factorisation (n^3/3
/// flops, once per matrix) costs about one sweep over the finest level of a 50-cell drum.
constexpr long kCoarsestRows = 40;
/// A colour of fewer rows is swept on one thread (on a grid that runs on threads, core/threads.hpp:
/// a loop over fewer than about 1,000 rows costs less than waking a second thread).
constexpr long kParallelRows = 1024;
/// A row with a_ii >= kDominance sum_{j != i} |a_ij| stays out of the coarse levels (header
/// comment). The factor hardly matters: the dust rows, which matter, have no coupling at all (the
/// values tried: docs/history.md, "Constants of the flow step").
constexpr double kDominance = 5.0;
/// Scale of the coarse correction, below sqrt(2) (header comment): piecewise-constant
/// prolongation makes the coarse corrections too small, and this factor buys back most of the
/// iterations they cost on finer grids (measured against 1.0 and 1.8: docs/history.md, "Constants
/// of the flow step").
constexpr double kOverCorrection = 1.4;

/// Calls body(begin, end) on blocks of [0, m): within a team (every thread of the team calls
/// this) each thread's share, the team waiting for all at the end (Team::share); else one block
/// per OpenMP thread where `parallel` and m >= kParallelRows, else one block on this thread
/// (outside an OpenMP region: a region costs about a microsecond on one thread too, and a W-cycle
/// passes many small levels).
template <class Body>
void for_rows(long m, bool parallel, Team* team, Body&& body) {
    if (team)
        team->share(m, body);
    else
        parallel_blocks(parallel && m >= kParallelRows, m, body);
}

/// b_r - sum_k a_rk x_k: the residual of row r of a compressed row-major matrix.
inline double row_residual(const Multilevel::Matrix& A, const double* b, const double* x, long r) {
    const int* outer = A.outerIndexPtr();
    const int* inner = A.innerIndexPtr();
    const double* a = A.valuePtr();
    double sum = b[r];
    for (int k = outer[r]; k < outer[r + 1]; ++k) sum -= a[k] * x[inner[k]];
    return sum;
}

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
        fine.joins.assign(n, 1.0);
        Level next;
        next.A = std::move(coarse);
        level_.push_back(std::move(next));
        at = std::move(coarse_at);
    }
    // Two visits of the coarse level (a W-cycle) below the finest level, where the coarse level
    // has at most a third of the rows (not in a column, where 1-D halving would make the work
    // n log n), not above the direct solve (a second exact solve only rescales the first), and
    // only where the over-correction keeps B positive definite (header comment): `bound` is an
    // upper bound of the eigenvalues of B A on the level below. The finest level is visited once:
    // a second visit costs a residual and two transfers over all cells, more than the
    // iterations it saves (measured on the drum: docs/history.md, "Constants of the flow step").
    double bound = 1.0;
    for (std::size_t l = level_.size() - 1; l-- > 0;) {
        Level& L = level_[l];
        const bool twice =
            l > 0 && l + 2 < level_.size() && 3 * level_[l + 1].A.rows() <= L.A.rows() && kOverCorrection * bound < 2.0;
        L.visits = twice ? 2 : 1;
        bound = twice ? 1.0 : std::max(1.0, kOverCorrection * bound);
    }
}

Multilevel& Multilevel::take_values(const double* value) {
    std::copy(value, value + level_[0].A.nonZeros(), level_[0].A.valuePtr());
    for (std::size_t l = 0; l + 1 < level_.size(); ++l) {
        Level& fine = level_[l];
        const long n = fine.A.rows();
        const int* outer = fine.A.outerIndexPtr();
        const int* inner = fine.A.innerIndexPtr();
        const double* a = fine.A.valuePtr();
        for (long r = 0; r < n; ++r) {
            double off = -std::fabs(a[fine.diagonal[r]]);
            for (int k = outer[r]; k < outer[r + 1]; ++k) off += std::fabs(a[k]);
            fine.joins[r] = a[fine.diagonal[r]] >= kDominance * off ? 0.0 : 1.0;
        }
        // A_c = P^T A P over the rows that join; a coarse row none joins gets a_II = 1 (its
        // right-hand side is always 0, so its value stays 0).
        Level& coarse = level_[l + 1];
        double* ac = coarse.A.valuePtr();
        std::fill(ac, ac + coarse.A.nonZeros(), 0.0);
        for (long r = 0; r < n; ++r)
            if (fine.joins[r] != 0.0)
                for (int k = outer[r]; k < outer[r + 1]; ++k) ac[fine.galerkin[k]] += fine.joins[inner[k]] * a[k];
        for (long R = 0; R < coarse.A.rows(); ++R)
            if (ac[coarse.diagonal[R]] == 0.0) ac[coarse.diagonal[R]] = 1.0;
    }
    coarsest_.compute(Eigen::MatrixXd(level_.back().A));
    return *this;
}

void Multilevel::sweep(const Level& L, bool backward, Team* team) const {
    const int colours = static_cast<int>(L.colour.size());
    const double* b = L.b.data();
    double* x = L.x.data();
    for (int q = 0; q < colours; ++q) {
        const std::vector<long>& rows = L.colour[backward ? colours - 1 - q : q];
        // From x = 0 (the forward sweep), the first colour's neighbours are all still 0.
        const bool alone = !backward && q == 0;
        for_rows(static_cast<long>(rows.size()), parallel_, team, [&, b, x](long begin, long end) {
            for (long s = begin; s < end; ++s) {
                const long r = rows[s];
                const double d = L.A.valuePtr()[L.diagonal[r]];
                x[r] = alone ? b[r] / d : x[r] + row_residual(L.A, b, x, r) / d;
            }
        });
    }
}

void Multilevel::restrict_residual(const Level& L, bool swept, Team* team) const {
    const int colours = static_cast<int>(L.colour.size());
    const double* b = L.b.data();
    const double* x = L.x.data();
    double* res = L.r.data();
    for (int q = 0; q < colours; ++q) {
        const std::vector<long>& rows = L.colour[q];
        const bool zero = swept && q == colours - 1;
        for_rows(static_cast<long>(rows.size()), parallel_, team, [&, b, x, res](long begin, long end) {
            for (long s = begin; s < end; ++s) {
                const long r = rows[s];
                res[r] = zero || L.joins[r] == 0.0 ? 0.0 : row_residual(L.A, b, x, r);
            }
        });
    }
}

void Multilevel::gather_residual(const Level& L, const Level& C) const {
    C.b.setZero();
    double* coarse = C.b.data();
    const double* res = L.r.data();
    for (long r = 0; r < L.A.rows(); ++r) coarse[L.aggregate[r]] += res[r];
}

void Multilevel::correct(const Level& L, const Level& C, Team* team) const {
    double* x = L.x.data();
    const double* xc = C.x.data();
    for_rows(L.A.rows(), parallel_, team, [&, x, xc](long begin, long end) {
        for (long r = begin; r < end; ++r) x[r] += kOverCorrection * L.joins[r] * xc[L.aggregate[r]];
    });
}

void Multilevel::cycle(std::size_t l) const {
    const Level& L = level_[l];
    if (l + 1 == level_.size()) {
        L.x = coarsest_.solve(L.b);
        return;
    }
    const Level& C = level_[l + 1];
    L.x.setZero();
    sweep(L, false, nullptr);
    for (int visit = 0; visit < L.visits; ++visit) {
        restrict_residual(L, visit == 0, nullptr);
        gather_residual(L, C);
        cycle(l + 1);
        correct(L, C, nullptr);
    }
    sweep(L, true, nullptr);
}

void Multilevel::team_cycle(Team& team, const double* b) const {
    const Level& L = level_[0];
    double* x = L.x.data();
    double* fine_b = L.b.data();
    team.share(L.A.rows(), [&, x, fine_b](long begin, long end) {
        for (long r = begin; r < end; ++r) fine_b[r] = b[r], x[r] = 0.0;
    });
    if (level_.size() == 1) {
        team.single([&] { L.x = coarsest_.solve(L.b); });
        return;
    }
    const Level& C = level_[1];
    sweep(L, false, &team);
    for (int visit = 0; visit < L.visits; ++visit) {
        restrict_residual(L, visit == 0, &team);
        // The coarse levels on one thread while the others wait.
        team.single([&] {
            gather_residual(L, C);
            cycle(1);
        });
        correct(L, C, &team);
    }
    sweep(L, true, &team);
}

const Multilevel::Vector& Multilevel::solve(const Vector& b) const {
    level_[0].b = b;
    cycle(0);
    return level_[0].x;
}

}  // namespace granseg
