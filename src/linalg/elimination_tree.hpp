// The elimination tree of a sparse symmetric matrix, and what it tells before any arithmetic:
// the symbolic part of a sparse factorisation (linalg/supernodal_ldlt.hpp).
//
//   solves      nothing numerical: the structure of the factor L of A = L D L^T
//   inputs      the pattern of A (both triangles, column-major) and a numbering of its rows
//   outputs     each column's lower neighbours; the elimination tree (parent of each column);
//               a postorder of it; the column counts of L
//   invariants  a column's parent comes after it; in the postorder every subtree is contiguous
#pragma once

#include <Eigen/SparseCore>

#include <vector>

namespace granseg {

/// Each column's lower neighbours in A's pattern, in the numbering new_of_old.
std::vector<std::vector<long>> lower_neighbours(const Eigen::SparseMatrix<double>& A, const std::vector<long>& new_of_old);

/// The elimination tree (parent of each column, -1 at a root) of the matrix whose column j has
/// the lower neighbours below[j] (Liu's algorithm with path compression).
std::vector<long> elimination_tree(const std::vector<std::vector<long>>& below);

/// The columns in a postorder of the tree (children before parents, each subtree contiguous).
std::vector<long> postorder(const std::vector<long>& parent);

/// Column counts of L below the diagonal: row k's entries are the tree paths from its entries of
/// A (below: the lower neighbours of each column) up to k.
std::vector<long> column_counts(const std::vector<std::vector<long>>& below, const std::vector<long>& parent);

}  // namespace granseg
