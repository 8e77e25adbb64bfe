// FlowSolver, implicit part of a step: viscosity (eqs. 9-11), heating, dissipation and
// conduction (eq. 14), each split by axis into tridiagonal line solves (flow/line_solver.hpp);
// and the cell velocity gradient handed to the segregation solver.
//
// With the asymmetric stress eta grad u (eqs. 10-11) every velocity component obeys
//   Phi (u_new - u)/dt = sum_axis d/dx_a (eta d u_new/dx_a),
// which has no mixed derivatives; the axes are taken one after the other (Lie/ADI splitting).
// Face coefficients are harmonic means of the two cells' values, so a face between the bed and
// near-empty air carries almost no stress or heat. The coefficients eta, lambda, eps are those of
// the state at the start of the step (linearly implicit), at the effective pressure
// (FlowSolver::effective_pressure_and_step). Outside and empty cells are identity rows (set once).
#include "flow/flow_solver.hpp"

#include <algorithm>
#include <cmath>

namespace granseg {

namespace {
inline double harmonic_mean(double a, double b) {
    const double s = a + b;
    return s > 0.0 ? 2.0 * a * b / s : 0.0;
}
}  // namespace

void FlowSolver::diffusion_rows(int a, double r, const std::vector<double>& kappa, bool no_slip) {
    const double *Phi = Phi_.data(), *k = kappa.data();
    const unsigned char *in = inside_.data(), *kind = face_kind_[a].data();
    double *lower = lower_.data(), *diag = diag_.data(), *upper = upper_.data();
    const double Phi_vac = settings_.Phi_vacuum, wall = no_slip ? 2.0 * r : 0.0;
    for_row_cells(a, [=](std::size_t c, int i, const AxisRow& ar) {
        const std::size_t fl = ar.face0 + i, fu = fl + ar.face_step;
        const bool active = in[c] && Phi[c] > Phi_vac;
        const bool in_lo = kind[fl] == kInterior, in_hi = kind[fu] == kInterior;
        const double w_lo = in_lo ? r * harmonic_mean(k[c], k[c + ar.lo_at(i)]) : wall * k[c];
        const double w_hi = in_hi ? r * harmonic_mean(k[c], k[c + ar.hi_at(i)]) : wall * k[c];
        lower[c] = active && in_lo ? w_lo : 0.0;
        upper[c] = active && in_hi ? w_hi : 0.0;
        diag[c] = active ? Phi[c] + w_lo + w_hi : 1.0;
    });
    lines_.factor(grid_, a, lower_, diag_, upper_);
}

void FlowSolver::implicit_viscosity(double dt) {
    const double Phi_vac = settings_.Phi_vacuum;
    for (int a = 0; a < 3; ++a) {
        if (!active_[a]) continue;
        const double r = dt / (grid_.h[a] * grid_.h[a]);
        diffusion_rows(a, r, eta_, true);
        for (int b = 0; b < 3; ++b) {
            // Right-hand side Phi u, plus 2 dt eta/h^2 U_wall on a moving wall of the domain
            // boundary (embedded walls are at rest).
            const double U_lo = 2.0 * r * wall_velocity_[a][0][b], U_hi = 2.0 * r * wall_velocity_[a][1][b];
            const double *Phi = Phi_.data(), *u = u_[b].data(), *eta = eta_.data();
            const unsigned char *in = inside_.data(), *kind = face_kind_[a].data();
            double* rhs = work_.data();
            for_row_cells(a, [=](std::size_t c, int i, const AxisRow& ar) {
                const std::size_t fl = ar.face0 + i, fu = fl + ar.face_step;
                double value = Phi[c] * u[c];
                if (kind[fl] == kWallBelow && ar.lo_at(i) == 0) value += U_lo * eta[c];
                if (kind[fu] == kWallAbove && ar.hi_at(i) == 0) value += U_hi * eta[c];
                rhs[c] = in[c] && Phi[c] > Phi_vac ? value : 0.0;
            });
            lines_.solve(work_);
            u_[b].swap(work_);
        }
    }
    const std::size_t n = inside_cells_.size();
#pragma omp parallel for schedule(static) if (parallel_)
    for (std::size_t q = 0; q < n; ++q) {
        const std::size_t c = inside_cells_[q];
        for (int b = 0; b < 3; ++b) m_[b][c] = Phi_[c] * u_[b][c];
    }
    gradient_valid_ = false;
}

void FlowSolver::implicit_temperature(double dt) {
    const std::size_t nx = grid_.n[0];
    const double Phi_vac = settings_.Phi_vacuum, T_floor = settings_.T_floor;
    // 1. Heating (3/2) eta kappa:kappa as the dissipation of the discrete viscous operator: half of
    //    eta_f ((u_nb - u)/h)^2 of each interior face, all of 2 eta ((U_wall - u)/h)^2 of a wall face.
    //    With dissipation: Phi (T - T*)/dt = (3/2) H - eps Phi T, eps at the start of the step. As
    //    (3/2) eta/(eps Phi) = (3/2) eta0/eps0, T moves towards eq. (45)'s value and never past it.
    const double* eta = eta_.data();
    const unsigned char* in = inside_.data();
    std::vector<double>& heat = lower_;  // work space; the line coefficients are rebuilt below
#pragma omp parallel for schedule(static) if (parallel_)
    for (std::size_t row = 0; row < rows_; ++row)
        for (int i = row_lo_[row]; i < row_hi_[row]; ++i) heat[nx * row + i] = 0.0;
    for (int a = 0; a < 3; ++a) {
        if (!active_[a]) continue;
        const double inv_h2 = 1.0 / (grid_.h[a] * grid_.h[a]);
        const unsigned char* kind = face_kind_[a].data();
#pragma omp parallel for schedule(static) if (parallel_)
        for (std::size_t row = 0; row < rows_; ++row) {
            const AxisRow ar = axis_row(a, row);
            for (int i = row_lo_[row]; i < row_hi_[row]; ++i) {
                const std::size_t c = nx * row + i, fl = ar.face0 + i, fu = fl + ar.face_step;
                if (!in[c]) continue;
                const long lo = ar.lo_at(i), hi = ar.hi_at(i);
                double h = 0.0;
                for (int side = 0; side < 2; ++side) {
                    const unsigned char k = kind[side == 0 ? fl : fu];
                    const std::size_t nb = c + (side == 0 ? lo : hi);
                    const bool interior = k == kInterior, boundary = (side == 0 ? lo : hi) == 0;
                    double sum = 0.0;
                    for (int b = 0; b < 3; ++b) {
                        const double other = interior ? u_[b][nb] : boundary ? wall_velocity_[a][side][b] : 0.0;
                        sum += (other - u_[b][c]) * (other - u_[b][c]);
                    }
                    h += (interior ? 0.5 * harmonic_mean(eta[c], eta[nb]) : 2.0 * eta[c]) * sum * inv_h2;
                }
                heat[c] += h;
            }
        }
    }
    const std::size_t n = inside_cells_.size();
#pragma omp parallel for schedule(static) if (parallel_)
    for (std::size_t q = 0; q < n; ++q) {
        const std::size_t c = inside_cells_[q];
        T_[c] = Phi_[c] <= Phi_vac ? T_floor : (Phi_[c] * T_[c] + dt * 1.5 * heat[c]) / (Phi_[c] + dt * epsPhi_[c]);  // eq. (14)
    }
    // 2. Conduction (3/2) div(lambda grad T), adiabatic walls, one axis after the other.
    for (int a = 0; a < 3; ++a) {
        if (!active_[a]) continue;
        diffusion_rows(a, 1.5 * dt / (grid_.h[a] * grid_.h[a]), lambda_, false);
#pragma omp parallel for schedule(static) if (parallel_)
        for (std::size_t q = 0; q < n; ++q) {
            const std::size_t c = inside_cells_[q];
            work_[c] = Phi_[c] <= Phi_vac ? T_floor : Phi_[c] * T_[c];
        }
        lines_.solve(work_);
        T_.swap(work_);
    }
    // 3. Floor (docs/assumptions.md) and the conserved variable.
#pragma omp parallel for schedule(static) if (parallel_)
    for (std::size_t q = 0; q < n; ++q) {
        const std::size_t c = inside_cells_[q];
        T_[c] = std::max(T_[c], T_floor);
        E_[c] = Phi_[c] * T_[c];
    }
}

void FlowSolver::update_velocity_gradient() const {
    // Central differences; a wall contributes the no-slip ghost 2 U_wall - u, an empty neighbour
    // (free surface) the cell's own value.
    const std::size_t nx = grid_.n[0];
    const double Phi_vac = settings_.Phi_vacuum;
    for (int a = 0; a < 3; ++a) {
        const double inv_2h = 0.5 / grid_.h[a];
        const unsigned char* kind = face_kind_[a].data();
        for (std::size_t row = 0; row < rows_; ++row) {
            const AxisRow ar = axis_row(a, row);
            for (int i = row_lo_[row]; i < row_hi_[row]; ++i) {
                const std::size_t c = nx * row + i, fl = ar.face0 + i, fu = fl + ar.face_step;
                if (!inside_[c]) continue;
                for (int b = 0; b < 3; ++b) {
                    auto value = [&](unsigned char k, long offset, int side) {
                        if (k == kInterior) return Phi_[c + offset] > Phi_vac ? u_[b][c + offset] : u_[b][c];
                        return 2.0 * (offset == 0 ? wall_velocity_[a][side][b] : 0.0) - u_[b][c];
                    };
                    grad_[3 * b + a][c] = active_[a] ? (value(kind[fu], ar.hi_at(i), 1) - value(kind[fl], ar.lo_at(i), 0)) * inv_2h : 0.0;
                }
            }
        }
    }
    gradient_valid_ = true;
}

}  // namespace granseg
