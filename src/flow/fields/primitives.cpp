#include "flow/fields/primitives.hpp"

#include "closures/closures.hpp"
#include "core/error.hpp"
#include "core/format.hpp"
#include "core/threads.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <string>

namespace granseg {

void compute_primitives(const FlowMesh& mesh, const Material& mat, const FlowSettings& settings,
                        const std::vector<double>& phi_hat, double t, FlowState& state, CellClosures& cl) {
    const double Phi_vac = settings.Phi_vacuum, T_floor = settings.T_floor;
    const double rcp0 = mat.packing.Phi_rcp(settings.phi_hat), co0 = mat.packing.Phi_co(settings.phi_hat);
    const std::size_t nx = mesh.grid.n[0];
    const double *Phi = state.Phi.data(), *E = state.E.data(), *mx = state.m[0].data(), *my = state.m[1].data(),
                 *mz = state.m[2].data();
    const unsigned char* in = mesh.inside.data();
    double *ux = state.u[0].data(), *uy = state.u[1].data(), *uz = state.u[2].data(), *T = state.T.data();
    double *p = cl.p.data(), *cs = cl.c.data(), *eta = cl.eta.data(), *lambda = cl.lambda.data(), *epsPhi = cl.epsPhi.data(),
           *rcp = cl.Phi_rcp.data(), *co = cl.Phi_co.data();
    const bool per_cell = !phi_hat.empty();
    auto row = [&](long& packed_cells, std::size_t r) {
        const std::size_t base = nx * r;
        if (per_cell)
            for (int i = mesh.row_lo[r]; i < mesh.row_hi[r]; ++i) {
                rcp[base + i] = mat.packing.Phi_rcp(phi_hat[base + i]);
                co[base + i] = mat.packing.Phi_co(phi_hat[base + i]);
            }
        long packed = 0;
#pragma omp simd reduction(+ : packed)
        for (int i = mesh.row_lo[r]; i < mesh.row_hi[r]; ++i) {
            const std::size_t c = base + i;
            if (!in[c]) continue;
            const bool empty = Phi[c] <= Phi_vac;
            const double inv = empty ? 0.0 : 1.0 / Phi[c];
            ux[c] = mx[c] * inv, uy[c] = my[c] * inv, uz[c] = mz[c] * inv;
            T[c] = empty ? T_floor : E[c] * inv;
            const double Phi_rcp = per_cell ? rcp[c] : rcp0, Phi_co = per_cell ? co[c] : co0;
            packed += Phi[c] < Phi_rcp ? 0 : 1;
            const ClosureValues v = evaluate_closures_at(mat, Phi[c], T[c], Phi_rcp, Phi_co);
            p[c] = v.p;
            cs[c] = std::sqrt(v.c2);
            eta[c] = empty ? 0.0 : v.eta;
            lambda[c] = empty ? 0.0 : v.lambda;
            epsPhi[c] = empty ? 0.0 : v.eps * Phi[c];
            rcp[c] = Phi_rcp, co[c] = Phi_co;
        }
        packed_cells += packed;
    };
    if (parallel_fold(mesh.parallel, mesh.rows, 0L, row, std::plus<long>()) > 0)
        for (std::size_t c : mesh.inside_cells)
            if (!(state.Phi[c] < cl.Phi_rcp[c]))
                throw InvariantError("flow: Phi = " + format_number(state.Phi[c], 8) + " reached Phi_rcp = " +
                                     format_number(cl.Phi_rcp[c], 8) + " at x = " + format_number(mesh.position[0][c]) +
                                     ", z = " + format_number(mesh.position[2][c]) + ", t = " + format_number(t) +
                                     " s: the packing limit is a wall of the model (eq. 18); the flow compacted the "
                                     "bed faster than the pressure could resist at this resolution and cfl");
}

void effective_pressure(const FlowMesh& mesh, const FlowFaces& faces, CellClosures& cl) {
    double *eta = cl.eta.data(), *lambda = cl.lambda.data(), *epsPhi = cl.epsPhi.data();
    const double* p = cl.p.data();
    const double* P[3] = {faces[0].p.data(), faces[1].p.data(), faces[2].p.data()};
    mesh.parallel_for_inside_cells([&](std::size_t c, int i, const AxisRow* ar) {
        double p_eff = p[c];
        for (int a = 0; a < 3; ++a) {
            if (!mesh.active[a]) continue;
            const std::size_t fl = ar[a].face0 + i, fu = fl + ar[a].face_step;
            p_eff = std::max(p_eff, 0.5 * (P[a][fl] + P[a][fu]));
        }
        const double scale = p[c] > 0.0 ? p_eff / p[c] : 0.0;
        eta[c] *= scale, lambda[c] *= scale, epsPhi[c] *= scale;
    });
}

}  // namespace granseg
