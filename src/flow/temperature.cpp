#include "flow/temperature.hpp"

#include <algorithm>

namespace granseg {

void implicit_temperature(const FlowMesh& mesh, const FlowSettings& settings, const WallVelocities& walls, double dt,
                          const CellClosures& cl, DiffusionLines& lines, std::vector<double>& heat,
                          std::vector<double>& work, FlowState& state) {
    const std::size_t nx = mesh.grid.n[0];
    const double Phi_vac = settings.Phi_vacuum, T_floor = settings.T_floor;
    // 1. Heating and dissipation.
    const double* eta = cl.eta.data();
    const unsigned char* in = mesh.inside.data();
    const auto& u = state.u;
#pragma omp parallel for schedule(static) if (mesh.parallel)
    for (std::size_t row = 0; row < mesh.rows; ++row)
        for (int i = mesh.row_lo[row]; i < mesh.row_hi[row]; ++i) heat[nx * row + i] = 0.0;
    for (int a = 0; a < 3; ++a) {
        if (!mesh.active[a]) continue;
        const double inv_h2 = 1.0 / (mesh.grid.h[a] * mesh.grid.h[a]);
        const unsigned char* kind = mesh.face_kind[a].data();
#pragma omp parallel for schedule(static) if (mesh.parallel)
        for (std::size_t row = 0; row < mesh.rows; ++row) {
            const AxisRow ar = mesh.axis_row(a, row);
            for (int i = mesh.row_lo[row]; i < mesh.row_hi[row]; ++i) {
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
                        const double other = interior ? u[b][nb] : boundary ? walls[a][side][b] : 0.0;
                        sum += (other - u[b][c]) * (other - u[b][c]);
                    }
                    h += (interior ? 0.5 * harmonic_mean(eta[c], eta[nb]) : 2.0 * eta[c]) * sum * inv_h2;
                }
                heat[c] += h;
            }
        }
    }
    std::vector<double>&T = state.T;
    const std::vector<double>& Phi = state.Phi;
    mesh.for_each_inside([&](std::size_t c) {
        T[c] = Phi[c] <= Phi_vac ? T_floor : (Phi[c] * T[c] + dt * 1.5 * heat[c]) / (Phi[c] + dt * cl.epsPhi[c]);  // eq. (14)
    });
    // 2. Conduction, one axis after the other.
    for (int a = 0; a < 3; ++a) {
        if (!mesh.active[a]) continue;
        lines.factor(mesh, a, 1.5 * dt / (mesh.grid.h[a] * mesh.grid.h[a]), Phi, cl.lambda, false, Phi_vac);
        mesh.for_each_inside([&](std::size_t c) { work[c] = Phi[c] <= Phi_vac ? T_floor : Phi[c] * T[c]; });
        lines.solve(work);
        T.swap(work);
    }
    // 3. Floor (docs/assumptions.md) and the conserved variable.
    mesh.for_each_inside([&](std::size_t c) {
        T[c] = std::max(T[c], T_floor);
        state.E[c] = Phi[c] * T[c];
    });
}

}  // namespace granseg
