// Implicit viscosity with all axes in one system (docs/flow_solver.md Sect. 2, viscosity).
//
//   solves      Phi u_new - dt div(eta grad u_new) = Phi u for each velocity component, by one
//               sparse LDL^T factorisation per step and a back-substitution per component
//   inputs      Phi, u, eta per cell, dt, the velocities of the domain-boundary walls
//   outputs     u and Phi u; diffuse_change(): a velocity change diffused by the same factor
//   invariants  empty cells (Phi <= Phi_vacuum) are identity rows at rest; the matrix is
//               symmetric positive definite and an M-matrix
//
// Every velocity component u_b solves
//     Phi u_new - dt sum_axis d/dx_a (eta d u_new/dx_a) = Phi u      (eqs. 9-11, stress eta grad u)
// with the same discretisation as the line solves of flow/diffusion/viscosity.hpp (face coefficient the
// harmonic mean of the cells' eta, no-slip walls at h/2 with the wall's velocity on moving walls
// of the domain boundary, empty cells at rest), but without splitting the axes. The split
// step (Lie/ADI) multiplies the responses of the axes: a mode with viscous rates a = dt eta k_x^2/Phi
// and b = dt eta k_z^2/Phi is damped by (1 + a)(1 + b) instead of 1 + a + b, so for a, b >> 1 the
// slow creep of a bed under a load that varies in x and z comes out min(a, b) times too slow,
// and more so the longer the step: at the semi-implicit step's dt the drum's bed stays rigid far
// past the friction angle (docs/flow_solver_choices.md, "Why these choices").
// One sparse symmetric positive definite matrix for the three components: its pattern (inside
// cells, interior faces) and fill-reducing ordering are set up once, the values and the sparse
// LDL^T factor each step: the project's supernodal one (linalg/supernodal_ldlt.hpp) or Eigen's
// SimplicialLDLT ([flow] factorisation; the cost of each: docs/flow_solver_choices.md).
#pragma once

#include "flow/fields/cell_pattern.hpp"
#include "flow/fields/flow_mesh.hpp"
#include "flow/fields/flow_settings.hpp"
#include "flow/fields/flow_state.hpp"
#include "linalg/supernodal_ldlt.hpp"

#include <Eigen/Dense>
#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>

#include <vector>

namespace granseg {

class CoupledViscosity {
public:
    explicit CoupledViscosity(const FlowMesh& mesh, Factorisation factorisation = Factorisation::supernodal);
    /// Copies the pattern; the factorisation (not copyable) is set up anew.
    CoupledViscosity(const CoupledViscosity& other);
    CoupledViscosity& operator=(const CoupledViscosity& other);

    /// Updates u and Phi u of `state` (reads Phi, u) for a step dt with eta per cell.
    void apply(const FlowMesh& mesh, const FlowSettings& settings, const WallVelocities& walls, double dt,
               const std::vector<double>& eta, FlowState& state);
    /// Solves the system of the last apply() again for a velocity change du (walls at rest):
    /// du <- (Phi - dt div eta grad)^(-1) Phi du in the cells active then; others keep du.
    void diffuse_change(const FlowMesh& mesh, std::array<std::vector<double>, 3>& du);

private:
    using Matrix = Eigen::SparseMatrix<double>;
    void set_up();
    /// The factor's solution for each column of rhs_, on OpenMP threads if `parallel`; columns of
    /// zeros (u_y in an x-z slice) skip the solve.
    Eigen::MatrixXd solve_columns(bool parallel) const;
    CellPattern<Matrix> pattern_;  // inside cells and interior faces; its matrix takes each step's values
    Eigen::MatrixXd rhs_;
    Eigen::VectorXd mass_;  // per unknown: the last apply()'s Phi, 0 in empty cells (identity rows)
    Factorisation factorisation_;
    SupernodalLDLT ldlt_;                       // factorisation_ == supernodal
    Eigen::SimplicialLDLT<Matrix> simplicial_;  // factorisation_ == simplicial
};

}  // namespace granseg
