// The temperature equation (14) without convection (docs/flow_solver.md Sect. 2, T).
//
//   solves      heating, dissipation and conduction of T in one implicit system per step
//               (below), by Jacobi-preconditioned conjugate gradients for the change of T
//   inputs      Phi, u, T per cell; eta, lambda, eps Phi of the closures at t^n; dt; the wall
//               velocities (for the heating at walls)
//   outputs     T and Phi T; the conjugate-gradient iterations
//   invariants  T >= T_floor; positive data give positive T (an M-matrix); a state that does
//               not change stays as it is
//
// The system:
//     Phi T_new + dt eps Phi T_new - (3/2) dt div(lambda grad T_new) = Phi T* + (3/2) dt H,
// with H the dissipation of the discrete viscous operator (half of eta_f ((u_nb - u)/h)^2 of each
// interior face, all of 2 eta ((U_wall - u)/h)^2 of a wall face), eta, lambda, eps Phi from the
// start of the step, face conductivities the harmonic means of the cells' lambda, adiabatic walls,
// empty cells at T_floor; then T >= T_floor (assumption F2) and Phi T = Phi T_new.
// Why one system: lambda and eps Phi are both proportional to p/sqrt(T), so conduction reaches
// only sqrt(3 lambda0/(2 eps0)) (0.66 mm with the default material) before dissipation takes the
// heat, whatever T. Conducting first and dissipating after (operator splitting) spreads the heat
// of a yielding cell over sqrt(3 lambda dt/(2 Phi)) instead (the whole drum at T_floor): the bed
// then could not heat itself off the floor, and the drum stick-slipped at long steps.
// The matrix is symmetric positive definite and an M-matrix (positive data give positive T); its
// conduction is at most 2 d (3 lambda0/(2 eps0 h^2)) times its dissipation in d dimensions, so
// Jacobi-preconditioned conjugate gradients, solving for the change T_new - T*, converge in a few
// iterations at any dt.
#pragma once

#include "flow/fields/cell_pattern.hpp"
#include "flow/fields/flow_mesh.hpp"
#include "flow/fields/flow_settings.hpp"
#include "flow/fields/flow_state.hpp"
#include "run/state_io.hpp"

#include <Eigen/SparseCore>

#include <vector>

namespace granseg {

/// heat = H per cell (see above) from the velocities of `state` and eta of `closures`.
void viscous_heating(const FlowMesh& mesh, const WallVelocities& walls, const CellClosures& closures, const FlowState& state,
                     std::vector<double>& heat);

class TemperatureSolver {
public:
    explicit TemperatureSolver(const FlowMesh& mesh);

    /// Updates T and Phi T of `state` (reads Phi, u, T) over dt with eta, lambda, eps Phi of
    /// `closures`; `heat` holds one value per cell. Returns the conjugate-gradient iterations.
    /// Throws InvariantError if they do not converge.
    int apply(const FlowMesh& mesh, const FlowSettings& settings, const WallVelocities& walls, double dt,
              const CellClosures& closures, std::vector<double>& heat, FlowState& state);

private:
    using Matrix = Eigen::SparseMatrix<double, Eigen::RowMajor>;
    CellPattern<Matrix> pattern_;       // inside cells and interior faces; values rewritten each step
    Eigen::VectorXd rhs_, T_, change_;  // per row: right-hand side, T, the change of T (the next guess)

public:
    /// Saves or restores (run/state_io.hpp) the warm start of the next solve.
    void checkpoint(StateIO& io) { io("change", change_); }
};

}  // namespace granseg
