// The time step of the explicit scheme (docs/flow_solver.md Sect. 3): the smallest of
//   cfl / max_cells sum_axis max(|u_n| + c over the cell's two faces)/h_axis   (CFL, first-order unsplit),
//   kOutflowFraction * Phi / (outflow rate)   (Phi stays > 0, T and u_t stay convex combinations),
//   kCompactionFraction * (Phi_rcp - Phi) / (net inflow rate)   (Phi stays < Phi_rcp, F4),
//   dt_max and the time left to t_end,
// all from the face fluxes of the step, which do not depend on dt.
#pragma once

#include "flow/flow_mesh.hpp"
#include "flow/flow_settings.hpp"
#include "flow/flow_state.hpp"

namespace granseg {

/// The share of a cell's volume fraction that may leave it in one step (assumption F4).
constexpr double kOutflowFraction = 0.9;
/// The share of a cell's gap to random close packing that one step may close (assumption F4): the
/// HLLC waves are estimated from the states before the step and do not see the pressure diverge.
constexpr double kCompactionFraction = 0.5;

/// The largest rates over inside cells (1/s): wave speeds over h, outflow over Phi, net inflow
/// over the gap Phi_rcp - Phi.
struct StepRates {
    double waves = 0.0, outflow = 0.0, compaction = 0.0;
};

/// The rates of the explicit step from the face fluxes and speeds of every active axis.
StepRates explicit_step_rates(const FlowMesh& mesh, const FlowState& state, const CellClosures& closures,
                              const FlowFaces& faces);

/// dt from the rates (cfl on the wave rate, kOutflowFraction and kCompactionFraction on the
/// others), dt_max and t_end - t. Throws InvariantError naming the bound that set it if dt falls
/// below dt_min before t_end.
double explicit_time_step(const FlowMesh& mesh, const FlowSettings& settings, double t, double t_end,
                          const StepRates& rates, const FlowState& state, const CellClosures& closures);

}  // namespace granseg
