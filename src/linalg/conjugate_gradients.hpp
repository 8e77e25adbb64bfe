// Conjugate gradients with the multilevel preconditioner, the whole solve in one OpenMP parallel
// region (docs/flow_solver_choices.md, "Threads").
//
//   solves      A x = b, A symmetric positive definite (row-major, full pattern), preconditioned
//               by one cycle of a Multilevel built for A's pattern and given A's values
//   inputs      A, the preconditioner, b, the relative tolerance
//   outputs     x (from x = 0) and the iterations, counted as Eigen::ConjugateGradient counts them
//   invariants  the iteration of Eigen::ConjugateGradient (stop when |r|^2 < tol^2 |b|^2, at most
//               2 n iterations); the threads stay together from the first product to the last
//               update: the sparse product, the vector updates and the preconditioner's finest
//               level are shared, its coarse levels run on one thread while the others wait;
//               every dot product sums fixed blocks of rows in block order, so x has the same bits
//               on any number of threads
//
// Used by the pressure solve on grids that run on threads (core/threads.hpp), where Eigen's CG
// would open a region for each product and each preconditioner sweep and
// keep its dot products and updates on one thread.
#pragma once

#include "linalg/multilevel.hpp"

namespace granseg {

struct CgResult {
    long iterations = 0;  // as Eigen::ConjugateGradient::iterations()
    double error = 0.0;   // |r| / |b| at the end
};

/// x = A^-1 b to the relative tolerance `tolerance` (see the header comment).
CgResult team_cg(const Multilevel::Matrix& A, const Multilevel& B, const Eigen::VectorXd& b, double tolerance,
                 Eigen::VectorXd& x);

}  // namespace granseg
