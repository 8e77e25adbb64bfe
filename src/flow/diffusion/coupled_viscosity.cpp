#include "flow/diffusion/coupled_viscosity.hpp"

#include "core/error.hpp"
#include "core/threads.hpp"
#include "flow/diffusion/diffusion_faces.hpp"

#include <algorithm>

namespace granseg {

CoupledViscosity::CoupledViscosity(const FlowMesh& mesh, Factorisation factorisation)
    : pattern_(cell_pattern<Matrix>(mesh)), factorisation_(factorisation) {
    set_up();
}

CoupledViscosity::CoupledViscosity(const CoupledViscosity& other)
    : pattern_(other.pattern_), factorisation_(other.factorisation_) {
    set_up();
}

CoupledViscosity& CoupledViscosity::operator=(const CoupledViscosity& other) {
    if (this == &other) return *this;
    pattern_ = other.pattern_;
    factorisation_ = other.factorisation_;
    set_up();
    return *this;
}

void CoupledViscosity::set_up() {
    rhs_.setZero(pattern_.matrix.rows(), 3);
    mass_.setZero(pattern_.matrix.rows());
    // The fill-reducing ordering (and the supernodes), once per pattern.
    if (factorisation_ == Factorisation::supernodal)
        ldlt_.analyze(pattern_.matrix);
    else
        simplicial_.analyzePattern(pattern_.matrix);
}

void CoupledViscosity::apply(const FlowMesh& mesh, const FlowSettings& settings, const WallVelocities& walls, double dt,
                             const std::vector<double>& eta, FlowState& state) {
    const Grid& grid = mesh.grid;
    const std::vector<double>& Phi = state.Phi;
    auto active = [&](std::size_t c) { return Phi[c] > settings.Phi_vacuum; };
    double* value = pattern_.matrix.valuePtr();
    std::fill(value, value + pattern_.matrix.nonZeros(), 0.0);
    // Mass rows; an empty cell is an identity row with right-hand side 0 (at rest).
    for (std::size_t c : mesh.inside_cells) {
        const long r = pattern_.unknown[c];
        value[pattern_.diagonal[r]] = active(c) ? Phi[c] : 1.0;
        mass_[r] = active(c) ? Phi[c] : 0.0;
        for (int b = 0; b < 3; ++b) rhs_(r, b) = active(c) ? Phi[c] * state.u[b][c] : 0.0;
    }
    // Viscous couplings; an active cell next to an empty one keeps its weight on the diagonal
    // (the empty cell's velocity is 0), as in the line solves.
    for (int a = 0; a < 3; ++a) {
        if (!mesh.active[a]) continue;
        const double r = dt / (grid.h[a] * grid.h[a]);
        for (const MeshFace& f : mesh.faces[a]) {
            if (f.kind == kInterior) {
                if (f.repeat) continue;
                const double w = r * face_conductance(true, eta[f.lo], eta[f.hi], true);
                const bool lo = active(f.lo), hi = active(f.hi);
                if (lo && hi)
                    pattern_.couple(value, a, f, w);
                else if (lo || hi)
                    value[pattern_.diagonal[pattern_.unknown[lo ? f.lo : f.hi]]] += w;
                continue;
            }
            const std::size_t c = f.lo;  // a wall: both sides name the inside cell
            if (!active(c)) continue;
            const double w = r * face_conductance(false, eta[c], 0.0, true);
            value[pattern_.diagonal[pattern_.unknown[c]]] += w;
            // Moving walls are those of the domain boundary (embedded walls are at rest).
            const int side = f.kind == kWallBelow ? 0 : 1;
            if (on_domain_boundary(grid, a, f.f))
                for (int b = 0; b < 3; ++b) rhs_(pattern_.unknown[c], b) += w * walls[a][side][b];
        }
    }
    bool factored = false;
    if (factorisation_ == Factorisation::supernodal) {
        factored = ldlt_.factorize(pattern_.matrix, mesh.parallel);
    } else {
        simplicial_.factorize(pattern_.matrix);
        factored = simplicial_.info() == Eigen::Success;
    }
    if (!factored) throw InvariantError("flow: the coupled viscosity matrix could not be factorised (not positive definite)");
    const Eigen::MatrixXd u = solve_columns(mesh.parallel);
    for (std::size_t c : mesh.inside_cells)
        for (int b = 0; b < 3; ++b) {
            state.u[b][c] = u(pattern_.unknown[c], b);
            state.m[b][c] = Phi[c] * state.u[b][c];
        }
}

Eigen::MatrixXd CoupledViscosity::solve_columns(bool parallel) const {
    Eigen::MatrixXd x = Eigen::MatrixXd::Zero(rhs_.rows(), rhs_.cols());
    std::vector<Eigen::Index> columns;  // a zero column solves to zero exactly
    for (Eigen::Index b = 0; b < rhs_.cols(); ++b)
        if (!rhs_.col(b).isZero(0.0)) columns.push_back(b);
    // The columns' solves are independent: one per thread.
    parallel_for(parallel && columns.size() > 1, columns.size(), [&](std::size_t q) {
        if (factorisation_ == Factorisation::simplicial) {
            x.col(columns[q]) = simplicial_.solve(rhs_.col(columns[q]));
            return;
        }
        x.col(columns[q]) = rhs_.col(columns[q]);
        ldlt_.solve(x.col(columns[q]).data());
    });
    return x;
}

void CoupledViscosity::diffuse_change(const FlowMesh& mesh, std::array<std::vector<double>, 3>& du) {
    for (std::size_t c : mesh.inside_cells) {
        const long r = pattern_.unknown[c];
        for (int b = 0; b < 3; ++b) rhs_(r, b) = mass_[r] * du[b][c];
    }
    const Eigen::MatrixXd w = solve_columns(mesh.parallel);
    for (std::size_t c : mesh.inside_cells) {
        const long r = pattern_.unknown[c];
        if (mass_[r] > 0.0)
            for (int b = 0; b < 3; ++b) du[b][c] = w(r, b);
    }
}

}  // namespace granseg
