// FlowSolver: construction, the state, the step (both modes), the explicit step, invariants. The
// semi-implicit step is in flow/semi_implicit_step.cpp.
#include "flow/flow_solver.hpp"

#include "core/error.hpp"
#include "core/format.hpp"
#include "core/threads.hpp"
#include "flow/diffusion/viscosity.hpp"
#include "flow/faces/convection.hpp"
#include "flow/faces/loads.hpp"
#include "flow/fields/primitives.hpp"
#include "flow/velocity_gradient.hpp"

#include <cmath>
#include <functional>
#include <string>

namespace granseg {

const char* flow_stage_name(FlowStage stage) {
    static const char* const names[kFlowStages] = {"closures",  "step_size",      "forces",         "predictor",
                                                   "viscosity", "pressure_faces", "pressure_solve", "repeat",
                                                   "transport", "increments",     "temperature"};
    return names[static_cast<int>(stage)];
}

double FlowTimers::total() const {
    double sum = 0.0;
    for (double s : seconds) sum += s;
    return sum;
}

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
    if (transport_scheme(settings_) == Transport::muscl) {
        if (settings_.time_stepping != TimeStepping::semi_implicit)
            throw InputError("FlowSolver: transport = muscl needs the semi-implicit time stepping");
        reconstruction_.emplace(g, settings_.limiter);
    }

    const std::size_t cells = g.cells();
    for (auto* f : {&state_.Phi, &state_.E, &state_.T, &Phi_before_, &closures_.p, &closures_.c, &closures_.eta,
                    &closures_.lambda, &closures_.epsPhi, &closures_.Phi_rcp, &closures_.Phi_co, &potential_.cell, &E_start_,
                    &mass_change_, &dp_, &dust_scale_, &Phi_after_, &line_rhs_, &heat_})
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
        for (auto* f :
             {&P.p_lo, &P.p_hi, &P.force, &P.predictor, &P.smoothing, &P.coupling, &P.value_lo, &P.value_hi, &P.donor, &P.flux})
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
            throw InvariantError("flow: phi_hat = " + format_number(phi_hat[c]) + " outside [0, 1] at cell " + std::to_string(c));
    // The state keeps Phi < Phi_rcp (header comment): a mixture change that moves Phi_rcp to or
    // below a cell's Phi is the mixture's doing, not the flow's.
    if (!state_.Phi.empty())
        for (std::size_t c : mesh_.inside_cells) {
            const double x = phi_hat.empty() ? settings_.phi_hat : phi_hat[c], rcp = material_.packing.Phi_rcp(x);
            if (!(state_.Phi[c] < rcp))
                throw InvariantError("flow: the mixture change to phi_hat = " + format_number(x) +
                                     " at x = " + format_number(mesh_.position[0][c]) +
                                     ", z = " + format_number(mesh_.position[2][c]) + " moves Phi_rcp to " +
                                     format_number(rcp, 8) + ", at or below the cell's Phi = " + format_number(state_.Phi[c], 8) +
                                     " (t = " + format_number(t_) + " s)");
        }
    phi_hat_ = std::move(phi_hat);
}

std::array<double, 2> FlowSolver::packing(std::size_t cell) const {
    const double x = phi_hat_.empty() ? settings_.phi_hat : phi_hat_[cell];
    return {material_.packing.Phi_rcp(x), material_.packing.Phi_co(x)};
}

double FlowSolver::step(double t_end) {
    const SerialScope serial(!mesh_.parallel);  // below the crossover Eigen's products run on one thread too
    Phi_before_ = state_.Phi;
    update_closures();
    const StepSize size =
        settings_.time_stepping == TimeStepping::semi_implicit ? semi_implicit_step(t_end) : explicit_step(t_end);
    gradient_valid_ = false;
    temperature(size.dt);
    t_ += size.dt;
    dt_ = size.dt, bound_ = size.bound;
    ++counters_.set_by[static_cast<int>(size.bound)];
    ++steps_;
    check_invariants();
    return size.dt;
}

void FlowSolver::update_closures() {
    Stopwatch watch(timers_, FlowStage::closures);
    compute_primitives(mesh_, material_, settings_, phi_hat_, t_, state_, closures_);
}

void FlowSolver::potential_at(double t) {
    t_forces_ = t;
    cell_potential(mesh_, frame_, t_forces_, potential_.cell);
}

StepSize FlowSolver::explicit_step(double t_end) {
    const StepSize size = explicit_convection(t_end);
    viscosity(size.dt);
    return size;
}

StepSize FlowSolver::explicit_convection(double t_end) {
    StepSize size{};
    {
        Stopwatch watch(timers_, FlowStage::forces);
        potential_at(t_);  // the explicit step's dt follows from these forces: gravity at t^n
        for (int a = 0; a < 3; ++a) {
            if (!mesh_.active[a]) continue;
            face_loads(a);
            hllc_face_fluxes(mesh_, a, state_, closures_, potential_, loads_[a], faces_[a]);
        }
        effective_pressure(mesh_, faces_, closures_);
    }
    {
        Stopwatch watch(timers_, FlowStage::step_size);
        const StepRates rates = explicit_step_rates(mesh_, state_, closures_, faces_);
        size = time_step(mesh_, settings_, t_, t_end, rates, state_, closures_);
    }
    Stopwatch watch(timers_, FlowStage::predictor);
    explicit_update(mesh_, settings_, frame_, source_, t_forces_, size.dt, faces_, state_);
    return size;
}

void FlowSolver::face_loads(int a) {
    face_potential(mesh_, frame_, t_forces_, a, potential_.cell, potential_.face[a]);
    unsupported_loads(mesh_, settings_, frame_, t_forces_, a, state_, closures_, potential_, loads_[a]);
}

void FlowSolver::viscosity(double dt) {
    Stopwatch watch(timers_, FlowStage::viscosity);
    if (viscosity_solve(settings_) == ViscositySolve::split) {
        implicit_viscosity(mesh_, settings_, walls_, dt, closures_.eta, lines_, line_rhs_, state_);
        return;
    }
    if (!coupled_) coupled_.emplace(mesh_, settings_.factorisation);
    coupled_->apply(mesh_, settings_, walls_, dt, closures_.eta, state_);
}

void FlowSolver::temperature(double dt) {
    Stopwatch watch(timers_, FlowStage::temperature);
    counters_.temperature_iterations += temperature_.apply(mesh_, settings_, walls_, dt, closures_, heat_, state_);
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
    // Phi_rcp of the step (closures_, from the phi_hat the step ran with).
    const std::vector<double>& rcp = closures_.Phi_rcp;
    auto ok = [&](std::size_t c) {
        return Phi[c] >= 0.0 && Phi[c] < rcp[c] && std::isfinite(Phi[c]) && T[c] >= 0.0 && std::isfinite(T[c]) &&
               std::isfinite(u[0][c]) && std::isfinite(u[1][c]) && std::isfinite(u[2][c]);
    };
    const long bad = parallel_fold(
        mesh_.parallel, mesh_.inside_cells.size(), 0L,
        [&](long& count, std::size_t q) { count += ok(mesh_.inside_cells[q]) ? 0 : 1; }, std::plus<long>());
    if (bad == 0) return;
    for (std::size_t c : mesh_.inside_cells)
        if (!ok(c))
            throw InvariantError("flow: invalid state at x = " + format_number(mesh_.position[0][c]) +
                                 ", z = " + format_number(mesh_.position[2][c]) + ", t = " + format_number(t_) +
                                 " s after a flow step: Phi = " + format_number(Phi[c], 8) + " (Phi_rcp " +
                                 format_number(rcp[c], 8) + "), T = " + format_number(T[c]) + ", u = (" + format_number(u[0][c]) +
                                 ", " + format_number(u[1][c]) + ", " + format_number(u[2][c]) + ") (" + std::to_string(bad) +
                                 " cells)");
}

}  // namespace granseg
