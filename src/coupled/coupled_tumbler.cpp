#include "coupled/coupled_tumbler.hpp"

#include "core/error.hpp"
#include "core/format.hpp"
#include "core/stopwatch.hpp"
#include "core/threads.hpp"
#include "direction/segregation_direction.hpp"
#include "direction/segregation_velocity.hpp"
#include "segregation/invariants.hpp"
#include "segregation/reconstruction.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace granseg {

namespace {

/// The flow settings with the initial mixture as the uniform phi_hat.
FlowSettings with_mixture(FlowSettings settings, double mixture) {
    settings.phi_hat = mixture;
    return settings;
}

}  // namespace

CoupledTumbler::InitialMixture CoupledTumbler::initial_mixture(const CoupledTumblerSetup& setup) {
    const Grid grid = setup.drum.grid();
    const std::vector<double> fill = drum_fill_fraction(setup.drum, grid);
    InitialMixture m{std::vector<double>(grid.cells(), 0.0), 0.0};
    double filled = 0.0;
    for (int k = 0; k < grid.n[2]; ++k)
        for (int j = 0; j < grid.n[1]; ++j)
            for (int i = 0; i < grid.n[0]; ++i) {
                const std::size_t c = grid.index(i, j, k);
                if (!(fill[c] > 0.0)) continue;
                const double x = grid.center(0, i), z = grid.center(2, k), v = setup.phi_hat0(x, z);
                if (!(v >= 0.0 && v <= 1.0))
                    throw InputError("tumbler: initial phi_hat = " + format_number(v) + " at x = " + format_number(x) +
                                     ", z = " + format_number(z) + " outside [0, 1]");
                m.phi_hat[c] = v;
                m.mean += fill[c] * v, filled += fill[c];  // (assumption C3)
            }
    m.mean /= filled;
    if (!std::isnan(setup.mixture)) {
        if (!(setup.mixture >= 0.0 && setup.mixture <= 1.0))
            throw InputError("tumbler: mixture = " + format_number(setup.mixture) + " outside [0, 1]");
        if (setup.packing_feedback) throw InputError("tumbler: a fixed mixture needs packing feedback off (C3)");
        m.mean = setup.mixture;
    }
    return m;
}

CoupledTumbler::CoupledTumbler(const CoupledTumblerSetup& setup)
    : setup_(setup),
      initial_(initial_mixture(setup)),
      flow_(setup.drum.grid(), setup.material, with_mixture(setup.flow, initial_.mean), setup.drum.frame()),
      bulk_(flow_.grid()),
      segregation_(flow_.grid(), setup.segregation),
      inside_(flow_.grid().cells(), 1),
      parallel_(threads_pay(flow_.grid().cells())) {
    if (!flow_.grid().inside.empty()) inside_ = flow_.grid().inside;
    if (transport_scheme(setup.flow) == Transport::muscl) fct_.emplace(flow_.grid(), setup.flow.limiter);
    if (!(setup.S >= 0.0 && std::isfinite(setup.S))) throw InputError("tumbler: S must be finite and >= 0");
    if (!preserves_bounds(setup.segregation.scheme))
        throw InputError("tumbler: the segregation scheme must keep 0 <= phi <= Phi (modified-godunov, -2)");
    const Grid& g = flow_.grid();
    const std::vector<double> Phi0 =
        setup.packing_feedback
            ? drum_bed_at_rest(setup.drum, g, setup.material, initial_.phi_hat, initial_.mean, setup.flow.T_floor)
            : drum_bed_at_rest(setup.drum, g, setup.material, initial_.mean, setup.flow.T_floor);
    phi_.assign(g.cells(), 0.0);
    for (std::size_t c = 0; c < g.cells(); ++c) phi_[c] = initial_.phi_hat[c] * Phi0[c];
    if (setup.tracer0) {
        tracer_.assign(g.cells(), 0.0);
        for (int k = 0; k < g.n[2]; ++k)
            for (int j = 0; j < g.n[1]; ++j)
                for (int i = 0; i < g.n[0]; ++i) {
                    const std::size_t c = g.index(i, j, k);
                    if (!g.is_inside(c)) continue;
                    const double x = g.center(0, i), z = g.center(2, k), v = setup.tracer0(x, z);
                    if (!(v >= 0.0 && v <= 1.0))
                        throw InputError("tumbler: initial tracer = " + format_number(v) + " at x = " + format_number(x) +
                                         ", z = " + format_number(z) + " outside [0, 1]");
                    tracer_[c] = v * Phi0[c];
                }
    }
    if (setup.packing_feedback) flow_.set_phi_hat(initial_.phi_hat);  // before set_state, which checks Phi < Phi_rcp
    const std::vector<double> zero(g.cells(), 0.0), T(g.cells(), setup.flow.T_floor);
    flow_.set_state(Phi0, {zero, zero, zero}, T);

    frozen_.Phi = Phi0;
    for (int axis = 0; axis < 3; ++axis)
        if (g.n[axis] > 1) frozen_.a[axis].assign(g.cells(), 0.0), d_s_[axis].assign(g.cells(), 0.0);
}

void CoupledTumbler::start_from(StateIO& flow_state) {
    flow_.checkpoint(flow_state);
    const Grid& g = grid();
    const double t = flow_.time();
    const auto share = [&](const std::function<double(double, double)>& f, const char* name, std::size_t c) {
        if (!(flow_.Phi()[c] > 0.0)) return 0.0;
        const auto lab = flow_.frame().to_lab_position(t, g.center(0, c % g.n[0]), g.center(2, c / (g.n[0] * g.n[1])));
        const double v = f(lab[0], lab[1]);
        if (!(v >= 0.0 && v <= 1.0))
            throw InputError(std::string("tumbler: initial ") + name + " = " + format_number(v) +
                             " at x = " + format_number(lab[0]) + ", z = " + format_number(lab[1]) +
                             " (lab frame, t = " + format_number(t) + " s) outside [0, 1]");
        return v * flow_.Phi()[c];
    };
    for (std::size_t c = 0; c < g.cells(); ++c) {
        if (!g.is_inside(c)) continue;
        phi_[c] = share(setup_.phi_hat0, "phi_hat", c);
        if (!tracer_.empty()) tracer_[c] = share(setup_.tracer0, "tracer", c);
    }
    flow_.set_phi_hat(setup_.packing_feedback ? phi_hat() : std::vector<double>{});  // (assumption C3)
    frozen_.Phi = flow_.Phi();
}

std::vector<double> CoupledTumbler::phi_hat() const {
    const std::size_t cells = grid().cells();
    const unsigned char* in = inside_.data();
    const double *Phi = flow_.Phi().data(), *phi = phi_.data();
    std::vector<double> hat(cells);
    parallel_for(parallel_, cells, [&](std::size_t c) { hat[c] = in[c] ? composition(phi[c], Phi[c]) : 0.0; });
    return hat;
}

double CoupledTumbler::step(double t_end) {
    const SerialScope serial(!parallel_);  // below the crossover Eigen's products run on one thread too
    const double dt = timed(timers_.flow, [&] { return flow_.step(t_end); });  // 1. (eqs. 8, 9, 14)
    timed(timers_.bulk, [&] {
        transport(phi_, dt);  // 2. (eq. 65, F^bulk)
        clip_bulk_round_off(phi_, "phi");
        if (!tracer_.empty()) transport(tracer_, dt), clip_bulk_round_off(tracer_, "the tracer");  // 2'.
    });
    timed(timers_.segregation, [&] { segregate(dt); });  // 3. (eqs. 46, 47, 52b; assumption C1)
    timed(timers_.feedback, [&] {
        if (setup_.packing_feedback) flow_.set_phi_hat(phi_hat());  // 4. (eqs. 18, 19)
    });
    return dt;
}

void CoupledTumbler::transport(std::vector<double>& field, double dt) {
    const FaceFieldRefs M = {&flow_.mass_flux(0), &flow_.mass_flux(1), &flow_.mass_flux(2)};
    if (fct_)
        fct_->step(flow_.Phi_before(), flow_.Phi(), M, no_inflow_, dt, field, setup_.Phi_min);
    else
        bulk_.step(flow_.Phi_before(), M, no_inflow_, dt, field, setup_.Phi_min);
}

void CoupledTumbler::clip_bulk_round_off(std::vector<double>& field, const char* name) {
    const std::size_t cells = grid().cells();
    const unsigned char* in = inside_.data();
    const double *Phi = flow_.Phi().data(), *before = flow_.Phi_before().data();
    double* phi = field.data();
    // The donor-cell step keeps phi_hat in [0, 1] exactly, and so does the limited antidiffusion;
    // their rounding is a few ulps of the amounts that pass through a cell: relative to the cell's
    // larger Phi (before or after the step).
    struct Bounds {
        double excess = -INFINITY, lowest = INFINITY, worst = 0.0;  // worst: largest correction / allowance
        long nonfinite = 0;
    };
    auto cell = [&](Bounds& b, std::size_t c) {
        if (!in[c]) return;
        b.nonfinite += !std::isfinite(phi[c]);
        b.excess = std::max(b.excess, phi[c] - Phi[c]), b.lowest = std::min(b.lowest, phi[c]);
        const double correction = std::max(phi[c] - Phi[c], -phi[c]);
        if (correction > 0.0) b.worst = std::max(b.worst, correction / (kBoundRoundOff * std::max(before[c], Phi[c])));
    };
    const auto [excess, lowest, worst, nonfinite] =
        parallel_fold(parallel_, cells, Bounds{}, cell, [](const Bounds& x, const Bounds& y) {
            return Bounds{std::max(x.excess, y.excess), std::min(x.lowest, y.lowest), std::max(x.worst, y.worst),
                          x.nonfinite + y.nonfinite};
        });
    max_excess_ = std::max(max_excess_, excess), min_phi_ = std::min(min_phi_, lowest);
    if (nonfinite > 0)
        throw InvariantError(std::string("tumbler: non-finite ") + name + " after the bulk step at t = " + format_number(time()) +
                             " (" + std::to_string(nonfinite) + " cells)");
    if (!(excess > 0.0 || lowest < 0.0)) return;
    if (worst > 1.0)
        throw InvariantError(std::string("tumbler: the bulk step left 0 <= ") + name +
                             " <= Phi by more than round-off (max excess " + format_number(excess, 3) + ", min " +
                             format_number(lowest, 3) + ") at t = " + format_number(time()) + " s");
    for (std::size_t c = 0; c < cells; ++c) {
        if (!in[c]) continue;
        largest_bulk_clip_ = std::max(largest_bulk_clip_, std::max(phi[c] - Phi[c], -phi[c]));
        phi[c] = std::clamp(phi[c], 0.0, Phi[c]);
    }
}

SegregationDirection CoupledTumbler::direction(std::size_t c) const {
    const FlowSolver& f = flow_;
    DirectionOptions options;
    options.planar_xz = grid().n[1] == 1;
    options.shear_threshold = std::max(options.shear_threshold, setup_.diagnostic_min_shear_rate);  // (D1)
    Eigen::Matrix3d G;
    for (int b = 0; b < 3; ++b)
        for (int k = 0; k < 3; ++k) G(b, k) = f.velocity_gradient(b, k)[c];
    const Eigen::Vector3d u(f.u(0)[c], f.u(1)[c], f.u(2)[c]);  // relative to the drum
    return segregation_direction(G, u, options);               // (Sect. 2.3)
}

void CoupledTumbler::update_segregation_velocity() {
    const FlowSolver& f = flow_;
    const Grid& g = grid();
    const Vec3 gv = f.frame().gravity_at(f.time());  // gravity in the drum frame
    const Eigen::Vector3d gravity(gv[0], gv[1], gv[2]);
    frozen_.Phi = f.Phi();
    for (std::size_t c = 0; c < g.cells(); ++c) {
        Eigen::Vector3d d_s = Eigen::Vector3d::Zero(), a = Eigen::Vector3d::Zero();
        if (g.is_inside(c) && f.Phi()[c] >= setup_.Phi_min) {  // (assumption C2)
            d_s = direction(c).d_s;
            a = segregation_velocity(setup_.S, f.T()[c], d_s, gravity);  // (eq. 46)
        }
        for (int axis = 0; axis < 3; ++axis)
            if (!frozen_.a[axis].empty()) frozen_.a[axis][c] = a(axis), d_s_[axis][c] = d_s(axis);
    }
}

void CoupledTumbler::segregate(double dt) {
    update_segregation_velocity();
    solver_steps_ += segregation_.advance(frozen_, dt, phi_);  // (eq. 52b)
    ++split_steps_;
}

}  // namespace granseg
