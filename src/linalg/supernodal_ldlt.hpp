// A sparse LDL^T factorisation in supernodes, for the coupled viscosity (flow/diffusion/coupled_viscosity.hpp).
//
//   solves      A x = b for a sparse symmetric positive definite A, by A = P^T L D L^T P with a
//               fill-reducing P (approximate minimum degree, then a postorder of the elimination
//               tree), L unit lower triangular, D diagonal
//   inputs      analyze(): the pattern of A (both triangles, column-major); factorize(): its values
//   outputs     solve(): x for one right-hand side
//   invariants  the pattern is that of analyze(); factorize() reports failure (not positive definite
//               or not finite) instead of factorising
//
// The idea (Ng & Peyton's left-looking supernodal Cholesky, here in its LDL^T form): consecutive
// columns of L with the same rows below them form a supernode, stored as one dense column-major
// panel. Every update of a panel by an earlier one is then a small dense product, computed in a
// contiguous buffer and added into the panel through one row map, instead of one indirectly
// addressed update per entry of L as in the row-by-row (up-looking) simplicial algorithm; most
// of the work of a 2-D grid's factor sits in the long, shared columns at the top of its tree.
// Two sets of subtrees of the elimination tree, of about equal work, depend on nothing outside
// themselves: they are factorised on two threads, then the supernodes above them ("the top").
//
// Symbolic stage, once per pattern: the ordering, the elimination tree (Liu's algorithm), the
// column counts of L (each row's subtree walked once), the supernodes (a column joins the one
// before it when it is that column's parent and the explicit zeros this pads in stay few:
// kRelaxedZeros), each supernode's rows (its own entries of A and its child supernodes' rows), the
// position of every entry of A in the panels, the split into two lanes and the top.
#pragma once

#include <Eigen/SparseCore>

#include <array>
#include <utility>
#include <vector>

namespace granseg {

class SupernodalLDLT {
public:
    using Matrix = Eigen::SparseMatrix<double>;  // column-major

    /// The ordering, the supernodes and where each entry of A goes (A: both triangles stored).
    void analyze(const Matrix& A);
    /// L and D for the values of A (same pattern as analyze()); two subtrees of the elimination
    /// tree on two OpenMP threads if `parallel` (the same arithmetic either way). False, and no
    /// usable factor, if a pivot is not positive and finite (failed_row() then names its row).
    /// Eigen's dense products inside a lane run on the lane's thread alone: InvariantError if
    /// Eigen::setNbThreads() asked for more.
    bool factorize(const Matrix& A, bool parallel);
    /// After a failed factorize(): the row of A whose pivot failed (a wide panel, factored by a
    /// dense Cholesky, names its first row); -1 after a success.
    long failed_row() const { return failed_row_; }
    /// How many columns the supernode holding row r of A has (the panel's width: wide panels
    /// factor their diagonal block by a dense Cholesky, narrow ones column by column).
    long supernode_width(long r) const;
    /// x = A^-1 b in place (b of A's row count).
    void solve(double* x) const;

    long rows() const { return static_cast<long>(order_.size()); }
    long supernodes() const { return static_cast<long>(first_.size()) - 1; }

private:
    /// The scratch of one thread of factorize().
    struct Lane {
        std::vector<std::pair<long, long>> subtrees;  // supernode ranges [begin, end) it factors
        std::vector<long> relative;                   // row -> position in the panel being updated
        std::vector<double> product, scaled;          // one dense update, D L^T of its columns
        std::vector<long> pending;                    // supernodes to update a top one, in order
    };
    // Supernode s holds columns first_[s] .. first_[s + 1] - 1 (of the permuted matrix) and the rows
    // row_[row_start_[s] ..] (its own columns first, ascending), stored column-major from
    // value_[value_start_[s]] with leading dimension height(s).
    long width(long s) const { return first_[s + 1] - first_[s]; }
    long height(long s) const { return row_start_[s + 1] - row_start_[s]; }
    // analyze(), step by step.
    /// order_ and new_of_old_ (the fill-reducing order, postordered); returns the lower
    /// neighbours of each column of A in that order.
    std::vector<std::vector<long>> order_rows(const Matrix& A);
    /// first_ and super_of_ from the elimination tree and the column counts; each supernode's
    /// parent (-1 at a root) and children.
    void form_supernodes(const std::vector<long>& parent, const std::vector<long>& count, std::vector<long>& super_parent,
                         std::vector<std::vector<long>>& children);
    /// row_start_, row_, value_start_ and value_: each supernode's rows and panel.
    void gather_rows(const std::vector<std::vector<long>>& below, const std::vector<std::vector<long>>& children);
    /// entry_start_ and entry_: where each stored entry of A goes in the panels.
    void place_entries(const Matrix& A);
    /// Splits the supernodal tree into two sets of subtrees of about equal work and the top
    /// (the rest, factored after both).
    void split(const std::vector<double>& work, const std::vector<long>& parent, const std::vector<std::vector<long>>& children);
    /// Factors supernode s (A's values a) with the updates waiting for it; supernodes then
    /// waiting for a top supernode go to lane.pending if `defer`. False if a pivot fails.
    bool factor_supernode(long s, const double* a, Lane& lane, bool defer);
    /// The multiply-adds of each supernode's updates and panel (factorize()'s schedule without
    /// the arithmetic), for split().
    std::vector<double> update_work() const;
    /// The supernode holding supernode d's row at `position` (the next one d updates), -1 past its last row.
    long waits_for(long d, long position) const;
    /// How many of supernode d's rows, from its position begin on, lie in supernode s's columns.
    long rows_in(long d, long begin, long s) const;
    /// Subtracts supernode d's update of supernode s (from d's row cursor_[d] on) from s's panel.
    void update(long d, long s, Lane& lane);
    /// The dense LDL^T of supernode s's panel (its diagonal block and the rows below); false if a
    /// pivot fails, with failed_row_ set.
    bool factor_panel(long s);

    std::vector<long> order_;                   // permuted row k is row order_[k] of A
    std::vector<long> new_of_old_;              // row of A -> permuted row
    std::vector<long> first_;                   // first column of each supernode (one past the last at the end)
    std::vector<long> super_of_;                // column -> supernode
    std::vector<long> row_start_;               // per supernode, into row_
    std::vector<long> row_;                     // each supernode's rows (permuted numbering)
    std::vector<long> value_start_;             // per supernode, into value_
    std::vector<long> entry_start_;             // per supernode, into entry_
    std::vector<std::pair<long, long>> entry_;  // its entries of A: (index in A's values, in its panel)
    std::vector<double> value_;                 // the panels: L below the diagonal, D on it
    std::vector<long> top_;                     // supernodes factored after both lanes, ascending
    std::vector<char> in_top_;
    // Scratch of factorize().
    std::array<Lane, 2> lanes_;
    std::vector<long> next_, link_;  // linked lists of supernodes waiting to update a later one
    std::vector<long> cursor_;       // per supernode, the position of its next row to update with
    long failed_row_ = -1;           // row of A of the last failed pivot
};

}  // namespace granseg
