// The compressible granular flow solver (Sect. 2.1, eqs. 8, 9, 14 with the asymmetric stress of
// eqs. 10-11 and the closures of eqs. 15-20). Walk-through: docs/flow_solver.md.
//
//   solves      eqs. (8), (9), (14) step by step, first order in time and space, in the x-z plane,
//               a column or a slab, with embedded walls, in a frame that may turn (flow/fields/frame.hpp)
//   inputs      Grid, Material, FlowSettings, Frame; the state (set_state), optionally phi_hat per
//               cell, wall velocities of the domain boundary, sources
//   outputs     the state after each step and the coupling hand-over below
//   invariants  Phi_new = Phi_old - dt div M in every inside cell; finite Phi >= 0, T >= 0 and u;
//               Phi < Phi_rcp (a step that breaks one throws InvariantError)
//
// FlowSolver owns the state (flow/fields/flow_state.hpp) and runs a step as a list of stages, each a
// private member function that calls free kernels with const inputs (Lie splitting). A stage's
// label is the name of its timer (FlowStage, the summaries' seconds_LABEL), the same in the
// driver (semi_implicit_step.cpp) and docs/flow_solver.md.
// Both modes:
//   closures: Phi_before = Phi; primitives u, T and the closures at t^n
//      (flow/fields/primitives.hpp, flow/faces/loads.hpp);
//   ...the mode's stages...
//   temperature: heating (3/2) eta kappa:kappa, dissipation eps Phi T and conduction
//      (3/2) div(lambda grad T) implicit in one sparse system (T relaxes towards
//      (3/2)(eta0/eps0) kappa:kappa, eq. 45); T >= T_floor (flow/diffusion/temperature.hpp).
// Explicit step (time_stepping = "explicit", explicit_step):
//   forces: gravity at t^n (dt follows from these forces); per active axis the face potentials and
//       the unsupported loads (flow/faces/loads.hpp) and the HLLC face fluxes with hydrostatic reconstruction
//       (flow/faces/convection.hpp, flow/faces/hllc.hpp); the effective pressure of eta, lambda, eps Phi
//       (flow/fields/primitives.hpp);
//   step_size: dt from a CFL condition on |u_n| + c, from the cells' outflow (so Phi stays > 0
//       and T, u_t stay convex combinations) and their compaction (so Phi stays < Phi_rcp)
//       (flow/time_step.hpp);
//   predictor: the conservative update, body forces along inactive or periodic axes, optional
//       sources, Coriolis rotation of u over dt (exact) (explicit_update, flow/faces/convection.hpp);
//   viscosity: implicit viscosity d(Phi u)/dt = div(eta grad u), all axes in one system or split
//       by axis into line solves (flow/diffusion/coupled_viscosity.hpp, flow/diffusion/viscosity.hpp).
// Semi-implicit step (the default, semi_implicit_step; kernels in flow/faces/semi_implicit_faces.hpp):
//   step_size: dt from the material speeds |u_n|, |U| and the outflow and compaction of the last
//       step's fluxes, at most kStepGrowth times the last dt (flow/time_step.hpp);
//   forces: forces of the state at t^n with gravity at t^n + dt/2 (it turns in the drum frame):
//       face potentials and loads, reconstructed pressures p' and face forces
//       D, the effective pressure; the state at t^n kept for a repeat;
//   predictor: each cell's share of D and its weight (gravity as in forces), Coriolis, sources (the explicit
//       update without mass flux), the force part A of that change;
//   viscosity: implicit viscosity (as in the explicit step): u*;
//   pressure_faces: face predictor U*, donors, coupling K and explicit mass change; after the
//       solve the corrected faces U, M = Phi_d U, the faces the pressure reversed onto a cell
//       holding clearly less marked, the dust cap, Phi after the step, the fluxes of momentum and
//       Phi T; again (at most 4 solves) while faces were marked; then the outflow and compaction
//       bounds checked on these fluxes (the reconstruction's face values, transport = muscl, are
//       timed as transport);
//   pressure_solve: the Newton solve for the pressure increments dp (flow/pressure/pressure_solver.hpp);
//   repeat: a broken bound: Phi, Phi u, u, Phi T and dp back to t^n, no reversed marks, half the
//       dt, again from predictor;
//   transport: Phi_new = Phi - dt div M exactly, Phi u and Phi T with the donors' values
//       (transport_update, flow/faces/convection.hpp);
//   increments: the velocity change since u* diffused by the viscosity's solve with walls at
//       rest (the solve is linear): u = u* + V0(u - u*).
// Walls: no-slip (moving domain-boundary walls allowed), adiabatic, no mass flux. An axis with
// one cell is inactive (the field does not vary along it). Embedded walls: grid.inside.
//
// What each stage reads and writes. Fields of state_ and closures_ by their symbols (Phi, Phi u,
// Phi T, u, T; p, c, eta, lambda, eps Phi, Phi_rcp, Phi_co), psi = potential_; "faces" and "pf"
// are faces_ and pressure_ of the active axes; other names are members.
//   stage            reads                                   writes
//   closures         Phi, Phi u, Phi T, phi_hat_             Phi_before_, u, T, closures_
//   explicit step:
//   forces           Phi, u, T, p, c, Phi_co                 t_forces_ = t, psi, loads_, faces, eta, lambda, eps Phi
//   step_size        Phi, Phi_rcp, faces M and speed         dt
//   predictor        faces, Phi                              Phi, Phi u, Phi T, u, T
//   viscosity        Phi, u, eta                             u, Phi u (line_rhs_: split solves)
//   semi-implicit step:
//   step_size        Phi, u, c, Phi_co, Phi_rcp, faces M     dt
//                    and speed (the last step's), dt_
//   forces           Phi, u, T, p, c, Phi_co, dt; Phi u,     t_forces_ = t + dt/2, psi, loads_, pf (p',
//                    Phi T                                   D; reversed = 0), faces p, eta,
//                                                            lambda, eps Phi; m_start_, u_start_, E_start_
//   predictor        pf, Phi, u, p, c, t_forces_             faces (M = 0), force_part_, Phi u, Phi T, u, T
//                                                            (Phi with sources)
//   viscosity        Phi, u, eta                             u, Phi u (u*; line_rhs_: split solves)
//   pressure_faces   Phi, u, T, p, c, Phi_rcp, Phi_co,       pf (U*, smoothing, donor, K, flux,
//                    force_part_, pf, dp_                    reversed), mass_change_, faces, dust_scale_,
//                                                            Phi_after_
//   pressure_solve   Phi, T, p, Phi_rcp, Phi_co, pf K,       dp_
//                    mass_change_, dp_
//   repeat           Phi_before_, m_start_, u_start_,        Phi, Phi u, u, Phi T, dp_, pf reversed
//                    E_start_
//   transport        Phi, Phi u, Phi T, u, faces             u_star_; Phi, Phi u, Phi T, u, T
//   increments       u, u_star_, Phi_before_, Phi, eta       velocity_change_, u, Phi u (increment_,
//                                                            line_rhs_: split solves)
//   temperature      Phi, u, T, eta, lambda, eps Phi         heat_, T, Phi T
//
// Coupling hand-over (per step): Phi before and after, T, u, the cell velocity gradient, and
// per axis the face mass flux M (Phi u_n) such that in every inside cell
//   Phi_new = Phi_old - dt * sum_axis (M[upper face] - M[lower face]) / h_axis,
// M = 0 on wall faces (one stage per step, so M is also its time average over the step).
#pragma once

#include "closures/material.hpp"
#include "core/grid.hpp"
#include "core/stopwatch.hpp"
#include "flow/diffusion/coupled_viscosity.hpp"
#include "flow/diffusion/diffusion_lines.hpp"
#include "flow/diffusion/temperature.hpp"
#include "flow/faces/semi_implicit_faces.hpp"
#include "flow/fields/flow_mesh.hpp"
#include "flow/fields/flow_settings.hpp"
#include "flow/fields/flow_state.hpp"
#include "flow/fields/frame.hpp"
#include "flow/pressure/pressure_solver.hpp"
#include "flow/time_step.hpp"
#include "run/state_io.hpp"
#include "transport/muscl_hancock.hpp"

#include <array>
#include <limits>
#include <optional>
#include <vector>

namespace granseg {

/// The stages of step(), in the order a step runs them (their labels in the header comment and
/// docs/flow_solver.md); FlowTimers keeps the wall-clock time of each (each second counted once).
enum class FlowStage {
    closures,
    step_size,
    forces,
    predictor,
    viscosity,
    pressure_faces,
    pressure_solve,
    repeat,
    transport,
    increments,
    temperature
};
constexpr int kFlowStages = 11;
/// The stage's label, as in the output tables ("closures", "step_size", ...).
const char* flow_stage_name(FlowStage stage);

/// Wall-clock seconds spent in each FlowStage (for benchmarks and run summaries).
struct FlowTimers {
    std::array<double, kFlowStages> seconds{};
    double total() const;
    void checkpoint(StateIO& io) { io("seconds", seconds); }
};

/// The work of the steps (for benchmarks and run summaries): pressure solves, their Newton steps
/// and conjugate-gradient iterations, step attempts repeated with half the dt (semi-implicit),
/// the conjugate-gradient iterations of the temperature solves (both modes), and how many steps
/// each bound of flow/time_step.hpp set.
struct FlowCounters {
    long pressure_solves = 0, newton = 0, krylov = 0, repeated = 0, temperature_iterations = 0;
    std::array<long, kStepBounds> set_by{};
    void checkpoint(StateIO& io) {
        io("pressure_solves", pressure_solves)("newton", newton)("krylov", krylov)("repeated", repeated);
        io("temperature_iterations", temperature_iterations)("set_by", set_by);
    }
};

class FlowSolver {
public:
    FlowSolver(Grid grid, Material material, FlowSettings settings, Frame frame);

    /// Sets the state (Phi >= 0, T >= 0, finite; outside cells are ignored). Throws InvariantError
    /// if a cell has Phi >= Phi_rcp.
    void set_state(const std::vector<double>& Phi, const std::array<std::vector<double>, 3>& u, const std::vector<double>& T);
    /// Small-particle share phi_hat = phi/Phi per cell (same layout, values in [0, 1], copied):
    /// Phi_rcp and Phi_co then follow it cell by cell from the next step on. An empty vector
    /// returns to the uniform settings.phi_hat. InvariantError, naming the mixture change, if the
    /// new Phi_rcp of a cell is at or below its Phi.
    void set_phi_hat(std::vector<double> phi_hat);
    /// Tangential velocity of the domain-boundary wall on `side` (0 lower, 1 upper) of `axis`.
    void set_wall_velocity(int axis, int side, const Vec3& U) { walls_[axis][side] = U; }
    void set_source(FlowSource source) { source_ = std::move(source); }

    /// Advances one step, not beyond t_end; returns dt. InvariantError on a broken invariant
    /// (non-finite field, Phi reaching Phi_rcp, dt below dt_min).
    double step(double t_end = std::numeric_limits<double>::infinity());

    const Grid& grid() const { return mesh_.grid; }
    const Material& material() const { return material_; }
    const FlowSettings& settings() const { return settings_; }
    const Frame& frame() const { return frame_; }
    double time() const { return t_; }
    long steps() const { return steps_; }
    double last_dt() const { return dt_; }
    /// What set the last step's dt.
    StepBound last_bound() const { return bound_; }

    // Coupling hand-over, valid after a step (see the header comment).
    const std::vector<double>& Phi() const { return state_.Phi; }
    const std::vector<double>& Phi_before() const { return Phi_before_; }
    const std::vector<double>& T() const { return state_.T; }
    const std::vector<double>& u(int b) const { return state_.u[b]; }
    /// d u_b / d x_a per cell (central differences; wall ghosts carry the wall velocity),
    /// computed when first asked for after a step.
    const std::vector<double>& velocity_gradient(int b, int a) const;
    const std::vector<double>& mass_flux(int axis) const { return faces_[axis].mass; }
    /// The last semi-implicit step's face smoothing velocities along `axis` (m/s; flow/faces/semi_implicit_faces.hpp).
    const std::vector<double>& smoothing(int axis) const { return pressure_[axis].smoothing; }
    bool active(int axis) const { return mesh_.active[axis]; }

    /// Total granular volume, sum of Phi times cell volume over inside cells.
    double mass() const;
    /// Phi_rcp and Phi_co of a cell (from the phi_hat field, or settings.phi_hat).
    std::array<double, 2> packing(std::size_t cell) const;
    const FlowTimers& timers() const { return timers_; }
    const FlowCounters& counters() const { return counters_; }

private:
    /// Adds the wall-clock time of its scope to one stage of timers_ (core/stopwatch.hpp).
    class Stopwatch : granseg::Stopwatch {
    public:
        Stopwatch(FlowTimers& timers, FlowStage stage) : granseg::Stopwatch(timers.seconds[static_cast<int>(stage)]) {}
    };

    // Both modes (flow_solver.cpp).
    /// closures: primitives and closures at t_.
    void update_closures();
    /// forces: the cell potential psi with gravity at time t (t_forces_ = t).
    void potential_at(double t);
    /// The face potentials and unsupported loads of `axis` at t^n.
    void face_loads(int axis);
    /// viscosity: the implicit viscosity of a step dt, coupled or split as the settings say.
    void viscosity(double dt);
    /// temperature: the temperature step.
    void temperature(double dt);
    void check_invariants() const;

    // The explicit step (flow_solver.cpp): forces, step_size, predictor, viscosity. Returns dt and its bound.
    StepSize explicit_step(double t_end);
    /// forces, step_size, predictor: HLLC fluxes, effective pressure, dt, the update.
    StepSize explicit_convection(double t_end);

    // The semi-implicit step (semi_implicit_step.cpp): step_size to increments. Returns dt and its bound.
    StepSize semi_implicit_step(double t_end);
    /// step_size: dt and its bound.
    StepSize semi_implicit_dt(double t_end);
    /// forces: the forces of the state at t^n, gravity at t^n + dt/2, and the effective pressure.
    void forces_at_start(double dt);
    /// predictor to repeat: keeps the state at t^n; predictor, viscosity, pressure correction,
    /// repeated with half the dt until the fluxes keep every bound. Returns the dt that did.
    StepSize predict_and_correct(StepSize size);
    /// forces: m_start_, u_start_, E_start_.
    void keep_start_state();
    /// predictor: the forces at t^n and the force part A (before viscosity).
    void predictor_forces(double dt);
    /// pressure_faces and pressure_solve: the pressure correction with its donor passes; whether
    /// the fluxes keep every bound (false also when the pressure equation did not converge).
    bool pressure_correct(double dt);
    /// pressure_faces: U* of every face, and with transport = muscl the face values of Phi for them (once per
    /// attempt: the donor passes change only the donors).
    void face_velocities(double dt);
    /// pressure_faces: donors, K of every face and the explicit mass change r_c.
    void face_donors_and_change(double dt);
    /// pressure_solve: the Newton solve for dp_ (counted; `repeat`: dp_ solved this step's equation already);
    /// whether it converged.
    bool solve_pressure(bool repeat);
    /// pressure_faces: corrected faces, the reversed ones marked (before the dust cap), dust cap, Phi after
    /// the step and the fluxes; returns how many faces the pressure reversed (marked for the smaller donor).
    long corrected_fluxes(double dt);
    /// repeat: restores the state at t^n and halves dt; throws InvariantError below dt_min.
    StepSize restart_with_half_dt(StepSize size);
    /// transport: transport by the corrected fluxes (u* kept in u_star_).
    void transport(double dt);
    /// increments: the velocity change since u* diffused like the predictor's: u = u* + V0(u - u*).
    void diffuse_increments(double dt);
    /// A velocity change du diffused by the step's viscosity solve with walls at rest (the
    /// solve is linear: V(u + du) = V(u) + V0(du)); cells empty at t^n keep du.
    void diffuse_change(double dt, std::array<std::vector<double>, 3>& du);

    FlowMesh mesh_;
    Material material_;
    FlowSettings settings_;
    Frame frame_;
    std::vector<double> phi_hat_;  // per cell, or empty: settings_.phi_hat everywhere
    WallVelocities walls_{};
    FlowSource source_;

    double t_ = 0.0, dt_ = 0.0;
    double t_forces_ = 0.0;  // the time of gravity in this step's forces: t + dt/2 (semi-implicit), t (explicit)
    StepBound bound_ = StepBound::dt_max;
    long steps_ = 0;
    FlowState state_;
    std::vector<double> Phi_before_;
    CellClosures closures_;
    Potential potential_;
    std::array<AxisLoads, 3> loads_;
    FlowFaces faces_;
    PressureFaces pressure_;
    PressureSolver pressure_solver_;
    PressureSolveStats pressure_stats_;  // of the last pressure solve
    // Per cell, each with one meaning (the table in the header comment says which stage writes
    // and reads it):
    std::array<std::vector<double>, 3> m_start_, u_start_;  // Phi u and u at t^n, for a repeat
    std::vector<double> E_start_;                           // Phi T at t^n, for a repeat
    std::array<std::vector<double>, 3> force_part_;         // A: velocity change of the predictor's forces, before viscosity
    std::array<std::vector<double>, 3> u_star_;             // u*: the predictor's velocity after viscosity
    std::vector<double> mass_change_;                       // r_c: mass change of the explicit face fluxes (pressure equation)
    std::vector<double> dp_;                                // pressure increments of the last solve (its warm start next time)
    std::vector<double> dust_scale_;                        // factor on a dust cell's outgoing mass fluxes (1 elsewhere)
    std::vector<double> Phi_after_;                         // Phi at the end of the step (shares of the increment force)
    std::array<std::vector<double>, 3> velocity_change_;    // u - u* after transport, then diffused
    FlowState increment_;                                   // split viscosity's state for diffuse_change: Phi at t^n and du
    std::vector<double> line_rhs_;  // right-hand side of the split viscosity's line solves (swapped with u)
    std::vector<double> heat_;      // viscous heating H of the temperature step
    mutable std::array<std::vector<double>, 9> grad_;
    mutable bool gradient_valid_ = false;
    DiffusionLines lines_;
    TemperatureSolver temperature_;
    std::optional<CoupledViscosity> coupled_;     // set up when the settings ask for it
    std::optional<MusclHancock> reconstruction_;  // transport = muscl: the face values of Phi
    FlowTimers timers_;
    FlowCounters counters_;

public:
    /// Saves or restores (run/state_io.hpp) what a later step or a caller reads: time, steps,
    /// the last dt and its bound, the state, phi_hat, the hand-over (Phi_before_, the last step's
    /// faces, which also bound the next dt), the pressure's and the temperature's warm starts,
    /// counters and timers. The rest is scratch that a step writes before it reads it, or set-up
    /// (grid, settings, walls, sources: the caller builds the solver as before). A member added
    /// above that outlives a step belongs here too (the kill-and-resume checks catch one forgotten).
    void checkpoint(StateIO& io) {
        io("flow.t", t_)("flow.dt", dt_)("flow.bound", bound_)("flow.steps", steps_)("flow.phi_hat", phi_hat_);
        io("flow.state", state_)("flow.Phi_before", Phi_before_)("flow.faces", faces_)("flow.dp", dp_);
        io("flow.temperature", temperature_)("flow.counters", counters_)("flow.timers", timers_);
        gradient_valid_ = gradient_valid_ && !io.restoring();  // the closures follow at the next step's start
    }
};

}  // namespace granseg
