#include "flow/diffusion/viscosity.hpp"

namespace granseg {

void implicit_viscosity(const FlowMesh& mesh, const FlowSettings& settings, const WallVelocities& walls, double dt,
                        const std::vector<double>& eta_in, DiffusionLines& lines, std::vector<double>& work, FlowState& state) {
    const double Phi_vac = settings.Phi_vacuum;
    for (int a = 0; a < 3; ++a) {
        if (!mesh.active[a]) continue;
        const double r = dt / (mesh.grid.h[a] * mesh.grid.h[a]);
        lines.factor(mesh, a, r, state.Phi, eta_in, true, Phi_vac);
        for (int b = 0; b < 3; ++b) {
            // Right-hand side Phi u, plus 2 dt eta/h^2 U_wall on a moving wall of the domain
            // boundary (embedded walls are at rest).
            const double U_lo = 2.0 * r * walls[a][0][b], U_hi = 2.0 * r * walls[a][1][b];
            const double *Phi = state.Phi.data(), *u = state.u[b].data(), *eta = eta_in.data();
            const unsigned char *in = mesh.inside.data(), *kind = mesh.face_kind[a].data();
            const Grid* grid = &mesh.grid;
            double* rhs = work.data();
            mesh.parallel_for_row_cells(a, [=](std::size_t c, int i, const AxisRow& ar) {
                const std::size_t fl = ar.face0 + i, fu = fl + ar.face_step;
                double value = Phi[c] * u[c];
                if (kind[fl] == kWallBelow && on_domain_boundary(*grid, a, fl)) value += U_lo * eta[c];
                if (kind[fu] == kWallAbove && on_domain_boundary(*grid, a, fu)) value += U_hi * eta[c];
                rhs[c] = in[c] && Phi[c] > Phi_vac ? value : 0.0;
            });
            lines.solve(work);
            state.u[b].swap(work);
        }
    }
    mesh.parallel_for_inside([&](std::size_t c) {
        for (int b = 0; b < 3; ++b) state.m[b][c] = state.Phi[c] * state.u[b][c];
    });
}

}  // namespace granseg
