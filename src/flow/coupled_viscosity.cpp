#include "flow/coupled_viscosity.hpp"

#include "core/error.hpp"
#include "flow/diffusion_lines.hpp"

#include <algorithm>

namespace granseg {

CoupledViscosity::CoupledViscosity(const FlowMesh& mesh) {
    const Grid& grid = mesh.grid;
    unknown_.assign(grid.cells(), -1);
    long rows = 0;
    for (std::size_t c : mesh.inside_cells) unknown_[c] = rows++;
    std::vector<Eigen::Triplet<double>> pattern;
    for (long r = 0; r < rows; ++r) pattern.emplace_back(r, r, 0.0);
    for (int a = 0; a < 3; ++a)
        for (const MeshFace& f : mesh.faces[a])
            if (mesh.active[a] && f.kind == kInterior && !f.repeat) {
                pattern.emplace_back(unknown_[f.lo], unknown_[f.hi], 0.0);
                pattern.emplace_back(unknown_[f.hi], unknown_[f.lo], 0.0);
            }
    A_.resize(rows, rows);
    A_.setFromTriplets(pattern.begin(), pattern.end());
    A_.makeCompressed();
    auto position = [&](long row, long col) {
        for (long k = A_.outerIndexPtr()[col]; k < A_.outerIndexPtr()[col + 1]; ++k)
            if (A_.innerIndexPtr()[k] == row) return k;
        return -1L;
    };
    diagonal_.resize(rows);
    for (long r = 0; r < rows; ++r) diagonal_[r] = position(r, r);
    for (int a = 0; a < 3; ++a) {
        entry_[a].assign(grid.faces(a), -1);
        mirror_[a].assign(grid.faces(a), -1);
        for (const MeshFace& f : mesh.faces[a])
            if (mesh.active[a] && f.kind == kInterior && !f.repeat) {
                entry_[a][f.f] = position(unknown_[f.lo], unknown_[f.hi]);
                mirror_[a][f.f] = position(unknown_[f.hi], unknown_[f.lo]);
            }
    }
    set_up();
}

CoupledViscosity::CoupledViscosity(const CoupledViscosity& other)
    : unknown_(other.unknown_), entry_(other.entry_), mirror_(other.mirror_), diagonal_(other.diagonal_), A_(other.A_) {
    set_up();
}

CoupledViscosity& CoupledViscosity::operator=(const CoupledViscosity& other) {
    if (this == &other) return *this;
    unknown_ = other.unknown_, entry_ = other.entry_, mirror_ = other.mirror_, diagonal_ = other.diagonal_;
    A_ = other.A_;
    set_up();
    return *this;
}

void CoupledViscosity::set_up() {
    rhs_.setZero(A_.rows(), 3);
    ldlt_.analyzePattern(A_);  // the fill-reducing ordering, once per pattern
}

void CoupledViscosity::apply(const FlowMesh& mesh, const FlowSettings& settings, const WallVelocities& walls, double dt,
                             const std::vector<double>& eta, FlowState& state) {
    const Grid& grid = mesh.grid;
    const std::vector<double>& Phi = state.Phi;
    auto active = [&](std::size_t c) { return Phi[c] > settings.Phi_vacuum; };
    double* value = A_.valuePtr();
    std::fill(value, value + A_.nonZeros(), 0.0);
    // Mass rows; an empty cell is an identity row with right-hand side 0 (at rest).
    for (std::size_t c : mesh.inside_cells) {
        const long r = unknown_[c];
        value[diagonal_[r]] = active(c) ? Phi[c] : 1.0;
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
                const double w = r * harmonic_mean(eta[f.lo], eta[f.hi]);
                const bool lo = active(f.lo), hi = active(f.hi);
                if (lo) value[diagonal_[unknown_[f.lo]]] += w;
                if (hi) value[diagonal_[unknown_[f.hi]]] += w;
                if (lo && hi) value[entry_[a][f.f]] -= w, value[mirror_[a][f.f]] -= w;
                continue;
            }
            const std::size_t c = f.lo;  // a wall: both sides name the inside cell
            if (!active(c)) continue;
            const double w = 2.0 * r * eta[c];
            value[diagonal_[unknown_[c]]] += w;
            // Moving walls are those of the domain boundary (embedded walls are at rest).
            const int side = f.kind == kWallBelow ? 0 : 1;
            const int index = static_cast<int>((c / grid.stride(a)) % grid.n[a]);
            if (index == (side == 0 ? 0 : grid.n[a] - 1))
                for (int b = 0; b < 3; ++b) rhs_(unknown_[c], b) += w * walls[a][side][b];
        }
    }
    ldlt_.factorize(A_);
    if (ldlt_.info() != Eigen::Success)
        throw InvariantError("flow: the coupled viscosity matrix could not be factorised (not positive definite)");
    const Eigen::MatrixXd u = ldlt_.solve(rhs_);
    for (std::size_t c : mesh.inside_cells)
        for (int b = 0; b < 3; ++b) {
            state.u[b][c] = u(unknown_[c], b);
            state.m[b][c] = Phi[c] * state.u[b][c];
        }
}

}  // namespace granseg
