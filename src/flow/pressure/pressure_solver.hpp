// The implicit pressure equation of the semi-implicit step (docs/flow_solver.md Sect. 2, pressure_solve).
//
//   solves      F(dp) = 0 (below) for the pressure increments dp, by Newton's method with
//               multilevel-preconditioned conjugate gradients for each Newton step
//   inputs      p, T, Phi, Phi_rcp, Phi_co per cell; per face the coupling K_f; per cell the
//               explicit mass change r_c; dp of the last step (the warm start)
//   outputs     dp per inside cell; the Newton and Krylov counts, the final residual
//   invariants  Phi(p + dp) < Phi_rcp in every cell (Newton approaches the root from below);
//               r = 0 from a guess of 0 takes no Newton step and keeps dp = 0 exactly; a balanced
//               bed, whose r is the rounding where gravity and the pressure gradient cancel, takes
//               one and moves by round-off (how far at the defaults: verify_flow_rest and
//               docs/flow_solver_pressure.md); max |F| stops at `accuracy` max |r|
//               over the whole domain, so two runs that differ by rounding (the slab of
//               verify_flow_rotation and its 2-D run) differ by what that tolerance admits
//
// Find the pressure increments dp per inside cell with
//     F_c(dp) = Phi(p_c + dp_c; T_c) - Phi_c - r_c + sum_faces K_f (dp_c - dp_nb) = 0,
// where Phi(p; T) is the inverse equation of state (flow/pressure/equation_of_state.hpp), r_c the mass
// change of the explicit part of the face mass fluxes, and K_f = (dt/h)^2 Phi_donor/Phi_face >= 0
// the coupling of the two cells of an interior face (the face mass flux changes by
// -(dt/h) (Phi_donor/Phi_face) (dp_hi - dp_lo), eq. 9 without convection). Phi(p) is concave and
// increasing and the coupling matrix is a weighted graph Laplacian, so the Newton iterates after
// the first approach the solution from below (Casulli & Zanolli, SIAM J. Sci. Comput. 32, 2010):
// Phi stays below Phi_rcp. Each Newton step solves J s = -F, J = diag(dPhi/dp) + K, symmetric
// positive definite, by conjugate gradients only as far as the Newton tolerance needs (Eigen's,
// or on a grid that runs on threads linalg/conjugate_gradients.hpp, the same iteration in one parallel region),
// preconditioned by one multilevel cycle (linalg/multilevel.hpp: aggregation of 2 x 2 (x 2) grid
// cells, Galerkin coarse matrices), whose iterations hardly grow with the grid, where Jacobi's
// grew like 1/h (docs/flow_solver_choices.md, "Why these choices"); the sparsity pattern (inside cells, interior
// faces) and the hierarchy are built once; the first guess is the previous step's dp (warm start)
// unless dp = 0 is closer to the solution.
// The Newton update, per cell: p + s, except where s would take a cell from above Phi_co (the
// stiff branch, dPhi/dp ~ 0.08 in the drum) below the kink at Phi_co into the soft branch, where the step,
// linearised on the stiff side, lands far too low, near p = 0 where dPhi/dp = 1/T is up to 100
// times its value at the root, and the iterates then crawl back from below over 5-7 Newton steps
// (traced in the 100-cell drum). Such a cell moves by the same Newton step expressed in Phi,
// Phi(p) + s dPhi/dp, taken back to p by the equation of state: as p(Phi) is convex, a single
// cell's step in Phi cannot jump past its root. Elsewhere the p form stays, also because the round trip through the equation of
// state costs tens of ulps of p, which a bed at rest would feel (verify_flow_rest's balanced box).
#pragma once

#include "closures/material.hpp"
#include "flow/faces/semi_implicit_faces.hpp"
#include "flow/fields/cell_pattern.hpp"
#include "flow/fields/flow_mesh.hpp"
#include "flow/fields/flow_state.hpp"
#include "linalg/multilevel.hpp"

#include <Eigen/IterativeLinearSolvers>
#include <Eigen/SparseCore>

#include <array>
#include <vector>

namespace granseg {

/// Iteration counts of one pressure solve.
struct PressureSolveStats {
    int newton = 0;         // Newton steps
    int krylov = 0;         // conjugate-gradient iterations, summed over the Newton steps
    double residual = 0.0;  // max |F_c| at the end
    bool converged = false;
};

class PressureSolver {
public:
    explicit PressureSolver(const FlowMesh& mesh);
    /// Copies the pattern, the hierarchy and the warm start; the Krylov solver (not copyable) is set up anew.
    PressureSolver(const PressureSolver& other);
    PressureSolver& operator=(const PressureSolver& other);

    /// Solves F(dp) = 0 (header comment) for dp (one value per grid cell, the guess on entry; 0
    /// outside). faces[a].coupling: per face the coupling K_f (0 on walls and faces without
    /// material); change: r_c per cell. Newton stops when max |F_c| <= accuracy max |r_c| + round-off,
    /// after at least one Newton step unless `solved_guess` (the guess already solves this step's
    /// equation for nearly the same K: a repeat after reversed faces) or F is at round-off.
    PressureSolveStats solve(const FlowMesh& mesh, const Material& material, const FlowState& state, const CellClosures& closures,
                             const PressureFaces& faces, const std::vector<double>& change, double accuracy, bool solved_guess,
                             std::vector<double>& dp);

private:
    using Matrix = Eigen::SparseMatrix<double, Eigen::RowMajor>;
    /// dp += the Newton step s, in p, or in Phi for a cell whose step would take it from the
    /// stiff branch (Phi > Phi_co) below the kink (header comment).
    void newton_update(const FlowMesh& mesh, const Material& material, const FlowState& state, const CellClosures& cl,
                       const Eigen::VectorXd& step);
    /// The Jacobian's coupling part from the faces' K, and per row Phi(p) (base_), r (target_) and
    /// the guess dp (x_).
    void assemble(const FlowMesh& mesh, const Material& material, const FlowState& state, const CellClosures& cl,
                  const PressureFaces& faces, const std::vector<double>& change, const std::vector<double>& dp);
    /// F = Phi(p + dp) - Phi(p) - r + K dp, and Phi(p + dp) and dPhi/dp per row; returns how finely
    /// F can resolve dp (below which no Newton step can reduce it).
    double residual(const FlowMesh& mesh, const Material& material, const FlowState& state, const CellClosures& cl);
    /// The Newton step step_ = -J^-1 F, by conjugate gradients to what the Newton tolerance
    /// needs; returns its iterations, counted as Eigen's CG counts them plus one.
    int newton_step(const FlowMesh& mesh, double tolerance);
    CellPattern<Matrix> pattern_;                    // inside cells and interior faces (flow/fields/cell_pattern.hpp)
    Matrix J_, laplacian_;                           // the Jacobian, and its coupling part (same pattern)
    Eigen::VectorXd x_, volume_, slope_, F_, step_;  // per row: dp, Phi(p + dp) and dPhi/dp there, F, Newton step
    Eigen::VectorXd base_, target_;                  // per row: Phi(p) at the start of the solve, r
    Eigen::ConjugateGradient<Matrix, Eigen::Lower | Eigen::Upper, Multilevel> cg_;
};

}  // namespace granseg
