#include "flow/pressure/pressure_solver.hpp"

#include "core/threads.hpp"
#include "flow/pressure/equation_of_state.hpp"
#include "linalg/conjugate_gradients.hpp"

#include <algorithm>
#include <cfloat>
#include <cmath>

namespace granseg {

namespace {
/// Relative tolerance of each conjugate-gradient solve at most this large (inexact Newton: the
/// outer iteration corrects what the inner one leaves)...
constexpr double kKrylovTolerance = 0.1;
/// and at most this small (a finer one would only fight round-off).
constexpr double kKrylovFloor = 1e-12;
/// Round-off of a volume fraction summed over a few face fluxes.
constexpr double kRoundOff = 1e-15;
/// The residual Phi(p + dp) - Phi(p) cannot resolve p + dp below a few units in the last place of
/// p and dp.
constexpr double kResolutionUlps = 4.0;
/// Newton steps before the solve gives up (the caller then shortens the step).
constexpr int kMaxNewton = 30;
}  // namespace

PressureSolver::PressureSolver(const FlowMesh& mesh) : pattern_(cell_pattern<Matrix>(mesh)) {
    const Grid& grid = mesh.grid;
    J_ = pattern_.matrix;
    laplacian_ = J_;
    std::vector<std::array<int, 3>> cell;  // grid coordinates of each row, for the aggregation
    for (std::size_t c : mesh.inside_cells)
        cell.push_back({static_cast<int>(c % grid.n[0]), static_cast<int>(c / grid.n[0] % grid.n[1]),
                        static_cast<int>(c / grid.n[0] / grid.n[1])});
    cg_.preconditioner().build(J_, cell, mesh.parallel);
    cg_.setTolerance(kKrylovTolerance);
    cg_.analyzePattern(J_);
    x_.setZero(J_.rows());
}

PressureSolver::PressureSolver(const PressureSolver& other)
    : pattern_(other.pattern_), J_(other.J_), laplacian_(other.laplacian_), x_(other.x_) {
    cg_.preconditioner() = other.cg_.preconditioner();
    cg_.setTolerance(kKrylovTolerance);
    cg_.analyzePattern(J_);
}

PressureSolver& PressureSolver::operator=(const PressureSolver& other) {
    if (this == &other) return *this;
    pattern_ = other.pattern_;
    J_ = other.J_, laplacian_ = other.laplacian_, x_ = other.x_;
    cg_.preconditioner() = other.cg_.preconditioner();
    cg_.analyzePattern(J_);
    return *this;
}

void PressureSolver::newton_update(const FlowMesh& mesh, const Material& material, const FlowState& state, const CellClosures& cl,
                                   const Eigen::VectorXd& step) {
    parallel_for(mesh.parallel, mesh.inside_cells.size(), [&](std::size_t q) {
        const std::size_t c = mesh.inside_cells[q];
        const long r = pattern_.unknown[c];
        const double T = state.T[c], Phi_co = cl.Phi_co[c], Phi_rcp = cl.Phi_rcp[c];
        const double Phi = volume_[r] + slope_[r] * step[r];  // the step's change of Phi
        const double p_co = kinetic_pressure(Phi_co, compressibility_factor(material, Phi_co, Phi_rcp), T);  // p(Phi_co)
        const bool across_kink = volume_[r] > Phi_co && cl.p[c] + x_[r] + step[r] < p_co && Phi > 0.0;
        if (!across_kink) {
            x_[r] += step[r];
            return;
        }
        const double g = compressibility_factor(material, Phi, Phi_rcp);
        x_[r] = kinetic_pressure(Phi, g, T) + yield_pressure(material.T0, Phi, Phi_co, g) - cl.p[c];
    });
}

void PressureSolver::assemble(const FlowMesh& mesh, const Material& material, const FlowState& state, const CellClosures& cl,
                              const PressureFaces& faces, const std::vector<double>& change, const std::vector<double>& dp) {
    const long rows = J_.rows();
    double* value = laplacian_.valuePtr();
    // The coupling part: K_f on both diagonals, -K_f off the diagonal.
    std::fill(value, value + laplacian_.nonZeros(), 0.0);
    for (int a = 0; a < 3; ++a)
        for (const MeshFace& f : mesh.faces[a])
            if (f.kind == kInterior && !f.repeat && faces[a].coupling[f.f] != 0.0)
                pattern_.couple(value, a, f, faces[a].coupling[f.f]);
    std::copy(value, value + laplacian_.nonZeros(), J_.valuePtr());
    base_.resize(rows), target_.resize(rows);
    x_.resize(rows), volume_.resize(rows), slope_.resize(rows), F_.resize(rows);
    for (std::size_t c : mesh.inside_cells) {
        const long r = pattern_.unknown[c];
        base_[r] = volume_at_pressure(material, cl.p[c], state.T[c], cl.Phi_rcp[c], cl.Phi_co[c], state.Phi[c]).Phi;
        target_[r] = change[c];
        x_[r] = dp[c];
    }
}

double PressureSolver::residual(const FlowMesh& mesh, const Material& material, const FlowState& state, const CellClosures& cl) {
    // Phi(p + dp) resolves p + dp no finer than the spacing of doubles near p and dp: where
    // dPhi/dp is large (a bed at T_floor, with p + dp near 0) that alone leaves a residual of
    // slope * eps * (|p| + |dp|), far above kRoundOff, which no Newton step can reduce (the step
    // rounds away in dp + step).
    F_ = laplacian_ * x_ - target_;
    auto cell = [&](double& resolution, std::size_t q) {
        const std::size_t c = mesh.inside_cells[q];
        const long r = pattern_.unknown[c];
        const VolumeAtPressure v =
            volume_at_pressure(material, cl.p[c] + x_[r], state.T[c], cl.Phi_rcp[c], cl.Phi_co[c], base_[r]);
        F_[r] += v.Phi - base_[r];
        volume_[r] = v.Phi, slope_[r] = v.slope;
        resolution = std::max(resolution, kResolutionUlps * DBL_EPSILON * v.slope * (std::fabs(cl.p[c]) + std::fabs(x_[r])));
    };
    return parallel_fold(mesh.parallel, mesh.inside_cells.size(), 0.0, cell, [](double a, double b) { return std::max(a, b); });
}

int PressureSolver::newton_step(const FlowMesh& mesh, double tolerance) {
    const double* value = laplacian_.valuePtr();
    for (long r = 0; r < J_.rows(); ++r) J_.valuePtr()[pattern_.diagonal[r]] = value[pattern_.diagonal[r]] + slope_[r];
    cg_.factorize(J_);
    // Each solve only needs to bring the residual well below the Newton tolerance: with the
    // warm start that is often a small relative reduction.
    const double krylov_tolerance = std::min(kKrylovTolerance, std::max(kKrylovFloor, 0.1 * tolerance / F_.norm()));
    // On a grid that runs on threads the whole CG in one parallel region (linalg/conjugate_gradients.hpp).
    if (mesh.parallel) return static_cast<int>(team_cg(J_, cg_.preconditioner(), -F_, krylov_tolerance, step_).iterations) + 1;
    cg_.setTolerance(krylov_tolerance);
    step_ = cg_.solve(-F_);
    return static_cast<int>(cg_.iterations()) + 1;  // Eigen counts the iterations after the first
}

PressureSolveStats PressureSolver::solve(const FlowMesh& mesh, const Material& material, const FlowState& state,
                                         const CellClosures& cl, const PressureFaces& faces, const std::vector<double>& change,
                                         double accuracy, bool solved_guess, std::vector<double>& dp) {
    assemble(mesh, material, state, cl, faces, change, dp);
    PressureSolveStats stats;
    // Newton stops at `accuracy` times the largest mass change of the explicit fluxes, and at
    // round-off when they change nothing (a bed at rest stays at rest to round-off).
    const double tolerance = accuracy * target_.lpNorm<Eigen::Infinity>() + kRoundOff;
    double resolution = residual(mesh, material, state, cl);
    // The warm start, unless it is further from the solution than no increment at all (F = -r
    // there): after a sudden change of the state the last step's dp can be a poor guess
    // (docs/flow_solver_choices.md, "Warm starts").
    if (F_.lpNorm<Eigen::Infinity>() > target_.lpNorm<Eigen::Infinity>() && x_.any()) {
        x_.setZero();
        resolution = residual(mesh, material, state, cl);
    }
    for (;; ++stats.newton) {
        stats.residual = F_.lpNorm<Eigen::Infinity>();
        // At least one Newton step (a lagged pressure would not damp the acoustic waves), unless
        // the guess is this step's implicit pressure already or the residual is at round-off (a
        // bed at rest then stays exactly where it is).
        if (stats.residual <= tolerance + resolution && (stats.newton > 0 || solved_guess || stats.residual <= kRoundOff)) {
            stats.converged = true;
            break;
        }
        if (stats.newton == kMaxNewton) break;
        stats.krylov += newton_step(mesh, tolerance);
        newton_update(mesh, material, state, cl, step_);
        resolution = residual(mesh, material, state, cl);
    }
    for (std::size_t c : mesh.inside_cells) dp[c] = x_[pattern_.unknown[c]];
    return stats;
}

}  // namespace granseg
