#include "flow/time_step.hpp"

#include "core/error.hpp"
#include "core/format.hpp"
#include "core/threads.hpp"
#include "flow/faces/semi_implicit_faces.hpp"
#include "flow/fields/face_balance.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <string>

namespace granseg {

namespace {
/// The largest rates over inside cells (StepRates): wave(c, i, rows) is the cell's wave rate,
/// outflow(c, out) its outflow rate for an outflow out > 0 (face_outflow with 1/h), and the
/// compaction rate is its net inflow over the gap Phi_rcp - Phi.
template <class Wave, class Outflow>
StepRates largest_rates(const FlowMesh& mesh, const FlowState& state, const CellClosures& closures, const FlowFaces& faces,
                        Wave&& wave, Outflow&& outflow) {
    const std::size_t nx = mesh.grid.n[0];
    const double *Phi = state.Phi.data(), *rcp = closures.Phi_rcp.data();
    const AxisFields M = axis_fields(faces, &AxisFaces::mass);
    const AxisWeights inv_h = axis_weights(mesh);
    auto row = [&](StepRates& rates, std::size_t r) {
        AxisRow ar[3];
        for (int a = 0; a < 3; ++a) ar[a] = mesh.axis_row(a, r);
        for (int i = mesh.row_lo[r]; i < mesh.row_hi[r]; ++i) {
            const std::size_t c = nx * r + i;
            if (!mesh.inside[c]) continue;
            rates.waves = std::max(rates.waves, wave(c, i, ar));
            const double out = face_outflow(M, inv_h, i, ar), div = face_balance(M, inv_h, i, ar);
            if (out > 0.0) rates.outflow = std::max(rates.outflow, outflow(c, out));
            if (div < 0.0) rates.compaction = std::max(rates.compaction, -div / (rcp[c] - Phi[c]));
        }
    };
    return parallel_fold(mesh.parallel, mesh.rows, StepRates{0.0, 0.0, 0.0}, row, [](const StepRates& x, const StepRates& y) {
        return StepRates{std::max(x.waves, y.waves), std::max(x.outflow, y.outflow), std::max(x.compaction, y.compaction)};
    });
}
}  // namespace

StepRates explicit_step_rates(const FlowMesh& mesh, const FlowState& state, const CellClosures& closures,
                              const FlowFaces& faces) {
    const AxisFields S = axis_fields(faces, &AxisFaces::speed);
    const AxisWeights inv_h = axis_weights(mesh);
    const double* Phi = state.Phi.data();
    auto wave = [&](std::size_t, int i, const AxisRow* ar) {
        return sum_over_axes(inv_h, i, ar, [&](int a, std::size_t fl, std::size_t fu) { return std::max(S[a][fl], S[a][fu]); });
    };
    auto outflow = [&](std::size_t c, double out) { return Phi[c] > 0.0 ? out / Phi[c] : INFINITY; };
    return largest_rates(mesh, state, closures, faces, wave, outflow);
}

StepRates material_step_rates(const FlowMesh& mesh, const FlowState& state, const CellClosures& closures, const FlowFaces& faces,
                              bool first) {
    const AxisFields S = axis_fields(faces, &AxisFaces::speed);
    const AxisWeights inv_h = axis_weights(mesh);
    const double sound = first ? 1.0 : 0.0, *cs = closures.c.data();
    double inv_h_max = 0.0;
    for (int a = 0; a < 3; ++a)
        if (mesh.active[a]) inv_h_max = std::max(inv_h_max, 1.0 / mesh.grid.h[a]);
    const double *Phi = state.Phi.data(), *Phi_co = closures.Phi_co.data();
    const double* u[3] = {state.u[0].data(), state.u[1].data(), state.u[2].data()};
    auto wave = [&](std::size_t c, int i, const AxisRow* ar) {
        const double own = is_dust(Phi[c], Phi_co[c]) ? 0.0 : 1.0;  // a dust cell's own speed does not count
        return sum_over_axes(inv_h, i, ar, [&](int a, std::size_t fl, std::size_t fu) {
            return std::max({own * std::fabs(u[a][c]), S[a][fl], S[a][fu]}) + sound * cs[c];
        });
    };
    // Twice the last step's outflow rate; none for dust, whose outflow is capped instead.
    auto outflow = [&](std::size_t c, double out) { return is_dust(Phi[c], Phi_co[c]) ? 0.0 : 2.0 * out / Phi[c]; };
    StepRates rates = largest_rates(mesh, state, closures, faces, wave, outflow);
    for (std::size_t c : mesh.inside_cells) rates.acoustic = std::max(rates.acoustic, cs[c] * inv_h_max);
    return rates;
}

const char* step_bound_name(StepBound bound) {
    static const char* const names[kStepBounds] = {"dt_max", "cfl", "outflow", "compaction", "growth", "halved", "acoustic"};
    return names[static_cast<int>(bound)];
}

StepSize time_step(const FlowMesh& mesh, const FlowSettings& settings, double t, double t_end, const StepRates& rates,
                   const FlowState& state, const CellClosures& cl) {
    double dt = std::min(settings.dt_max, t_end - t);
    const double dt_cfl = rates.waves > 0.0 ? settings.cfl / rates.waves : INFINITY;
    const double dt_outflow = rates.outflow > 0.0 ? kOutflowFraction / rates.outflow : INFINITY;
    const double dt_compaction = rates.compaction > 0.0 ? kCompactionFraction / rates.compaction : INFINITY;
    const bool acoustic = settings.face_smoothing == FaceSmoothing::acoustic && rates.acoustic > 0.0;
    const double dt_acoustic = acoustic ? settings.acoustic_courant_max / rates.acoustic : INFINITY;
    dt = std::min({dt, dt_cfl, dt_outflow, dt_compaction, dt_acoustic});
    const StepBound bound = dt == dt_cfl          ? StepBound::cfl
                            : dt == dt_outflow    ? StepBound::outflow
                            : dt == dt_compaction ? StepBound::compaction
                            : dt == dt_acoustic   ? StepBound::acoustic
                                                  : StepBound::dt_max;
    if (!(dt >= settings.dt_min) && t_end - t > settings.dt_min) {
        double c_max = 0.0, Phi_at = 0.0;
        for (std::size_t c : mesh.inside_cells)
            if (cl.c[c] > c_max) c_max = cl.c[c], Phi_at = state.Phi[c];
        const std::string cause =
            bound == StepBound::compaction
                ? "the compaction bound: the bed is compacted towards Phi_rcp faster than this resolution can follow"
            : bound == StepBound::outflow
                ? "the outflow bound: a cell loses more than its mass (outflow rate " + format_number(rates.outflow) + " 1/s)"
            : bound == StepBound::acoustic ? "the face smoothing's acoustic Courant number (acoustic_courant_max, F13)"
                                           : "the CFL condition";
        throw InvariantError("flow: time step " + format_number(dt) + " s fell below dt_min = " + format_number(settings.dt_min) +
                             " s at t = " + format_number(t) + " s, set by " + cause + " (largest sound speed c = " +
                             format_number(c_max) + " m/s at Phi = " + format_number(Phi_at, 8) + ")");
    }
    return {dt, bound};
}

bool step_within_bounds(const FlowMesh& mesh, double dt, const std::vector<double>& Phi_before, const CellClosures& cl,
                        const FlowFaces& faces) {
    const AxisFields M = axis_fields(faces, &AxisFaces::mass);
    const AxisWeights inv_h = axis_weights(mesh);
    auto row = [&](long& bad, std::size_t r) {
        AxisRow ar[3];
        for (int a = 0; a < 3; ++a) ar[a] = mesh.axis_row(a, r);
        for (int i = mesh.row_lo[r]; i < mesh.row_hi[r]; ++i) {
            const std::size_t c = mesh.grid.n[0] * r + i;
            if (!mesh.inside[c]) continue;
            const double out = face_outflow(M, inv_h, i, ar), div = face_balance(M, inv_h, i, ar);
            const bool ok = dt * out <= kOutflowFraction * Phi_before[c] &&
                            -dt * div <= kCompactionFraction * (cl.Phi_rcp[c] - Phi_before[c]);
            bad += ok ? 0 : 1;
        }
    };
    return parallel_fold(mesh.parallel, mesh.rows, 0L, row, std::plus<long>()) == 0;
}

}  // namespace granseg
