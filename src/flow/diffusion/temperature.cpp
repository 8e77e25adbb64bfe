#include "flow/diffusion/temperature.hpp"

#include "core/error.hpp"
#include "core/format.hpp"
#include "core/threads.hpp"
#include "flow/diffusion/diffusion_faces.hpp"

#include <Eigen/IterativeLinearSolvers>

#include <algorithm>

namespace granseg {

namespace {
/// The conjugate gradients solve for the change dT = T_new - T* and stop when its residual has
/// fallen to this share of the residual of T*: the error is 1e-8 of the step's change of T (far
/// below the step's own error), and a state that does not change stays exactly as it is.
constexpr double kTolerance = 1e-8;
/// Round-off may stop the iterations short of kTolerance; a residual above this is an error.
constexpr double kAcceptable = 1e-5;
/// Far more than the iterations the bounded condition number needs.
constexpr int kMaxIterations = 500;
}  // namespace

void viscous_heating(const FlowMesh& mesh, const WallVelocities& walls, const CellClosures& cl, const FlowState& state,
                     std::vector<double>& heat) {
    const std::size_t nx = mesh.grid.n[0];
    const double* eta = cl.eta.data();
    const unsigned char* in = mesh.inside.data();
    const auto& u = state.u;
    parallel_for(mesh.parallel, mesh.rows, [&](std::size_t row) {
        for (int i = mesh.row_lo[row]; i < mesh.row_hi[row]; ++i) heat[nx * row + i] = 0.0;
    });
    for (int a = 0; a < 3; ++a) {
        if (!mesh.active[a]) continue;
        const double inv_h2 = 1.0 / (mesh.grid.h[a] * mesh.grid.h[a]);
        const unsigned char* kind = mesh.face_kind[a].data();
        parallel_for(mesh.parallel, mesh.rows, [&](std::size_t row) {
            const AxisRow ar = mesh.axis_row(a, row);
            for (int i = mesh.row_lo[row]; i < mesh.row_hi[row]; ++i) {
                const std::size_t c = nx * row + i, fl = ar.face0 + i, fu = fl + ar.face_step;
                if (!in[c]) continue;
                const long lo = ar.lo_at(i), hi = ar.hi_at(i);
                double h = 0.0;
                for (int side = 0; side < 2; ++side) {
                    const std::size_t f = side == 0 ? fl : fu, nb = c + (side == 0 ? lo : hi);
                    const bool interior = kind[f] == kInterior;
                    double sum = 0.0;
                    for (int b = 0; b < 3; ++b) {
                        const double other = interior ? u[b][nb] : wall_velocity(mesh.grid, walls, a, side, f, b);
                        sum += (other - u[b][c]) * (other - u[b][c]);
                    }
                    // Each interior face's dissipation is shared by its two cells.
                    const double eta_f = face_conductance(interior, eta[c], eta[nb], true);
                    h += (interior ? 0.5 * eta_f : eta_f) * sum * inv_h2;
                }
                heat[c] += h;
            }
        });
    }
}

TemperatureSolver::TemperatureSolver(const FlowMesh& mesh) : pattern_(cell_pattern<Matrix>(mesh)) {
    rhs_.setZero(pattern_.matrix.rows());
    T_.setZero(pattern_.matrix.rows());
    change_.setZero(pattern_.matrix.rows());
}

int TemperatureSolver::apply(const FlowMesh& mesh, const FlowSettings& settings, const WallVelocities& walls, double dt,
                             const CellClosures& cl, std::vector<double>& heat, FlowState& state) {
    viscous_heating(mesh, walls, cl, state, heat);
    const std::vector<double>& Phi = state.Phi;
    std::vector<double>& T = state.T;
    auto active = [&](std::size_t c) { return Phi[c] > settings.Phi_vacuum; };
    double* value = pattern_.matrix.valuePtr();
    std::fill(value, value + pattern_.matrix.nonZeros(), 0.0);
    // Mass, dissipation and heating (eq. 14); an empty cell is an identity row at T_floor.
    for (std::size_t c : mesh.inside_cells) {
        const long r = pattern_.unknown[c];
        value[pattern_.diagonal[r]] = active(c) ? Phi[c] + dt * cl.epsPhi[c] : 1.0;
        rhs_[r] = active(c) ? Phi[c] * T[c] + dt * 1.5 * heat[c] : settings.T_floor;
        T_[r] = active(c) ? T[c] : settings.T_floor;  // T*, the start
    }
    // Conduction (3/2) div(lambda grad T) between cells that both hold material; walls adiabatic.
    for (int a = 0; a < 3; ++a) {
        if (!mesh.active[a]) continue;
        const double r = 1.5 * dt / (mesh.grid.h[a] * mesh.grid.h[a]);
        for (const MeshFace& f : mesh.faces[a]) {
            if (f.kind != kInterior || f.repeat || !active(f.lo) || !active(f.hi)) continue;
            pattern_.couple(value, a, f, r * face_conductance(true, cl.lambda[f.lo], cl.lambda[f.hi], false));
        }
    }
    Eigen::ConjugateGradient<Matrix, Eigen::Lower | Eigen::Upper> cg;  // Jacobi preconditioner
    cg.setTolerance(kTolerance);
    cg.setMaxIterations(kMaxIterations);
    cg.compute(pattern_.matrix);
    rhs_ -= pattern_.matrix * T_;  // the residual of T*: the right-hand side of dT
    // The last step's change is the guess: in a steady flow heating, dissipation and conduction
    // change T by much the same amount step after step (the tolerance stays relative to rhs_).
    change_ = cg.solveWithGuess(rhs_, change_);
    T_ += change_;
    if (cg.info() != Eigen::Success && !(cg.error() <= kAcceptable))
        throw InvariantError("flow: the temperature equation did not converge in " + std::to_string(kMaxIterations) +
                             " iterations (relative residual " + format_number(cg.error()) + ")");
    for (std::size_t c : mesh.inside_cells) {
        T[c] = std::max(T_[pattern_.unknown[c]], settings.T_floor);  // floor: docs/assumptions.md F2
        state.E[c] = Phi[c] * T[c];
    }
    return static_cast<int>(cg.iterations());
}

}  // namespace granseg
