// The compressible granular flow solver (Sect. 2.1, eqs. 8, 9, 14 with the asymmetric stress of
// eqs. 10-11 and the closures of eqs. 15-20). Walk-through: docs/flow_solver.md.
//
// FlowSolver owns the state (flow/flow_state.hpp) and runs one step as a sequence of kernels,
// each a free function with const inputs in its own file (first order in time and space, Lie
// splitting):
//   1. primitives and closures at t^n (flow/primitives.hpp); the potential psi and, per axis,
//      the face potentials and unsupported loads (flow/loads.hpp);
//   2. per axis the HLLC face fluxes with hydrostatic reconstruction (flow/convection.hpp,
//      flow/hllc.hpp); transport coefficients at the effective pressure (flow/primitives.hpp);
//      dt from a CFL condition on |u_n| + c, from the cells' outflow (so Phi stays > 0 and T, u_t
//      stay convex combinations) and from their compaction (so Phi stays < Phi_rcp)
//      (flow/time_step.hpp);
//   3. the conservative update, body forces along inactive or periodic axes, optional sources,
//      Coriolis rotation of u over dt (exact) (flow/convection.hpp);
//   4. implicit viscosity d(Phi u)/dt = div(eta grad u), split by axis into line solves
//      (flow/viscosity.hpp);
//   5. temperature: heating (3/2) eta kappa:kappa, dissipation eps Phi T and conduction
//      (3/2) div(lambda grad T) implicit in one sparse system (T relaxes towards
//      (3/2)(eta0/eps0) kappa:kappa, eq. 45); T >= T_floor (flow/temperature.hpp).
// Walls: no-slip (moving domain-boundary walls allowed), adiabatic, no mass flux. An axis with
// one cell is inactive (the field does not vary along it). Embedded walls: grid.inside.
//
// Coupling hand-over (per step): Phi before and after, T, u, the cell velocity gradient, and
// per axis the face mass flux M (Phi u_n) such that in every inside cell
//   Phi_new = Phi_old - dt * sum_axis (M[upper face] - M[lower face]) / h_axis,
// M = 0 on wall faces (one stage per step, so M is also its time average over the step).
#pragma once

#include "closures/material.hpp"
#include "core/grid.hpp"
#include "flow/coupled_viscosity.hpp"
#include "flow/diffusion_lines.hpp"
#include "flow/flow_mesh.hpp"
#include "flow/flow_settings.hpp"
#include "flow/flow_state.hpp"
#include "flow/frame.hpp"
#include "flow/pressure_solver.hpp"
#include "flow/semi_implicit.hpp"
#include "flow/temperature.hpp"
#include "flow/time_step.hpp"

#include <array>
#include <limits>
#include <optional>
#include <vector>

namespace granseg {

/// Wall-clock seconds spent in the phases of step() (for benchmarks); `pressure` is the part of
/// `convection` spent in the pressure solves of the semi-implicit step.
struct FlowTimers {
    double closures = 0, convection = 0, viscosity = 0, temperature = 0, pressure = 0;
};

/// The work of the steps (for benchmarks and run summaries): pressure solves, their Newton steps
/// and conjugate-gradient iterations, step attempts repeated with half the dt (semi-implicit),
/// the conjugate-gradient iterations of the temperature solves (both modes), and how many steps
/// each bound of flow/time_step.hpp set.
struct FlowCounters {
    long pressure_solves = 0, newton = 0, krylov = 0, repeated = 0, temperature_iterations = 0;
    std::array<long, kStepBounds> set_by{};
};

class FlowSolver {
public:
    FlowSolver(Grid grid, Material material, FlowSettings settings, Frame frame);

    /// Sets the state (Phi >= 0, T >= 0, finite; outside cells are ignored). Throws InvariantError
    /// if a cell has Phi >= Phi_rcp.
    void set_state(const std::vector<double>& Phi, const std::array<std::vector<double>, 3>& u,
                   const std::vector<double>& T);
    /// Small-particle share phi_hat = phi/Phi per cell (same layout, values in [0, 1], copied):
    /// Phi_rcp and Phi_co then follow it cell by cell from the next step on. An empty vector
    /// returns to the uniform settings.phi_hat.
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
    bool active(int axis) const { return mesh_.active[axis]; }

    /// Total granular volume, sum of Phi times cell volume over inside cells.
    double mass() const;
    /// Phi_rcp and Phi_co of a cell (from the phi_hat field, or settings.phi_hat).
    std::array<double, 2> packing(std::size_t cell) const;
    const FlowTimers& timers() const { return timers_; }
    const FlowCounters& counters() const { return counters_; }

private:
    /// Primitives, closures and the cell potential at t_.
    void update_closures();
    /// The explicit step up to the temperature: HLLC face fluxes, effective pressure, dt, update,
    /// implicit viscosity. Returns dt and its bound.
    StepSize explicit_step(double t_end);
    /// The semi-implicit step up to the temperature (flow/semi_implicit.hpp): dt, predictor with
    /// the pressure at t^n, implicit viscosity, pressure solve, transport; repeated with half the
    /// dt while the step would break a bound. Returns dt and its bound.
    StepSize semi_implicit_step(double t_end);
    /// The implicit viscosity of a step dt, split or coupled as the settings say.
    void viscosity(double dt);
    /// A velocity change du diffused by the step's viscosity solve with walls at rest (the
    /// solve is linear: V(u + du) = V(u) + V0(du)); cells empty at t^n keep du.
    void diffuse_change(double dt, std::array<std::vector<double>, 3>& du);
    /// The semi-implicit step's velocity change after the predictor (transport, pressure
    /// increments) diffused like the predictor's: u = u* + V0(u - u*).
    void viscous_increment(double dt);
    void check_invariants() const;

    FlowMesh mesh_;
    Material material_;
    FlowSettings settings_;
    Frame frame_;
    std::vector<double> phi_hat_;  // per cell, or empty: settings_.phi_hat everywhere
    WallVelocities walls_{};
    FlowSource source_;

    double t_ = 0.0, dt_ = 0.0;
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
    // Per cell, each with one meaning (the table in the header comment says which stage writes
    // and reads it):
    std::array<std::vector<double>, 3> m_start_, u_start_;  // Phi u and u at t^n, for a repeat
    std::vector<double> E_start_;                           // Phi T at t^n, for a repeat
    std::array<std::vector<double>, 3> force_part_;  // A: velocity change of the predictor's forces, before viscosity
    std::array<std::vector<double>, 3> u_star_;      // u*: the predictor's velocity after viscosity
    std::vector<double> mass_change_;  // r_c: mass change of the explicit face fluxes (pressure equation)
    std::vector<double> dp_;           // pressure increments of the last solve (its warm start next time)
    std::vector<double> dust_scale_;   // factor on a dust cell's outgoing mass fluxes (1 elsewhere)
    std::vector<double> Phi_after_;    // Phi at the end of the step (shares of the increment force)
    std::array<std::vector<double>, 3> velocity_change_;  // u - u* after transport, then diffused
    FlowState increment_;            // split viscosity's state for diffuse_change: Phi at t^n and du
    std::vector<double> line_rhs_;   // right-hand side of the split viscosity's line solves (swapped with u)
    std::vector<double> heat_;       // viscous heating H of the temperature step
    mutable std::array<std::vector<double>, 9> grad_;
    mutable bool gradient_valid_ = false;
    DiffusionLines lines_;
    TemperatureSolver temperature_;
    std::optional<CoupledViscosity> coupled_;  // set up when the settings ask for it
    FlowTimers timers_;
    FlowCounters counters_;
};

}  // namespace granseg
