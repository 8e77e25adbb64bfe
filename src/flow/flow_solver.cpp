// FlowSolver: construction, the state, the step driver (the sequence of kernels), invariants.
#include "flow/flow_solver.hpp"

#include "core/error.hpp"
#include "core/format.hpp"
#include "flow/convection.hpp"
#include "flow/loads.hpp"
#include "flow/primitives.hpp"
#include "flow/velocity_gradient.hpp"
#include "flow/viscosity.hpp"

#include <chrono>
#include <cmath>
#include <string>

namespace granseg {

namespace {
/// The pressure equation is solved to this share of the step's largest explicit mass change
/// (and to round-off in a bed that does not change): errors far below the scheme's.
constexpr double kPressureAccuracy = 1e-6;
/// Pressure solves per step attempt: the first, and repeats after faces reversed by the pressure
/// took the smaller donor (semi_implicit.hpp).
constexpr int kDonorPasses = 4;

double seconds_since(std::chrono::steady_clock::time_point t0) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}
}  // namespace

FlowSolver::FlowSolver(Grid grid, Material material, FlowSettings settings, Frame frame)
    : mesh_(std::move(grid)),
      material_(std::move(material)),
      settings_(settings),
      frame_(frame),
      pressure_solver_(mesh_),
      lines_(mesh_),
      temperature_(mesh_) {
    const Grid& g = mesh_.grid;
    if (frame_.omega != 0.0 && (g.periodic[0] || g.periodic[2]))
        throw InputError("FlowSolver: a rotating frame needs walls (not periodic ends) along x and z");
    if (!(settings_.T_floor > 0.0) || !(settings_.Phi_vacuum > 0.0) || !(settings_.cfl > 0.0))
        throw InputError("FlowSolver: T_floor, Phi_vacuum and cfl must be > 0");

    const std::size_t cells = g.cells();
    for (auto* f : {&state_.Phi, &state_.E, &state_.T, &Phi_before_, &closures_.p, &closures_.c, &closures_.eta,
                    &closures_.lambda, &closures_.epsPhi, &closures_.Phi_rcp, &closures_.Phi_co, &potential_.cell,
                    &E_start_, &mass_change_, &dp_, &dust_scale_, &Phi_after_, &line_rhs_, &heat_})
        f->assign(cells, 0.0);
    for (int b = 0; b < 3; ++b) {
        state_.m[b].assign(cells, 0.0);
        state_.u[b].assign(cells, 0.0);
        m_start_[b].assign(cells, 0.0);
        u_start_[b].assign(cells, 0.0);
        force_part_[b].assign(cells, 0.0);
        u_star_[b].assign(cells, 0.0);
        velocity_change_[b].assign(cells, 0.0);
        increment_.u[b].assign(cells, 0.0);
        increment_.m[b].assign(cells, 0.0);
        loads_[b].load.assign(cells, 0.0);
        loads_[b].carry.assign(cells, 0.0);
        loads_[b].downhill.assign(cells, 0.0);
    }
    for (auto& f : grad_) f.assign(cells, 0.0);
    for (int a = 0; a < 3; ++a) {
        const std::size_t faces = g.faces(a);
        AxisFaces& F = faces_[a];
        for (auto* f : {&F.mass, &F.energy, &F.mom_below, &F.p, &F.speed, &potential_.face[a]}) f->assign(faces, 0.0);
        for (int b = 0; b < 3; ++b) F.mom[b].assign(faces, 0.0);
        AxisPressureFaces& P = pressure_[a];
        for (auto* f : {&P.p_lo, &P.p_hi, &P.corr_lo, &P.corr_hi, &P.force, &P.predictor, &P.coupling, &P.donor, &P.flux})
            f->assign(faces, 0.0);
        P.reversed.assign(faces, 0);
    }
    for (std::size_t c : mesh_.inside_cells) state_.T[c] = settings_.T_floor;
}

void FlowSolver::set_state(const std::vector<double>& Phi, const std::array<std::vector<double>, 3>& u,
                           const std::vector<double>& T) {
    const std::size_t cells = mesh_.grid.cells();
    if (Phi.size() != cells || T.size() != cells || u[0].size() != cells || u[1].size() != cells || u[2].size() != cells)
        throw InputError("FlowSolver::set_state: fields must have one value per grid cell");
    for (std::size_t c : mesh_.inside_cells) {
        if (!(Phi[c] >= 0.0) || !(T[c] >= 0.0) || !std::isfinite(Phi[c]) || !std::isfinite(T[c]))
            throw InvariantError("flow initial state: Phi = " + format_number(Phi[c]) + ", T = " + format_number(T[c]) +
                                 " at cell " + std::to_string(c) + " (need finite Phi >= 0, T >= 0)");
        const bool empty = Phi[c] <= settings_.Phi_vacuum;
        state_.Phi[c] = Phi[c];
        for (int b = 0; b < 3; ++b) state_.m[b][c] = empty ? 0.0 : Phi[c] * u[b][c];
        state_.E[c] = Phi[c] * (empty ? settings_.T_floor : std::max(T[c], settings_.T_floor));
    }
    Phi_before_ = state_.Phi;
    update_closures();
    gradient_valid_ = false;
}

void FlowSolver::set_phi_hat(std::vector<double> phi_hat) {
    if (!phi_hat.empty() && phi_hat.size() != mesh_.grid.cells())
        throw InputError("FlowSolver::set_phi_hat: need one value per grid cell");
    for (std::size_t c : mesh_.inside_cells)
        if (!phi_hat.empty() && !(phi_hat[c] >= 0.0 && phi_hat[c] <= 1.0))
            throw InvariantError("flow: phi_hat = " + format_number(phi_hat[c]) + " outside [0, 1] at cell " +
                                 std::to_string(c));
    phi_hat_ = std::move(phi_hat);
}

std::array<double, 2> FlowSolver::packing(std::size_t cell) const {
    const double x = phi_hat_.empty() ? settings_.phi_hat : phi_hat_[cell];
    return {material_.packing.Phi_rcp(x), material_.packing.Phi_co(x)};
}

void FlowSolver::update_closures() {
    cell_potential(mesh_, frame_, t_, potential_.cell);
    compute_primitives(mesh_, material_, settings_, phi_hat_, t_, state_, closures_);
}

StepSize FlowSolver::explicit_step(double t_end) {
    using clock = std::chrono::steady_clock;
    auto t0 = clock::now();
    for (int a = 0; a < 3; ++a) {
        if (!mesh_.active[a]) continue;
        face_potential(mesh_, frame_, t_, a, potential_.cell, potential_.face[a]);
        unsupported_loads(mesh_, settings_, frame_, t_, a, state_, closures_, potential_, loads_[a]);
        hllc_face_fluxes(mesh_, a, state_, closures_, potential_, loads_[a], faces_[a]);
    }
    effective_pressure(mesh_, faces_, closures_);
    const StepRates rates = explicit_step_rates(mesh_, state_, closures_, faces_);
    const StepSize size = time_step(mesh_, settings_, t_, t_end, rates, state_, closures_);
    explicit_update(mesh_, settings_, frame_, source_, t_, size.dt, faces_, state_);
    timers_.convection += seconds_since(t0);
    t0 = clock::now();
    viscosity(size.dt);
    timers_.viscosity += seconds_since(t0);
    return size;
}

StepSize FlowSolver::semi_implicit_step(double t_end) {
    using clock = std::chrono::steady_clock;
    auto t0 = clock::now();
    const StepRates rates = material_step_rates(mesh_, state_, closures_, faces_, steps_ == 0);  // the last step's faces
    for (int a = 0; a < 3; ++a) {
        if (!mesh_.active[a]) continue;
        face_potential(mesh_, frame_, t_, a, potential_.cell, potential_.face[a]);
        unsupported_loads(mesh_, settings_, frame_, t_, a, state_, closures_, potential_, loads_[a]);
        pressure_faces(mesh_, a, frame_.gravity, state_, closures_, potential_, loads_[a], pressure_[a], faces_[a]);
    }
    effective_pressure(mesh_, faces_, closures_);
    auto [dt, bound] = time_step(mesh_, settings_, t_, t_end, rates, state_, closures_);
    if (steps_ > 0 && kStepGrowth * dt_ < dt) dt = kStepGrowth * dt_, bound = StepBound::growth;
    m_start_ = state_.m, u_start_ = state_.u, E_start_ = state_.E;
    for (;;) {
        // 1. Predictor: pressure and weight at t^n, Coriolis, sources; the force part A (before
        // viscosity: the face predictor replaces it by the face's own force); viscosity.
        for (int a = 0; a < 3; ++a)
            if (mesh_.active[a]) predictor_faces(mesh_, a, dt, state_, closures_, pressure_[a], faces_[a]);
        explicit_update(mesh_, settings_, frame_, source_, t_, dt, faces_, state_);
        mesh_.for_each_inside([&](std::size_t c) {
            for (int b = 0; b < 3; ++b) force_part_[b][c] = state_.u[b][c] - u_start_[b][c];
        });
        timers_.convection += seconds_since(t0);
        t0 = clock::now();
        viscosity(dt);
        timers_.viscosity += seconds_since(t0);
        t0 = clock::now();
        // 2., 3. Face predictor, pressure increments, corrected faces; the donors of faces the
        // pressure reversed onto a cell with clearly less material become the smaller cell and
        // the solve is repeated.
        PressureSolveStats stats;
        bool within = false;
        for (int donor_passes = 1;; ++donor_passes) {
            for (int a = 0; a < 3; ++a)
                if (mesh_.active[a]) pressure_coupling(mesh_, settings_, a, dt, state_, closures_, force_part_, pressure_[a]);
            explicit_mass_change(mesh_, dt, pressure_, mass_change_);
            const auto tp = clock::now();
            stats = pressure_solver_.solve(mesh_, material_, state_, closures_, pressure_, mass_change_, kPressureAccuracy, dp_);
            timers_.pressure += seconds_since(tp);
            ++counters_.pressure_solves, counters_.newton += stats.newton, counters_.krylov += stats.krylov;
            if (!stats.converged) break;
            for (int a = 0; a < 3; ++a)
                if (mesh_.active[a])
                    corrected_face_velocities(mesh_, a, dt, state_, closures_, pressure_[a], dp_, faces_[a]);
            cap_dust_outflow(mesh_, dt, state_, closures_, dust_scale_, faces_);
            volume_fraction_after(mesh_, dt, state_.Phi, faces_, Phi_after_);
            long reversed = 0;
            for (int a = 0; a < 3; ++a)
                if (mesh_.active[a]) {
                    semi_implicit_face_fluxes(mesh_, a, state_, pressure_[a], dp_, Phi_after_, faces_[a]);
                    reversed += mark_reversed_faces(mesh_, a, state_, faces_[a], pressure_[a]);
                }
            if (reversed > 0 && donor_passes < kDonorPasses) continue;
            within = step_within_bounds(mesh_, dt, state_.Phi, closures_, faces_);
            break;
        }
        if (within) break;
        ++counters_.repeated;
        dt *= 0.5, bound = StepBound::halved;
        state_.Phi = Phi_before_, state_.m = m_start_, state_.E = E_start_;
        mesh_.for_each_inside([&](std::size_t c) { dp_[c] = 0.0; });
        if (!(dt >= settings_.dt_min))
            throw InvariantError("flow: the semi-implicit step fell below dt_min = " + format_number(settings_.dt_min) +
                                 " s at t = " + format_number(t_) + " s: " +
                                 (stats.converged ? "a cell would lose more than its mass or reach Phi_rcp"
                                                  : "the pressure equation did not converge (residual " +
                                                        format_number(stats.residual) + ")"));
    }
    // 3. Transport and the corrections of the increments (the predictor already carries gravity,
    // Coriolis and the sources): Phi_new = Phi - dt div M exactly.
    for (int b = 0; b < 3; ++b) u_star_[b] = state_.u[b];
    transport_update(mesh_, settings_, dt, faces_, state_);
    timers_.convection += seconds_since(t0);
    t0 = clock::now();
    viscous_increment(dt);
    timers_.viscosity += seconds_since(t0);
    return {dt, bound};
}

void FlowSolver::viscosity(double dt) {
    if (viscosity_solve(settings_) == ViscositySolve::split) {
        implicit_viscosity(mesh_, settings_, walls_, dt, closures_.eta, lines_, line_rhs_, state_);
        return;
    }
    if (!coupled_) coupled_.emplace(mesh_);
    coupled_->apply(mesh_, settings_, walls_, dt, closures_.eta, state_);
}

void FlowSolver::diffuse_change(double dt, std::array<std::vector<double>, 3>& du) {
    if (viscosity_solve(settings_) == ViscositySolve::coupled) return coupled_->diffuse_change(mesh_, du);
    for (int b = 0; b < 3; ++b) increment_.u[b] = du[b];
    increment_.Phi = Phi_before_;
    implicit_viscosity(mesh_, settings_, WallVelocities{}, dt, closures_.eta, lines_, line_rhs_, increment_);
    mesh_.for_each_inside([&](std::size_t c) {
        if (Phi_before_[c] > settings_.Phi_vacuum)
            for (int b = 0; b < 3; ++b) du[b][c] = increment_.u[b][c];
    });
}

void FlowSolver::viscous_increment(double dt) {
    const double Phi_vac = settings_.Phi_vacuum;
    mesh_.for_each_inside([&](std::size_t c) {
        for (int b = 0; b < 3; ++b) velocity_change_[b][c] = state_.u[b][c] - u_star_[b][c];
    });
    diffuse_change(dt, velocity_change_);
    // A cell empty at t^n (its row was the identity) or at the end keeps the update's velocity.
    mesh_.for_each_inside([&](std::size_t c) {
        if (!(Phi_before_[c] > Phi_vac && state_.Phi[c] > Phi_vac)) return;
        for (int b = 0; b < 3; ++b) {
            state_.u[b][c] = u_star_[b][c] + velocity_change_[b][c];
            state_.m[b][c] = state_.Phi[c] * state_.u[b][c];
        }
    });
}

double FlowSolver::step(double t_end) {
    using clock = std::chrono::steady_clock;
    Phi_before_ = state_.Phi;
    auto t0 = clock::now();
    update_closures();
    timers_.closures += seconds_since(t0);
    const auto [dt, bound] =
        settings_.time_stepping == TimeStepping::semi_implicit ? semi_implicit_step(t_end) : explicit_step(t_end);
    gradient_valid_ = false;
    t0 = clock::now();
    counters_.temperature_iterations += temperature_.apply(mesh_, settings_, walls_, dt, closures_, heat_, state_);
    timers_.temperature += seconds_since(t0);

    t_ += dt;
    dt_ = dt, bound_ = bound;
    ++counters_.set_by[static_cast<int>(bound)];
    ++steps_;
    check_invariants();
    return dt;
}

const std::vector<double>& FlowSolver::velocity_gradient(int b, int a) const {
    if (!gradient_valid_) {
        granseg::velocity_gradient(mesh_, settings_, walls_, state_.Phi, state_.u, grad_);
        gradient_valid_ = true;
    }
    return grad_[3 * b + a];
}

double FlowSolver::mass() const {
    double sum = 0.0;
    for (std::size_t c : mesh_.inside_cells) sum += state_.Phi[c];
    return sum * mesh_.grid.cell_volume();
}

void FlowSolver::check_invariants() const {
    const std::vector<double>& Phi = state_.Phi;
    const std::vector<double>& T = state_.T;
    const auto& u = state_.u;
    auto ok = [&](std::size_t c) {
        return Phi[c] >= 0.0 && std::isfinite(Phi[c]) && T[c] >= 0.0 && std::isfinite(T[c]) && std::isfinite(u[0][c]) &&
               std::isfinite(u[1][c]) && std::isfinite(u[2][c]);
    };
    long bad = 0;
    const std::size_t n = mesh_.inside_cells.size();
#pragma omp parallel for reduction(+ : bad) schedule(static) if (mesh_.parallel)
    for (std::size_t q = 0; q < n; ++q) bad += ok(mesh_.inside_cells[q]) ? 0 : 1;
    if (bad == 0) return;
    for (std::size_t c : mesh_.inside_cells)
        if (!ok(c))
            throw InvariantError("flow: invalid state at x = " + format_number(mesh_.position[0][c]) + ", z = " +
                                 format_number(mesh_.position[2][c]) + ", t = " + format_number(t_) + " s: Phi = " +
                                 format_number(Phi[c]) + ", T = " + format_number(T[c]) + ", u = (" +
                                 format_number(u[0][c]) + ", " + format_number(u[1][c]) + ", " +
                                 format_number(u[2][c]) + ") (" + std::to_string(bad) + " cells)");
}

}  // namespace granseg
