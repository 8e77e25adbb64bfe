// The faces of the semi-implicit (pressure-implicit) step (docs/flow_solver.md Sect. 2, forces to pressure_faces):
// transport explicit, the acoustic part implicit, so that dt follows the material speed, not
// the sound speed. One pass of an incremental pressure correction with Rhie-Chow face
// velocities (Rhie & Chow, AIAA J. 21, 1983; Patankar, "Numerical Heat Transfer and Fluid
// Flow", 1980, Sect. 6.8) on cells that keep the hydrostatic reconstruction of the explicit
// scheme.
//
//   solves      the face kernels of the semi-implicit step (predictor, face predictor, corrected
//               faces and fluxes; the pressure equation itself is flow/pressure/pressure_solver.hpp)
//   inputs      FlowMesh, the state and closures (at t^n, or u* after the predictor), psi, the
//               loads, the force part A, dt, the pressure increments dp
//   outputs     AxisPressureFaces (p', D, U*, donor, K, M_x); AxisFaces; r_c; Phi after the step
//   invariants  M = 0 on walls; D = 0 on every face of the discrete lithostatic balance (a bed
//               at rest stays at rest); a dust cell loses at most kDustOutflow of its Phi a step
//
// Per face between the cells lo and hi of one axis (cell size h, Phi_f = (Phi_lo + Phi_hi)/2):
//   reconstructed pressures p'_lo, p'_hi of the two cells at the face (flow/faces/hllc.hpp, with the
//     loads of flow/faces/loads.hpp) and the face force D = p'_lo - p'_hi: in the discrete lithostatic
//     balance D = 0 on every face, so a bed at rest stays at rest (well balanced). On a dilute
//     face (both cells below half their Phi_co) |D| is limited to 2 |g| h Phi_f, the free fall of
//     its material: loads passed on through dust would otherwise accelerate nearly nothing;
//   shares: cell lo takes Phi_lo/(Phi_lo + Phi_hi) of a face force, cell hi the rest, so both get
//     the same velocity change (dust next to a dense cell takes its velocity from the mass that
//     enters it, not from the dense cell's pressure).
// 1. Predictor (predictor_faces, face_force_part, then the explicit update and the implicit
//    viscosity of the explicit scheme): the cells feel their shares of D and their own weight at
//    t^n (no mass moves), Coriolis, sources, then viscosity, giving u*; A is the part of the change
//    that came from the face forces (the shares of D and the weight, before viscosity). A wall
//    pushes back on a cell moving towards it with the implicit acoustic impedance
//    p' + Phi c u_n/(1 + c dt/h), which never reverses u_n.
// 2. Face predictor (face_velocity_predictor, then face_donors):
//        U* = V* + tau (D/(h Phi_f) - V_A/dt),   tau = dt, or h/c_f (face_smoothing),
//    V*, V_A the normal components of u* and A at the face: the mass-weighted mean
//    (Phi_lo x_lo + Phi_hi x_hi)/(Phi_lo + Phi_hi), or the donor's own value when the donor holds
//    (almost) no material (dust left behind by a moving cell is not dragged along; 0 where that
//    value points away from the face: a gap opens and carries nothing). The face moves as its
//    cells do after the viscous step, plus the smoothing: tau times the face's own compact
//    acceleration D/(h Phi_f) less the cells' accelerations from the same forces interpolated
//    (Rhie-Chow: no checkerboard). By default the smoothing time is the step (Rhie and Chow's
//    coefficient), which damps a checkerboard within a step at any dt but vanishes with dt. With
//    face_smoothing = acoustic it is the acoustic time h/c_f of a cell (c_f the larger sound speed
//    of the two), the largest for which the implicit step damps a pressure checkerboard
//    monotonically at every dt, fading with c in soft material (c_f < h/smoothing_time_max): it
//    does not depend on dt, so dt -> 0 converges to one spatial scheme; for smooth fields the
//    smoothing is O(tau h^2) = O(h^3). Each cell gives the face a
//    value of Phi: its own (transport = donor-cell), or its limited reconstruction at the face
//    half-way through the step for the velocities U* (transport = muscl, transport/muscl_hancock.hpp;
//    a dust cell gives its own Phi). The donor Phi_d is the value of the cell U* leaves, or the
//    smaller of the two when U* = 0 or when the pressure reversed the flow on this face onto a cell
//    that gives clearly less (then the solve is repeated), so that no cell gives much more than it
//    holds times |U| dt/h. The explicit flux M_x = Phi_d U* and
//    the coupling K = (dt/h)^2 Phi_d/Phi_f define the pressure equation
//    (flow/pressure/pressure_solver.hpp) for the increments dp.
// 3. Corrected faces: U = U* - dt (dp_hi - dp_lo)/(h Phi_f) (eq. 9 for the increment), M = Phi_d U
//    (the hand-over; 0 on walls); the fluxes of momentum and Phi T are M times the donor's values
//    (all three velocity components, flow/faces/transport_flux.hpp), and each cell gets its share of the
//    increment force dp_lo - dp_hi by the masses at the end of the step.
// Dust (a cell below kDust Phi_co, assumption F11): a face between two dust cells stays explicit
// (K = 0, U = U*: the increments there are only an extension of the neighbours' and would push on
// almost no mass); a dust cell's outflow is capped at kDustOutflow of its Phi per step, so dust does
// not set dt (flow/time_step.hpp); a face is open when either of its cells holds more than
// Phi_vacuum (a cell just above it between empty ones once had only closed faces and kept
// accelerating under gravity).
#pragma once

#include "flow/fields/flow_mesh.hpp"
#include "flow/fields/flow_settings.hpp"
#include "flow/fields/flow_state.hpp"

#include <array>
#include <vector>

namespace granseg {

class MusclHancock;

/// Per axis and face, what the semi-implicit fluxes are built from.
struct AxisPressureFaces {
    std::vector<double> p_lo, p_hi;          // reconstructed pressures p' of the lower and upper cell
    std::vector<double> force;               // D, limited on dilute faces
    std::vector<double> predictor;           // U* for the current dt
    std::vector<double> smoothing;           // the smoothing part of U*, tau (D/(h Phi_f) - mean(A)/dt)
    std::vector<double> coupling;            // K
    std::vector<double> value_lo, value_hi;  // the Phi the lower / upper cell gives the face (its own, or reconstructed)
    std::vector<double> donor;               // Phi_d
    std::vector<double> flux;                // the explicit flux M_x = Phi_d U*
    std::vector<unsigned char> reversed;     // 1: the pressure reversed the flow, donor = min(Phi_lo, Phi_hi)
};

using PressureFaces = std::array<AxisPressureFaces, 3>;

/// The reconstructed pressures and (limited) face forces of every face of `axis` at
/// t^n (no reversed faces yet), and the face pressure (Phi_hi p'_lo + Phi_lo p'_hi)/(Phi_lo + Phi_hi)
/// in faces.p (the effective pressure; walls: the inside cell's p').
void pressure_faces(const FlowMesh& mesh, int axis, double gravity, const FlowState& state, const CellClosures& closures,
                    const Potential& psi, const AxisLoads& loads, AxisPressureFaces& pf, AxisFaces& faces);

/// Part 1: zero mass, energy and tangential fluxes; normal momentum fluxes p - (the side's share of
/// D), p the side's own pressure (its reconstruction p' plus the correction p - p' that carries its
/// weight), so that a cell's net force is its shares of D; a wall pushes with the inside cell's p
/// plus the implicit acoustic impedance Phi c u_n/(1 + c dt/h) of a cell moving towards it, which
/// never reverses u_n.
void predictor_faces(const FlowMesh& mesh, int axis, double dt, const FlowState& state, const CellClosures& closures,
                     const AxisPressureFaces& pf, AxisFaces& faces);

/// Part 1, per inside cell and before the explicit update: the force part A of the predictor, the
/// velocity change -dt (normal momentum flux balance)/Phi that the faces of predictor_faces give
/// each cell along each active axis (its shares of D and its weight; not Coriolis, sources or the
/// gravity of an inactive axis, which have no compact counterpart at the face).
void face_force_part(const FlowMesh& mesh, double dt, const FlowState& state, const FlowFaces& faces,
                     std::array<std::vector<double>, 3>& A);

/// Part 2a for `axis`: U* of every face (0 on walls and faces without material) from the predicted
/// state (u*) and the force part A of the predictor.
void face_velocity_predictor(const FlowMesh& mesh, const FlowSettings& settings, int axis, double dt, const FlowState& state,
                             const CellClosures& closures, const std::array<std::vector<double>, 3>& A, AxisPressureFaces& pf);

/// Part 2b for `axis`, after U* of every axis: the value each cell gives the face (its Phi, or with a
/// reconstruction its MUSCL-Hancock face value for U*, transport/muscl_hancock.hpp; a dust cell its
/// own Phi), the donor Phi_d, K and the explicit flux M_x = Phi_d U*.
void face_donors(const FlowMesh& mesh, const FlowSettings& settings, int axis, double dt, const FlowState& state,
                 const CellClosures& closures, const MusclHancock* reconstruction, AxisPressureFaces& pf);

/// Part 2, per inside cell: the mass change of the explicit fluxes,
/// r_c = -dt sum_axis (M_x[upper] - M_x[lower])/h (flow/fields/face_balance.hpp).
void explicit_mass_change(const FlowMesh& mesh, double dt, const PressureFaces& pf, std::vector<double>& change);

/// Marks the faces whose mass flux leaves a cell that gives the face clearly less than the donor it
/// was computed with (the pressure reversed the flow there); returns how many it marked. Call it on
/// the corrected fluxes before cap_dust_outflow: a face reversed onto an empty cell has no flux after
/// the cap and would go unmarked.
long mark_reversed_faces(const FlowMesh& mesh, int axis, const AxisFaces& faces, AxisPressureFaces& pf);

/// The smoothing time tau of a face of cell size h whose larger sound speed is c: the acoustic time
/// h/c of a cell where the material is stiff (c >= c* = h/smoothing_time_max); where it is soft
/// (c < c*: loose or unloaded material, free surfaces) tau fades with c, smoothing_time_max c/c*,
/// so that it never exceeds smoothing_time_max and vanishes where nothing carries a pressure
/// (docs/flow_solver_pressure.md). With face_smoothing = step it is the step dt itself.
inline double smoothing_time(const FlowSettings& settings, double h, double c, double dt) {
    if (settings.face_smoothing == FaceSmoothing::step) return dt;
    const double tau_max = settings.smoothing_time_max;
    return c * tau_max >= h ? h / c : tau_max * tau_max * c / h;
}

/// Below this share of Phi_co a cell is dust: as a donor it carries its material at its own
/// velocity, and its outflow is capped (dust_outflow_scale) instead of bounding dt (assumption F11).
constexpr double kDust = 1e-3;
/// Whether a cell with volume fraction Phi and Phi_co is dust (Phi < kDust Phi_co).
inline bool is_dust(double Phi, double Phi_co) { return Phi < kDust * Phi_co; }
/// The share of a dust cell's Phi that may leave it in one step.
constexpr double kDustOutflow = 0.5;

/// Part 3a for `axis` after the pressure solve (dp per cell): the corrected face velocity
/// U = U* - dt (dp_hi - dp_lo)/(h Phi_f), the mass flux M = Phi_d U in faces.mass (0 on walls), and
/// the speed |U| for the next step's bound in faces.speed (0 where the donor is dust).
void corrected_face_velocities(const FlowMesh& mesh, int axis, double dt, const FlowState& state, const CellClosures& closures,
                               const AxisPressureFaces& pf, const std::vector<double>& dp, AxisFaces& faces);

/// Caps the outflow of every dust cell (Phi < kDust Phi_co) at kDustOutflow of its Phi in a step of
/// length dt: its outgoing mass fluxes (faces.mass of every axis) are scaled down by the factor in
/// `scale` (1 for every other cell). Dust moves at most about one cell per step instead of setting
/// dt (assumption F11).
void cap_dust_outflow(const FlowMesh& mesh, double dt, const FlowState& state, const CellClosures& closures,
                      std::vector<double>& scale, FlowFaces& faces);

/// Phi_after = Phi - dt sum_axes (M[upper] - M[lower])/h per inside cell (mass_balance,
/// flow/fields/face_balance.hpp): Phi at the end of the step, for the shares of the increment force.
void volume_fraction_after(const FlowMesh& mesh, double dt, const std::vector<double>& Phi, const FlowFaces& faces,
                           std::vector<double>& Phi_after);

/// Part 3b for `axis`: with M = faces.mass (the hand-over; 0 on walls), the fluxes of momentum and
/// Phi T as M times the donor's values (all three velocity components, flow/faces/transport_flux.hpp),
/// and the corrections of the increments: each cell gets the share Phi_after_cell/(Phi_after_lo +
/// Phi_after_hi) of the increment force dp_lo - dp_hi, so both end the step with the same velocity
/// change (shares by the masses at t^n once gave dust next to a cell filling up in this step
/// hundreds of m/s).
void semi_implicit_face_fluxes(const FlowMesh& mesh, int axis, const FlowState& state, const AxisPressureFaces& pf,
                               const std::vector<double>& dp, const std::vector<double>& Phi_after, AxisFaces& faces);

}  // namespace granseg
