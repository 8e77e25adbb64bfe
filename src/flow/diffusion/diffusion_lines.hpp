// The implicit diffusion operator of one axis as tridiagonal line systems.
//
//   solves      Phi x_new - r d/dx_a (kappa dx_new/dx_a) h_a^2 = rhs along every line of one axis
//   inputs      Phi, kappa per cell, r, the wall rule (no-slip or adiabatic)
//   outputs     the factorised lines; solve() overwrites a right-hand side with the solution
//   invariants  outside and empty cells are identity rows; M-matrices
//
// docs/flow_solver.md Sect. 2, viscosity: for a field x with coefficient kappa (eta for the velocity, lambda for T),
//     Phi x_new - r d/dx_a (kappa dx_new/dx_a) h_a^2 = rhs,     r = dt/h_a^2 (times 3/2 for T),
// with the face coefficient the harmonic mean of the two cells' kappa (a face between the bed and
// near-empty air carries almost no stress or heat), walls Dirichlet at distance h/2 (no-slip,
// the wall value goes into rhs) or zero flux (adiabatic). Outside and empty cells are identity
// rows. The matrices are M-matrices: positive data give positive solutions.
#pragma once

#include "flow/diffusion/diffusion_faces.hpp"
#include "flow/fields/flow_mesh.hpp"
#include "linalg/tridiagonal_lines.hpp"

#include <vector>

namespace granseg {

class DiffusionLines {
public:
    explicit DiffusionLines(const FlowMesh& mesh);
    /// Builds and factorises the line systems of `axis` (see the header comment).
    void factor(const FlowMesh& mesh, int axis, double r, const std::vector<double>& Phi, const std::vector<double>& kappa,
                bool no_slip, double Phi_vacuum);
    /// Overwrites x (the right-hand side on entry) with the solution of the last factor().
    void solve(std::vector<double>& x) const { lines_.solve(x); }

private:
    std::vector<double> lower_, diag_, upper_;
    TridiagonalLines lines_;
};

}  // namespace granseg
