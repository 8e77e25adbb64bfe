#include "flow/velocity_gradient.hpp"

#include "flow/diffusion/diffusion_faces.hpp"

namespace granseg {

void velocity_gradient(const FlowMesh& mesh, const FlowSettings& settings, const WallVelocities& walls,
                       const std::vector<double>& Phi, const std::array<std::vector<double>, 3>& u,
                       std::array<std::vector<double>, 9>& grad) {
    const std::size_t nx = mesh.grid.n[0];
    const double Phi_vac = settings.Phi_vacuum;
    for (int a = 0; a < 3; ++a) {
        const double inv_2h = 0.5 / mesh.grid.h[a];
        const unsigned char* kind = mesh.face_kind[a].data();
        for (std::size_t row = 0; row < mesh.rows; ++row) {
            const AxisRow ar = mesh.axis_row(a, row);
            for (int i = mesh.row_lo[row]; i < mesh.row_hi[row]; ++i) {
                const std::size_t c = nx * row + i, fl = ar.face0 + i, fu = fl + ar.face_step;
                if (!mesh.inside[c]) continue;
                for (int b = 0; b < 3; ++b) {
                    // The value beyond a face: the neighbour's (the cell's own if the neighbour is
                    // empty), or the no-slip ghost 2 U_wall - u of a wall.
                    auto value = [&](std::size_t f, long offset, int side) {
                        if (kind[f] == kInterior) return Phi[c + offset] > Phi_vac ? u[b][c + offset] : u[b][c];
                        return 2.0 * wall_velocity(mesh.grid, walls, a, side, f, b) - u[b][c];
                    };
                    grad[3 * b + a][c] = mesh.active[a] ? (value(fu, ar.hi_at(i), 1) - value(fl, ar.lo_at(i), 0)) * inv_2h : 0.0;
                }
            }
        }
    }
}

}  // namespace granseg
