// The whole model in the drum of Sect. 4.2: the compressible flow (eqs. 8, 9, 14) and the
// segregation equation (eq. 47) coupled both ways. Walk-through: docs/sect4.2_tumbler.md.
//
//   solves      eqs. (8), (9), (14) and (47) in the turning drum, coupled both ways, split as in eq. (65)
//   inputs      CoupledTumblerSetup: the drum, the material, flow settings, S, the segregation options,
//               Phi_min, packing feedback, phi_hat at t = 0
//   outputs     after each step the flow's Phi, u, T and phi (phi_hat())
//   invariants  the amount of each phase; 0 <= phi <= Phi after the bulk step and the segregation
//               sub-step (round-off clips only); a uniform phi_hat stays uniform (coupled_run.hpp checks them)
//
// Everything is solved in the frame turning with the drum (the flow solver's frame, F5). One
// step of the coupled model:
//   1. flow step (FlowSolver::step): Phi, u, T from t to t + dt with the closures of the current
//      phi_hat; it hands over the face mass fluxes M with Phi_new = Phi_old - dt div_h M;
//   2. bulk transport: phi carried by the same M with the flow's transport scheme (eq. 65, F^bulk;
//      assumption G1). Donor cell: donor cell in phi_hat = phi/Phi_old, written like the mass
//      balance (BulkTransport), so phi_new/Phi_new is a convex combination of old phi_hat values
//      (the flow keeps dt sum_out M/h <= 0.9 Phi_old) and a uniform phi_hat stays uniform to
//      round-off. muscl: that donor-cell step plus the limited antidiffusion of a MUSCL-Hancock flux
//      in phi_hat (FctBulkTransport, assumption T5), so phi_new/Phi_new stays within the local
//      extremes of the old and the donor-cell phi_hat;
//   2'. a passive tracer, if the setup has one: a second bulk field tau (0 <= tau <= Phi) carried by
//      the same M with the same transport as phi, and nothing else (no segregation, no feedback):
//      a dye that marks material, so that what leaves a region is measured in the model's own flow;
//   3. segregation sub-step with Phi and T frozen (eq. 52b) over the same dt: per cell
//      a = S^sl = -S0 sqrt(T) (d_s . g) d_s (eq. 46) with T from the flow and d_s (Sect. 2.3) from
//      the flow's velocity gradient and its velocity, both relative to the drum, so the rotation
//      of the frame does not enter d_s (docs/assumptions.md D3, C5); a = 0 where Phi < Phi_min
//      (assumption C2). SegregationSolver::advance (split over the axes, the sign-robust flux of
//      eq. 63, zero flux on every wall face) covers dt in steps of its own CFL bound;
//   4. closures from phi_hat: with packing feedback, Phi_rcp(phi_hat) and Phi_co(phi_hat) follow
//      phi_hat cell by cell (FlowSolver::set_phi_hat; eqs. 18, 19); without, they keep the values
//      of the initial mixture (assumption C3).
// Every step takes all four parts (Lie splitting, first order in dt; assumption C1): the
// segregation sub-step covers the flow's dt, so that the splitting error vanishes with dt. With
// packing feedback each flow step then meets a change of Phi_rcp and Phi_co that is proportional
// to its dt; a sub-step that covered a fixed stretch of time instead (at the segregation's own
// pace) changed them in jumps that one flow step had to absorb, and made the drum's angle and its
// pattern depend on dt without converging (docs/sect4.2_tumbler.md, "Time step").
#pragma once

#include "closures/material.hpp"
#include "direction/segregation_direction.hpp"
#include "drum/drum.hpp"
#include "flow/flow_solver.hpp"
#include "run/state_io.hpp"
#include "segregation/bulk_transport.hpp"
#include "segregation/bulk_transport_fct.hpp"
#include "segregation/frozen_fields.hpp"
#include "segregation/segregation_solver.hpp"

#include <functional>
#include <limits>
#include <optional>
#include <vector>

namespace granseg {

/// The coupled drum's default step (assumption C9): dt_max half the flow solver's, and at most two
/// acoustic times h/c of a cell (the flow solver's own bound allows five). With the packing
/// feedback the small-particle shares of the core and the axis carry a time error that follows the
/// acoustic Courant number c dt/h: 0.015 to 0.03 at five (50 cells at 2 ms, 100 cells at 1 ms), below
/// 0.01 at two (bench_time_step, sect4.2_tumbler.md "Time step").
constexpr double kCoupledDtMax = 1e-3;            // s
constexpr double kCoupledAcousticCourantMax = 2;  // dt * max_axis c/h_axis <= this

/// The flow settings of a coupled drum by default: the flow solver's with dt_max = kCoupledDtMax
/// and acoustic_courant_max = kCoupledAcousticCourantMax.
inline FlowSettings coupled_flow_settings() {
    FlowSettings f;
    f.dt_max = kCoupledDtMax;
    f.acoustic_courant_max = kCoupledAcousticCourantMax;
    return f;
}

/// Everything a coupled drum run needs (defaults: the Sect. 4.2 set-up, docs/scenes.md).
struct CoupledTumblerSetup {
    DrumSpec drum;
    Material material = Material::glass_substitute();
    FlowSettings flow = coupled_flow_settings();  // its phi_hat is replaced by the initial mixture's
    double S = 1.0;                               // S0 of eq. (46), s^2/m (Sect. 4.2); 0: no segregation
    SegregationOptions segregation;               // scheme, limiter, cfl of the segregation sub-step
    double Phi_min = 0.05;                        // no segregation in cells with Phi below this (C2)
    /// A diagnostic, not a physics option: no segregation in cells whose shear rate
    /// kappa_max - kappa_min (1/s) is at or below this, as if no shear plane existed there (it
    /// raises D1's threshold); 0: off. Switches the segregation off in the slowly creeping bed.
    double diagnostic_min_shear_rate = 0.0;
    bool packing_feedback = true;  // Phi_rcp, Phi_co follow phi_hat (true) or the initial mixture (C3)
    /// Without packing feedback: the phi_hat whose Phi_rcp, Phi_co the closures keep; NaN: the
    /// initial bed's mean (C3). Lets a tracer (S = 0) ride on the flow of another mixture.
    double mixture = std::numeric_limits<double>::quiet_NaN();
    std::function<double(double x, double z)> phi_hat0 = [](double, double) { return 0.5; };  // lab frame at t = 0
    /// A passive tracer's share tau/Phi at t = 0 (lab frame, in [0, 1]); empty: no tracer (step 2').
    std::function<double(double x, double z)> tracer0;
};

/// Wall-clock seconds spent in the parts of the coupled step (for benchmarks).
struct CoupledTimers {
    double flow = 0, bulk = 0, segregation = 0, feedback = 0;  // steps 1, 2, 3, 4
    void checkpoint(StateIO& io) { io("flow", flow)("bulk", bulk)("segregation", segregation)("feedback", feedback); }
};

class CoupledTumbler {
public:
    /// The drum at rest with the bed of the initial mixture (assumptions F6, C3) and
    /// phi = phi_hat0 Phi. Throws InputError for phi_hat0 outside [0, 1] in a bed cell, for a
    /// mixture outside [0, 1] or given with packing feedback,
    /// InvariantError if the bed is packed beyond Phi_rcp(phi_hat0) somewhere (packing feedback).
    explicit CoupledTumbler(const CoupledTumblerSetup& setup);

    /// One coupled step (see above), not beyond t_end. Returns the flow's dt. InvariantError on a
    /// broken invariant of the flow, or if the bulk step leaves 0 <= phi <= Phi beyond round-off.
    double step(double t_end = std::numeric_limits<double>::infinity());
    /// Starts from another run's flow instead of the bed at rest: the flow solver's state from
    /// `flow_state` (a tumbler-flow's or a tumbler's checkpoint, run/state_io.hpp), its time and
    /// steps included; phi = phi_hat0 Phi and the tracer from tracer0 at the cells' lab positions
    /// at that time; the segregation starts there as at t = 0. InputError for phi_hat0 or tracer0
    /// outside [0, 1] in a cell holding material, InvariantError (packing feedback) for a cell packed
    /// beyond Phi_rcp(phi_hat0).
    void start_from(StateIO& flow_state);

    const CoupledTumblerSetup& setup() const { return setup_; }
    const FlowSolver& flow() const { return flow_; }
    const Grid& grid() const { return flow_.grid(); }
    double time() const { return flow_.time(); }
    /// phi per cell (small-particle volume fraction); 0 outside the drum.
    const std::vector<double>& phi() const { return phi_; }
    /// phi_hat = phi/Phi per cell (0 where Phi = 0).
    std::vector<double> phi_hat() const;
    /// The passive tracer tau per cell (a volume fraction like phi; empty without a tracer).
    const std::vector<double>& tracer() const { return tracer_; }
    /// The small-particle share that sets Phi_rcp, Phi_co without packing feedback (C3): the setup's
    /// mixture if given, else the initial bed's mean.
    double initial_mixture() const { return initial_.mean; }
    /// The fields of the last segregation sub-step: Phi, a = S^sl per axis, and d_s per axis
    /// (drum frame, sign-normalised; 0 where there is no segregation).
    const FrozenFields& frozen() const { return frozen_; }
    const std::vector<double>& d_s(int axis) const { return d_s_[axis]; }
    /// The segregation direction (Sect. 2.3) in cell c from the flow's current velocity gradient and
    /// velocity, both relative to the drum, with D1's threshold raised to the setup's
    /// diagnostic_min_shear_rate; its principal_shear is the cell's shear rate kappa_max - kappa_min.
    SegregationDirection direction(std::size_t c) const;
    /// Segregation sub-steps of the splitting (part 3 above): one per coupled step.
    long split_segregation_steps() const { return split_steps_; }
    /// Steps of the segregation solver within them (each sub-step covers the flow's dt in steps
    /// of the solver's own CFL bound): at least one per sub-step.
    long segregation_solver_steps() const { return solver_steps_; }
    /// Largest amount the segregation solver's round-off guard moved phi back into [0, Phi].
    double largest_correction() const { return segregation_.largest_correction(); }
    /// Over all bulk steps so far: the extremes of phi - Phi and of phi before the round-off clip,
    /// and the largest clip (of phi and of the tracer).
    double max_excess() const { return max_excess_; }
    double min_phi() const { return min_phi_; }
    double largest_bulk_clip() const { return largest_bulk_clip_; }
    const CoupledTimers& timers() const { return timers_; }

private:
    /// a = S^sl and d_s per cell from the flow's current fields (step 3).
    void update_segregation_velocity();
    /// Step 3 over dt.
    void segregate(double dt);
    /// After the bulk step: `field` (phi or the tracer) back into [0, Phi] where rounding left it;
    /// InvariantError if by more than kBoundRoundOff times the cell's larger Phi (before or after).
    void clip_bulk_round_off(std::vector<double>& field, const char* name);
    /// Step 2 for `field` with the flow's face mass fluxes.
    void transport(std::vector<double>& field, double dt);

    /// phi_hat0 at the cells below the flat initial surface (0 elsewhere) and their mean (C3), or the
    /// setup's mixture in its place if given.
    struct InitialMixture {
        std::vector<double> phi_hat;
        double mean;
    };
    static InitialMixture initial_mixture(const CoupledTumblerSetup& setup);

    CoupledTumblerSetup setup_;
    InitialMixture initial_;  // before flow_, which is built with its mean
    FlowSolver flow_;
    BulkTransport bulk_;                   // transport = donor-cell
    std::optional<FctBulkTransport> fct_;  // transport = muscl
    FaceFields no_inflow_;                 // closed drum: nothing enters through a domain boundary
    SegregationSolver segregation_;
    std::vector<unsigned char> inside_;  // 1 for inside cells
    bool parallel_;                      // OpenMP threads on the per-cell loops of larger grids
    FrozenFields frozen_;
    std::array<std::vector<double>, 3> d_s_;
    std::vector<double> phi_, tracer_;
    long split_steps_ = 0, solver_steps_ = 0;
    double max_excess_ = -std::numeric_limits<double>::infinity(), min_phi_ = std::numeric_limits<double>::infinity();
    double largest_bulk_clip_ = 0.0;
    CoupledTimers timers_;

public:
    /// Saves or restores (run/state_io.hpp) what a later step or a caller reads: the flow, phi
    /// and the tracer, the fields of the last segregation sub-step, the counts and extremes, the
    /// timers. The rest is set-up (built from the setup as before) or
    /// scratch of a step. A member added above that outlives a step belongs here too.
    void checkpoint(StateIO& io) {
        io("tumbler.flow", flow_)("tumbler.segregation", segregation_)("tumbler.frozen", frozen_)("tumbler.d_s", d_s_);
        io("tumbler.phi", phi_)("tumbler.tracer", tracer_)("tumbler.substeps", split_steps_);
        io("tumbler.segregation_steps", solver_steps_)("tumbler.max_excess", max_excess_)("tumbler.min_phi", min_phi_);
        io("tumbler.largest_bulk_clip", largest_bulk_clip_)("tumbler.timers", timers_);
    }
};

}  // namespace granseg
