// The time step (docs/flow_solver.md Sect. 2, step_size): the smallest of
//   cfl / max_cells sum_axis max(wave speed over the cell's two faces)/h_axis   (CFL, first-order unsplit),
//   kOutflowFraction * Phi / (outflow rate)   (Phi stays > 0, T and u_t stay convex combinations),
//   kCompactionFraction * (Phi_rcp - Phi) / (net inflow rate)   (Phi stays < Phi_rcp, F4),
//   acoustic_courant_max / max_cells max_axis c/h_axis   (semi-implicit step with the acoustic
//       face smoothing: dt at most that many smoothing times tau_s = h/c, F13),
//   dt_max and the time left to t_end.
//
//   solves      nothing over time: the dt of a step, and whether a step's fluxes keep the bounds
//   inputs      FlowMesh, the state and closures at t^n, face fluxes and speeds (this step's in
//               the explicit step, the last step's in the semi-implicit one)
//   outputs     StepRates; StepSize (dt and the bound that set it); step_within_bounds
//   invariants  dt <= dt_max, dt <= t_end - t; dt >= dt_min before t_end (InvariantError otherwise)
//
// Explicit step: the waves are |u_n| + c, and all three rates come from the face fluxes of the step,
// which do not depend on dt. Semi-implicit step: the waves are the material speeds |u_n| of the
// cells and |U| of the last step's faces (and |u_n| + c in the first step, after which dt grows by
// at most kStepGrowth per step), the outflow rate is the last step's (halved margin) and so is the
// compaction rate (no margin: the check below catches the steps where it grew, and a margin costs
// more steps than those repeats: docs/flow_solver_choices.md, "Why these choices"),
// and the outflow and compaction bounds are checked after the pressure solve, since the fluxes of
// the step depend on dt (step_within_bounds(); the step is repeated with half the dt if a bound
// is broken).
#pragma once

#include "flow/fields/flow_mesh.hpp"
#include "flow/fields/flow_settings.hpp"
#include "flow/fields/flow_state.hpp"

namespace granseg {

/// The share of a cell's volume fraction that may leave it in one step (assumption F4).
constexpr double kOutflowFraction = 0.9;
/// The share of a cell's gap to random close packing that one step may close (assumption F4): the
/// HLLC waves are estimated from the states before the step and do not see the pressure diverge.
constexpr double kCompactionFraction = 0.5;

/// The largest rates over inside cells (1/s): wave speeds over h, outflow over Phi, net inflow
/// over the gap Phi_rcp - Phi, and (semi-implicit step) the sound speed over h, the inverse of the
/// shortest acoustic face smoothing time.
struct StepRates {
    double waves = 0.0, outflow = 0.0, compaction = 0.0, acoustic = 0.0;
};

/// The rates of the explicit step from the face fluxes and speeds of every active axis.
StepRates explicit_step_rates(const FlowMesh& mesh, const FlowState& state, const CellClosures& closures, const FlowFaces& faces);

/// The rates of the semi-implicit step: material speeds |u_n| of the cells and |U| (faces.speed)
/// of the last step's faces, twice the outflow rate of the last step's mass fluxes, without
/// dust cells (their outflow is capped, flow/faces/semi_implicit_faces.hpp, assumption F11), and their
/// compaction rate. The first
/// step also counts the sound speed, as the explicit step does: it starts from a state that need
/// not be in balance, whose waves the steps resolve while dt grows (kStepGrowth per step). The
/// acoustic rate is the largest c/h_axis of a cell.
StepRates material_step_rates(const FlowMesh& mesh, const FlowState& state, const CellClosures& closures, const FlowFaces& faces,
                              bool first);

/// Largest ratio of a semi-implicit step to the one before it.
constexpr double kStepGrowth = 2.0;

/// What set a step's dt: dt_max or t_end, the CFL condition, the outflow or compaction bound,
/// the semi-implicit step's growth limit (kStepGrowth), halving after a broken bound, or the
/// acoustic Courant number of the face smoothing (acoustic_courant_max).
enum class StepBound { dt_max, cfl, outflow, compaction, growth, halved, acoustic };
constexpr int kStepBounds = 7;
/// The bound's name as in the output tables ("dt_max", "cfl", ...).
const char* step_bound_name(StepBound bound);

struct StepSize {
    double dt;
    StepBound bound;
};

/// dt from the rates (cfl on the wave rate, kOutflowFraction and kCompactionFraction on the
/// others, acoustic_courant_max on the acoustic rate when face_smoothing = acoustic), dt_max and
/// t_end - t, and which of them set it. Throws InvariantError naming the bound
/// that set it if dt falls below dt_min before t_end.
StepSize time_step(const FlowMesh& mesh, const FlowSettings& settings, double t, double t_end, const StepRates& rates,
                   const FlowState& state, const CellClosures& closures);

/// Whether the fluxes of a step of length dt keep every cell within the bounds of the explicit
/// step: outflow at most kOutflowFraction of Phi_before, net inflow at most kCompactionFraction of
/// the gap Phi_rcp - Phi_before (the implicit pressure alone would let one step close almost all
/// of it, and the next start from a pressure near the divergence).
bool step_within_bounds(const FlowMesh& mesh, double dt, const std::vector<double>& Phi_before, const CellClosures& closures,
                        const FlowFaces& faces);

}  // namespace granseg
