#include "segregation/segregation_solver.hpp"

#include "core/format.hpp"
#include "segregation/face_fluxes.hpp"
#include "segregation/reconstruction.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace granseg {

SegregationSolver::SegregationSolver(Grid grid, SegregationOptions options) : grid_(std::move(grid)), options_(options) {
    if (!(options_.cfl > 0.0 && options_.cfl <= 1.0))
        throw InputError("segregation: CFL number " + format_number(options_.cfl) +
                         " is outside (0, 1]; above 1 the scheme no longer keeps 0 <= phi <= Phi");
    for (std::size_t c = 0; c < grid_.cells(); ++c) inside_cells_ += grid_.is_inside(c);
}

double SegregationSolver::time_step(const FrozenFields& fields) const {
    check_frozen_fields(grid_, fields);
    // Per Euler stage: (stage dt) * (r max|a|/h + 2 D/h^2) <= 1, r = 2 with reconstruction.
    const bool second = scheme_order(options_.scheme) == 2;
    const double reconstruction = second ? 2.0 : 1.0, ssp = second ? kSspStages - 1.0 : 1.0;
    double rate = 0.0;  // 1/dt_max
    for (int axis = 0; axis < 3; ++axis) {
        if (fields.a[axis].empty()) continue;
        const double h = grid_.h[axis];
        rate = std::max(
            rate, (reconstruction * max_coefficient(grid_, axis, fields, options_.scheme) / h + 2.0 * fields.D / (h * h)) / ssp);
    }
    return rate > 0.0 ? options_.cfl / rate : std::numeric_limits<double>::infinity();
}

void SegregationSolver::face_fluxes(const FrozenFields& fields, int axis, const std::vector<double>& phi,
                                    std::vector<double>& F) {
    if (scheme_order(options_.scheme) == 2) {
        reconstruct_faces(grid_, axis, phi, fields.Phi, options_.limiter, at_lower_, at_upper_);
        segregation_face_fluxes(grid_, axis, fields, options_.scheme, phi, at_lower_, at_upper_, F);
    } else {
        segregation_face_fluxes(grid_, axis, fields, options_.scheme, phi, phi, phi, F);
    }
    cell_updates_ += static_cast<long long>(inside_cells_);
}

void SegregationSolver::step(const FrozenFields& fields, double dt, std::vector<double>& phi) {
    if (phi.size() != grid_.cells() || fields.Phi.size() != grid_.cells())
        throw InputError("segregation: phi and Phi need one value per cell");
    for (int axis = 0; axis < 3; ++axis) {  // Lie splitting over the axes (eq. 65)
        if (fields.a[axis].empty()) continue;
        face_fluxes(fields, axis, phi, F_);
        if (scheme_order(options_.scheme) == 2) {
            // SSP-RK(3,2): u(k) = u(k-1) + dt/2 L(u(k-1)) for k = 1, 2, 3 and u = (u(0) + 2 u(3))/3,
            // a convex combination of Euler steps of length dt/2. Applied here as
            // u = u(0) - dt D(mean of the three stage fluxes): the same value in conservative form.
            stage_ = phi;
            F_sum_ = F_;
            for (int k = 1; k < kSspStages; ++k) {
                apply_flux_difference(grid_, axis, F_, dt / (kSspStages - 1), stage_);  // (eq. 64)
                face_fluxes(fields, axis, stage_, F_);
                for (std::size_t f = 0; f < F_.size(); ++f) F_sum_[f] += F_[f];
            }
            for (std::size_t f = 0; f < F_.size(); ++f) F_[f] = F_sum_[f] / kSspStages;
        }
        apply_flux_difference(grid_, axis, F_, dt, phi);  // (eq. 64)
        round_off_guard(fields.Phi, phi);
    }
}

void SegregationSolver::round_off_guard(const std::vector<double>& Phi, std::vector<double>& phi) {
    const bool bounded = preserves_bounds(options_.scheme);
    for (std::size_t c = 0; c < phi.size(); ++c) {
        if (!grid_.is_inside(c)) continue;
        double& v = phi[c];
        if (std::fabs(v) < kUnderflowFloor) v = 0.0;
        if (!bounded) continue;
        if (v < 0.0) {
            largest_correction_ = std::max(largest_correction_, -v);
            v = 0.0;
        } else if (v > Phi[c]) {
            largest_correction_ = std::max(largest_correction_, v - Phi[c]);
            v = Phi[c];
        }
    }
}

long SegregationSolver::advance(const FrozenFields& fields, double duration, std::vector<double>& phi,
                                const std::function<void(double, double)>& after_step) {
    const double dt_max = time_step(fields);
    long steps = 0;
    for (double t = 0.0; t < duration; ++steps) {
        const double dt = step_towards(fields, dt_max, duration, t, phi);
        if (after_step) after_step(t, dt);
    }
    return steps;
}

double SegregationSolver::step_towards(const FrozenFields& fields, double dt_max, double duration, double& t,
                                       std::vector<double>& phi) {
    const double dt = std::min(dt_max, duration - t);
    step(fields, dt, phi);
    t = dt == duration - t ? duration : t + dt;
    return dt;
}

}  // namespace granseg
