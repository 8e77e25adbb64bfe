#include "flow/time_step.hpp"

#include "core/error.hpp"
#include "core/format.hpp"
#include "flow/semi_implicit.hpp"

#include <algorithm>
#include <cmath>
#include <string>

namespace granseg {

StepRates explicit_step_rates(const FlowMesh& mesh, const FlowState& state, const CellClosures& cl,
                              const FlowFaces& faces) {
    const std::size_t nx = mesh.grid.n[0];
    const double *Phi = state.Phi.data(), *rcp = cl.Phi_rcp.data();
    const unsigned char* in = mesh.inside.data();
    const double* M[3] = {faces[0].mass.data(), faces[1].mass.data(), faces[2].mass.data()};
    const double* S[3] = {faces[0].speed.data(), faces[1].speed.data(), faces[2].speed.data()};
    double inv_h[3];
    for (int a = 0; a < 3; ++a) inv_h[a] = mesh.active[a] ? 1.0 / mesh.grid.h[a] : 0.0;
    double rate = 0.0, outflow_rate = 0.0, compaction_rate = 0.0;
#pragma omp parallel for reduction(max : rate, outflow_rate, compaction_rate) schedule(static) if (mesh.parallel)
    for (std::size_t r = 0; r < mesh.rows; ++r) {
        AxisRow ar[3];
        for (int a = 0; a < 3; ++a) ar[a] = mesh.axis_row(a, r);
        for (int i = mesh.row_lo[r]; i < mesh.row_hi[r]; ++i) {
            const std::size_t c = nx * r + i;
            if (!in[c]) continue;
            double cfl = 0.0, out = 0.0, div = 0.0;
            for (int a = 0; a < 3; ++a) {
                if (inv_h[a] == 0.0) continue;
                const std::size_t fl = ar[a].face0 + i, fu = fl + ar[a].face_step;
                cfl += std::max(S[a][fl], S[a][fu]) * inv_h[a];
                out += (std::max(0.0, M[a][fu]) + std::max(0.0, -M[a][fl])) * inv_h[a];
                div += (M[a][fu] - M[a][fl]) * inv_h[a];
            }
            rate = std::max(rate, cfl);
            if (out > 0.0) outflow_rate = std::max(outflow_rate, Phi[c] > 0.0 ? out / Phi[c] : INFINITY);
            if (div < 0.0) compaction_rate = std::max(compaction_rate, -div / (rcp[c] - Phi[c]));
        }
    }
    return {rate, outflow_rate, compaction_rate};
}

StepRates material_step_rates(const FlowMesh& mesh, const FlowState& state, const CellClosures& closures,
                              const FlowFaces& faces, bool first) {
    const std::size_t nx = mesh.grid.n[0];
    const double sound = first ? 1.0 : 0.0, *cs = closures.c.data();
    const double *Phi = state.Phi.data(), *Phi_co = closures.Phi_co.data(), *rcp = closures.Phi_rcp.data();
    const double* M[3] = {faces[0].mass.data(), faces[1].mass.data(), faces[2].mass.data()};
    const double* S[3] = {faces[0].speed.data(), faces[1].speed.data(), faces[2].speed.data()};
    const double* u[3] = {state.u[0].data(), state.u[1].data(), state.u[2].data()};
    double inv_h[3];
    for (int a = 0; a < 3; ++a) inv_h[a] = mesh.active[a] ? 1.0 / mesh.grid.h[a] : 0.0;
    double rate = 0.0, outflow_rate = 0.0, compaction_rate = 0.0;
#pragma omp parallel for reduction(max : rate, outflow_rate, compaction_rate) schedule(static) if (mesh.parallel)
    for (std::size_t r = 0; r < mesh.rows; ++r) {
        AxisRow ar[3];
        for (int a = 0; a < 3; ++a) ar[a] = mesh.axis_row(a, r);
        for (int i = mesh.row_lo[r]; i < mesh.row_hi[r]; ++i) {
            const std::size_t c = nx * r + i;
            if (!mesh.inside[c]) continue;
            const double own = is_dust(Phi[c], Phi_co[c]) ? 0.0 : 1.0;  // dust: its outflow is capped instead
            double cfl = 0.0, out = 0.0, div = 0.0;
            for (int a = 0; a < 3; ++a) {
                if (inv_h[a] == 0.0) continue;
                const std::size_t fl = ar[a].face0 + i, fu = fl + ar[a].face_step;
                cfl += (std::max({own * std::fabs(u[a][c]), S[a][fl], S[a][fu]}) + sound * cs[c]) * inv_h[a];
                out += (std::max(0.0, M[a][fu]) + std::max(0.0, -M[a][fl])) * inv_h[a];
                div += (M[a][fu] - M[a][fl]) * inv_h[a];
            }
            rate = std::max(rate, cfl);
            if (out > 0.0 && own > 0.0) outflow_rate = std::max(outflow_rate, 2.0 * out / Phi[c]);
            if (div < 0.0) compaction_rate = std::max(compaction_rate, -div / (rcp[c] - Phi[c]));
        }
    }
    return {rate, outflow_rate, compaction_rate};
}

const char* step_bound_name(StepBound bound) {
    static const char* const names[kStepBounds] = {"dt_max", "cfl", "outflow", "compaction", "growth", "halved"};
    return names[static_cast<int>(bound)];
}

StepSize time_step(const FlowMesh& mesh, const FlowSettings& settings, double t, double t_end,
                   const StepRates& rates, const FlowState& state, const CellClosures& cl) {
    double dt = std::min(settings.dt_max, t_end - t);
    const double dt_cfl = rates.waves > 0.0 ? settings.cfl / rates.waves : INFINITY;
    const double dt_outflow = rates.outflow > 0.0 ? kOutflowFraction / rates.outflow : INFINITY;
    const double dt_compaction = rates.compaction > 0.0 ? kCompactionFraction / rates.compaction : INFINITY;
    dt = std::min({dt, dt_cfl, dt_outflow, dt_compaction});
    const StepBound bound = dt == dt_cfl          ? StepBound::cfl
                            : dt == dt_outflow    ? StepBound::outflow
                            : dt == dt_compaction ? StepBound::compaction
                                                  : StepBound::dt_max;
    if (!(dt >= settings.dt_min) && t_end - t > settings.dt_min) {
        double c_max = 0.0, Phi_at = 0.0;
        for (std::size_t c : mesh.inside_cells)
            if (cl.c[c] > c_max) c_max = cl.c[c], Phi_at = state.Phi[c];
        const std::string cause =
            bound == StepBound::compaction ? "the compaction bound: the bed is compacted towards Phi_rcp faster than this resolution can follow"
            : bound == StepBound::outflow  ? "the outflow bound: a cell loses more than its mass (outflow rate " + format_number(rates.outflow) + " 1/s)"
                                           : "the CFL condition";
        throw InvariantError("flow: time step " + format_number(dt) + " s fell below dt_min = " +
                             format_number(settings.dt_min) + " s at t = " + format_number(t) + " s, set by " + cause +
                             " (largest sound speed c = " + format_number(c_max) + " m/s at Phi = " + format_number(Phi_at, 8) + ")");
    }
    return {dt, bound};
}

bool step_within_bounds(const FlowMesh& mesh, double dt, const std::vector<double>& Phi_before,
                        const CellClosures& cl, const FlowFaces& faces) {
    const double* M[3] = {faces[0].mass.data(), faces[1].mass.data(), faces[2].mass.data()};
    double inv_h[3];
    for (int a = 0; a < 3; ++a) inv_h[a] = mesh.active[a] ? 1.0 / mesh.grid.h[a] : 0.0;
    long bad = 0;
#pragma omp parallel for reduction(+ : bad) schedule(static) if (mesh.parallel)
    for (std::size_t r = 0; r < mesh.rows; ++r) {
        AxisRow ar[3];
        for (int a = 0; a < 3; ++a) ar[a] = mesh.axis_row(a, r);
        for (int i = mesh.row_lo[r]; i < mesh.row_hi[r]; ++i) {
            const std::size_t c = mesh.grid.n[0] * r + i;
            if (!mesh.inside[c]) continue;
            double out = 0.0, div = 0.0;
            for (int a = 0; a < 3; ++a) {
                if (inv_h[a] == 0.0) continue;
                const std::size_t fl = ar[a].face0 + i, fu = fl + ar[a].face_step;
                out += (std::max(0.0, M[a][fu]) + std::max(0.0, -M[a][fl])) * inv_h[a];
                div += (M[a][fu] - M[a][fl]) * inv_h[a];
            }
            const bool ok = dt * out <= kOutflowFraction * Phi_before[c] &&
                            -dt * div <= kCompactionFraction * (cl.Phi_rcp[c] - Phi_before[c]);
            bad += ok ? 0 : 1;
        }
    }
    return bad == 0;
}

}  // namespace granseg
