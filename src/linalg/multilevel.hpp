// A multilevel preconditioner for the conjugate gradients of the pressure solve.
//
//   solves      nothing exactly: one cycle z = B b approximates A^-1 b, with B fixed,
//               symmetric and positive definite, so that plain conjugate gradients may use it
//   inputs      the sparsity pattern and the grid coordinates of its rows (once); the values of
//               a matrix A = D + K of that pattern (per Newton step); a right-hand side b
//   outputs     z = B b
//   invariants  every level is again a diagonal plus a weighted graph Laplacian; new values
//               re-add sums along maps built once, without allocation
//
// Used by the pressure solve (flow/pressure/pressure_solver.hpp, docs/flow_solver.md Sect. 2, pressure_solve): symmetric positive
// definite matrices A = D + K on the cells of a Cartesian grid (D >= 0 diagonal, K a weighted graph Laplacian with faces of
// weight 0, the inside cells of a drum an irregular part of the grid).
//
// The choice (docs/flow_solver.md Sect. 2, pressure_solve, "The multilevel preconditioner"):
// * Aggregation: the cells of each 2 x 2 (x 2) block of the grid form one coarse cell (on the
//   coarse grid again, level by level), whatever the mask; the prolongation P is piecewise
//   constant, so the coarse matrix is the Galerkin product A_c = P^T A P, formed from the actual
//   fine matrix (at the wall, where blocks are cut, and across faces of weight 0 it is what the
//   fine matrix says). A_c(I, J) is the sum of the fine entries a_ij with i in I and j in J, so
//   the coarse sparsity patterns and the map of each fine entry to its coarse entry are built
//   once (`build`); a new matrix with the same pattern costs one pass of additions per level
//   (`factorize`). A 5-point (7-point) stencil stays one on every level.
// * Rows that their diagonal dominates (a_ii >= 5 sum |a_ij|; the dust, whose faces have weight
//   0) stay out of the coarse levels (their row of P is 0), as in Notay's aggregation AMG (ETNA
//   37, 2010): the smoother solves them, and in an aggregate with a bed cell their huge a_ii
//   would pin the coarse value and cut the bed's coarse correction at its surface (its cost in
//   iterations: docs/history.md). Which rows join follows the values, per matrix.
// * Cycle: one multicolour Gauss-Seidel sweep before the coarse correction (colours in order)
//   and its adjoint after it (colours in reverse order), a direct solve (dense LDL^T) on the
//   coarsest level (at most kCoarsestRows rows): the preconditioner B is a fixed symmetric
//   operator, so plain CG stays valid. The rows of one colour are independent, so a sweep runs
//   on OpenMP threads (`parallel`, as FlowMesh::parallel decides).
// * Over-correction and W-cycle: piecewise-constant prolongation gives coarse corrections that
//   are too small, so a plain V-cycle's iterations grow with the levels (Notay 2010; Braess,
//   Appl. Numer. Math. 19, 1995). The coarse correction is scaled by a = kOverCorrection and,
//   where the coarse level has at most a third of the rows, applied twice (W-cycle). Both fixed
//   (a varying factor, or Notay's K-cycle, would make B nonlinear and need flexible CG).
//   B stays positive definite: with C = I - a P B_c P^T A and the smoother's error propagation
//   E (an A-norm contraction), I - B A = E* C E. If the eigenvalues of B_c A_c lie in (0, m],
//   one visit gives C <= I, so B A > 0, with eigenvalues <= max(1, a m); two visits give
//   C = (I - a Q)^2 with Q in [0, m], in [0, 1] where a m < 2, so B A in (0, 1]. `build` tracks
//   m from the direct solve (m = 1) upwards and visits twice only where a m < 2.
#pragma once

#include <Eigen/Dense>
#include <Eigen/SparseCore>

#include <array>
#include <vector>

namespace granseg {

class Team;

class Multilevel {
public:
    using Matrix = Eigen::SparseMatrix<double, Eigen::RowMajor>;
    using Vector = Eigen::VectorXd;

    /// Builds the hierarchy for matrices with the pattern of `pattern` (values ignored; every row
    /// has its diagonal), row r being the grid cell with integer coordinates cell[r] (>= 0).
    /// `parallel`: smoothing sweeps on OpenMP threads.
    void build(const Matrix& pattern, const std::vector<std::array<int, 3>>& cell, bool parallel);

    /// Takes the values of a matrix with the pattern of `build` (its compressed value array) on
    /// every level: Galerkin sums and the coarsest factorisation.
    Multilevel& take_values(const double* value);

    /// z = B b: one cycle from z = 0 for A z = b (valid until the next call).
    const Vector& solve(const Vector& b) const;
    /// The same cycle, called by every thread of a team (core/threads.hpp, run_as_team): the
    /// finest level's loops shared, the coarse levels on one thread; z (the same bits on any
    /// number of threads) is then `result()`, complete on every thread. b: one value per row.
    void team_cycle(Team& team, const double* b) const;
    /// z of the last team_cycle (or solve).
    const Vector& result() const { return level_[0].x; }

    /// Number of levels (1: the fine matrix alone, solved directly).
    int levels() const { return static_cast<int>(level_.size()); }
    /// Rows on level l.
    long rows(int l) const { return level_[l].A.rows(); }

    // The interface of an Eigen iterative solver's preconditioner (Eigen::ConjugateGradient):
    // the hierarchy comes from `build`, so the pattern analysis has nothing to do.
    template <class SparseMatrix>
    Multilevel& analyzePattern(const SparseMatrix&) {
        return *this;
    }
    template <class SparseMatrix>
    Multilevel& factorize(const SparseMatrix& A) {
        return take_values(A.valuePtr());
    }
    template <class SparseMatrix>
    Multilevel& compute(const SparseMatrix& A) {
        return take_values(A.valuePtr());
    }
    Eigen::ComputationInfo info() const { return Eigen::Success; }

private:
    struct Level {
        Matrix A;
        std::vector<long> diagonal;             // value index of each row's diagonal
        std::vector<std::vector<long>> colour;  // rows of each colour (no two neighbours share one)
        std::vector<long> aggregate;            // row -> row of the next level (not on the coarsest)
        std::vector<long> galerkin;             // value index -> value index of the next level
        std::vector<double> joins;              // 1 for a row that takes part in the coarse levels, else 0
        int visits = 1;                         // visits of the next level per cycle (1: V, 2: W)
        mutable Vector x, r, b;                 // the V-cycle's iterate, residual and right-hand side
    };

    // `team`: called by every thread of a team, each taking its share of the rows (nullptr: one
    // parallel region per loop where the rows are many, or this thread alone).
    /// One Gauss-Seidel sweep for A x = b on level L, colours in order or (backward) in reverse order.
    void sweep(const Level& L, bool backward, Team* team) const;
    /// The residual r = b - A x of level L (0 on the rows that do not join the coarse level and,
    /// right after a forward sweep (`swept`), on its last colour's rows)...
    void restrict_residual(const Level& L, bool swept, Team* team) const;
    /// ...and its sum P^T r into the coarse right-hand side (one thread).
    void gather_residual(const Level& L, const Level& C) const;
    /// x += a P x_c on level L (the over-corrected coarse correction).
    void correct(const Level& L, const Level& C, Team* team) const;
    /// x = cycle for A x = b on level l, from x = 0.
    void cycle(std::size_t l) const;

    std::vector<Level> level_;
    Eigen::LDLT<Eigen::MatrixXd> coarsest_;
    bool parallel_ = false;
};

}  // namespace granseg
