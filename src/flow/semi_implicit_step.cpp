// FlowSolver's semi-implicit step (docs/flow_solver.md Sect. 2): the driver and its stages. The
// kernels are in flow/faces/semi_implicit_faces.hpp; the stage list and what each stage reads and writes are
// in the header comment of flow/flow_solver.hpp.
#include "flow/flow_solver.hpp"

#include "core/error.hpp"
#include "core/format.hpp"
#include "flow/diffusion/viscosity.hpp"
#include "flow/faces/convection.hpp"
#include "flow/fields/primitives.hpp"

#include <algorithm>

namespace granseg {

namespace {
/// Pressure solves per step attempt: the first, and repeats after faces reversed by the pressure
/// took the smaller donor (semi_implicit_faces.hpp).
constexpr int kDonorPasses = 4;
}  // namespace

StepSize FlowSolver::semi_implicit_step(double t_end) {
    // step_size: dt from the material speeds and the bounds of the last step's fluxes, at most
    //     kStepGrowth times the last dt (flow/time_step.hpp).
    StepSize size = semi_implicit_dt(t_end);
    // forces: the forces of the state at t^n with gravity at the middle of the step: face
    //     potentials and loads, the reconstructed pressures and face forces D, the effective
    //     pressure of eta, lambda, eps Phi.
    forces_at_start(size.dt);
    // predictor, viscosity, pressure_faces, pressure_solve, repeat: predict (u*), correct with the
    //     implicit pressure; while the corrected fluxes break a bound of the step, restore the
    //     state at t^n and repeat with half the dt.
    size = predict_and_correct(size);
    // transport: Phi_new = Phi - dt div M, momentum and Phi T with the donors' values.
    transport(size.dt);
    // increments: the velocity change since u* (transport, pressure increments) diffused like the predictor's.
    diffuse_increments(size.dt);
    return size;
}

StepSize FlowSolver::semi_implicit_dt(double t_end) {
    Stopwatch watch(timers_, FlowStage::step_size);
    // The rates of the last step's faces: this step's depend on dt.
    const StepRates rates = material_step_rates(mesh_, state_, closures_, faces_, steps_ == 0);
    StepSize size = time_step(mesh_, settings_, t_, t_end, rates, state_, closures_);
    if (steps_ > 0 && kStepGrowth * dt_ < size.dt) size = {kStepGrowth * dt_, StepBound::growth};
    return size;
}

void FlowSolver::forces_at_start(double dt) {
    Stopwatch watch(timers_, FlowStage::forces);
    // Gravity turns in the drum frame: at t + dt/2 its integral over the step is second order (at
    // t^n the drum's surface lagged the turning gravity by dt/2). A repeat with half the dt keeps
    // this time, so the cells' weights and the face forces stay balanced.
    potential_at(t_ + 0.5 * dt);
    for (int a = 0; a < 3; ++a) {
        if (!mesh_.active[a]) continue;
        face_loads(a);
        pressure_faces(mesh_, a, frame_.gravity, state_, closures_, potential_, loads_[a], pressure_[a], faces_[a]);
    }
    effective_pressure(mesh_, faces_, closures_);
}

StepSize FlowSolver::predict_and_correct(StepSize size) {
    keep_start_state();
    for (;;) {
        predictor_forces(size.dt);                   // predictor: forces at t^n, the force part A
        viscosity(size.dt);                          // viscosity: u*
        if (pressure_correct(size.dt)) return size;  // pressure_faces, pressure_solve: fluxes within every bound
        size = restart_with_half_dt(size);           // repeat
    }
}

void FlowSolver::keep_start_state() {
    Stopwatch watch(timers_, FlowStage::forces);
    m_start_ = state_.m, u_start_ = state_.u, E_start_ = state_.E;
}

void FlowSolver::predictor_forces(double dt) {
    Stopwatch watch(timers_, FlowStage::predictor);
    for (int a = 0; a < 3; ++a)
        if (mesh_.active[a]) predictor_faces(mesh_, a, dt, state_, closures_, pressure_[a], faces_[a]);
    face_force_part(mesh_, dt, state_, faces_, force_part_);
    explicit_update(mesh_, settings_, frame_, source_, t_forces_, dt, faces_, state_);
}

bool FlowSolver::pressure_correct(double dt) {
    face_velocities(dt);
    for (int pass = 1;; ++pass) {
        face_donors_and_change(dt);
        if (!solve_pressure(pass > 1)) return false;
        // Faces the pressure reversed onto a cell with clearly less material took the smaller
        // donor: solve again, up to kDonorPasses times.
        if (corrected_fluxes(dt) == 0 || pass == kDonorPasses) {
            Stopwatch watch(timers_, FlowStage::pressure_faces);
            return step_within_bounds(mesh_, dt, state_.Phi, closures_, faces_);
        }
    }
}

void FlowSolver::face_velocities(double dt) {
    {
        Stopwatch watch(timers_, FlowStage::pressure_faces);
        for (int a = 0; a < 3; ++a)
            if (mesh_.active[a]) face_velocity_predictor(mesh_, settings_, a, dt, state_, closures_, force_part_, pressure_[a]);
    }
    if (!reconstruction_) return;
    Stopwatch watch(timers_, FlowStage::transport);
    reconstruction_->face_values(state_.Phi, {&pressure_[0].predictor, &pressure_[1].predictor, &pressure_[2].predictor}, dt,
                                 MusclHancock::Form::conservative);
}

void FlowSolver::face_donors_and_change(double dt) {
    Stopwatch watch(timers_, FlowStage::pressure_faces);
    const MusclHancock* reconstruction = reconstruction_ ? &*reconstruction_ : nullptr;
    for (int a = 0; a < 3; ++a)
        if (mesh_.active[a]) face_donors(mesh_, settings_, a, dt, state_, closures_, reconstruction, pressure_[a]);
    explicit_mass_change(mesh_, dt, pressure_, mass_change_);
}

bool FlowSolver::solve_pressure(bool repeat) {
    Stopwatch watch(timers_, FlowStage::pressure_solve);
    pressure_stats_ = pressure_solver_.solve(mesh_, material_, state_, closures_, pressure_, mass_change_,
                                             settings_.pressure_tolerance, repeat, dp_);
    ++counters_.pressure_solves, counters_.newton += pressure_stats_.newton, counters_.krylov += pressure_stats_.krylov;
    return pressure_stats_.converged;
}

long FlowSolver::corrected_fluxes(double dt) {
    Stopwatch watch(timers_, FlowStage::pressure_faces);
    // Reversed faces are marked before the dust cap: a face the pressure reversed onto an empty
    // cell carries nothing once capped, yet the pressure equation counted its old donor.
    long reversed = 0;
    for (int a = 0; a < 3; ++a)
        if (mesh_.active[a]) {
            corrected_face_velocities(mesh_, a, dt, state_, closures_, pressure_[a], dp_, faces_[a]);
            reversed += mark_reversed_faces(mesh_, a, faces_[a], pressure_[a]);
        }
    cap_dust_outflow(mesh_, dt, state_, closures_, dust_scale_, faces_);
    volume_fraction_after(mesh_, dt, state_.Phi, faces_, Phi_after_);
    for (int a = 0; a < 3; ++a)
        if (mesh_.active[a]) semi_implicit_face_fluxes(mesh_, a, state_, pressure_[a], dp_, Phi_after_, faces_[a]);
    return reversed;
}

StepSize FlowSolver::restart_with_half_dt(StepSize size) {
    Stopwatch watch(timers_, FlowStage::repeat);
    ++counters_.repeated;
    size = {0.5 * size.dt, StepBound::halved};
    state_.Phi = Phi_before_, state_.m = m_start_, state_.u = u_start_, state_.E = E_start_;
    mesh_.parallel_for_inside([&](std::size_t c) { dp_[c] = 0.0; });
    for (AxisPressureFaces& P : pressure_) std::fill(P.reversed.begin(), P.reversed.end(), 0);
    if (!(size.dt >= settings_.dt_min))
        throw InvariantError("flow: the semi-implicit step fell below dt_min = " + format_number(settings_.dt_min) +
                             " s at t = " + format_number(t_) + " s: " +
                             (pressure_stats_.converged ? "a cell would lose more than its mass or reach Phi_rcp"
                                                        : "the pressure equation did not converge (residual " +
                                                              format_number(pressure_stats_.residual) + ")"));
    return size;
}

void FlowSolver::transport(double dt) {
    Stopwatch watch(timers_, FlowStage::transport);
    u_star_ = state_.u;
    transport_update(mesh_, settings_, dt, faces_, state_);
}

void FlowSolver::diffuse_increments(double dt) {
    Stopwatch watch(timers_, FlowStage::increments);
    const double Phi_vac = settings_.Phi_vacuum;
    mesh_.parallel_for_inside([&](std::size_t c) {
        for (int b = 0; b < 3; ++b) velocity_change_[b][c] = state_.u[b][c] - u_star_[b][c];
    });
    diffuse_change(dt, velocity_change_);
    // A cell empty at t^n (its row was the identity) or at the end keeps the update's velocity.
    mesh_.parallel_for_inside([&](std::size_t c) {
        if (!(Phi_before_[c] > Phi_vac && state_.Phi[c] > Phi_vac)) return;
        for (int b = 0; b < 3; ++b) {
            state_.u[b][c] = u_star_[b][c] + velocity_change_[b][c];
            state_.m[b][c] = state_.Phi[c] * state_.u[b][c];
        }
    });
}

void FlowSolver::diffuse_change(double dt, std::array<std::vector<double>, 3>& du) {
    if (viscosity_solve(settings_) == ViscositySolve::coupled) return coupled_->diffuse_change(mesh_, du);
    for (int b = 0; b < 3; ++b) increment_.u[b] = du[b];
    increment_.Phi = Phi_before_;
    implicit_viscosity(mesh_, settings_, WallVelocities{}, dt, closures_.eta, lines_, line_rhs_, increment_);
    mesh_.parallel_for_inside([&](std::size_t c) {
        if (Phi_before_[c] > settings_.Phi_vacuum)
            for (int b = 0; b < 3; ++b) du[b][c] = increment_.u[b][c];
    });
}

}  // namespace granseg
