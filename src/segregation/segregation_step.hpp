// The segregation sub-step: phi segregates with Phi and T frozen (eq. 52b).
//
// On any Grid (1-D column, 2-D x-z plane with embedded walls, periodic axes) the sub-step is
// split over the axes (eq. 65, Lie splitting x, then y, then z; docs/assumptions.md S2): along
// each axis that has coefficients a_k, eq. (64) with the interface fluxes of face_fluxes.hpp.
// First-order schemes take one forward-Euler stage per axis; modified-godunov-2 takes two
// (SSP-RK2: u1 = u0 + dt L(u0), u = (u0 + u1 + dt L(u1))/2, a convex combination of Euler steps).
//
// Time step: dt = cfl * dt_max with
//     dt_max = min over axes k of 1 / (order * max|a_k|/h_k + 2 D/h_k^2),
// the largest step for which the modified schemes keep 0 <= phi <= Phi (order = 2 for
// modified-godunov-2: its update is an average of first-order updates at twice the step).
// So cfl <= 1 is safe for every scheme, and cfl > 1 is rejected.
#pragma once

#include "segregation/frozen_fields.hpp"
#include "segregation/scheme.hpp"

#include <functional>
#include <vector>

namespace granseg {

struct SegregationOptions {
    SegregationScheme scheme = SegregationScheme::modified_godunov;
    Limiter limiter = Limiter::mc;  // modified-godunov-2 only
    double cfl = 0.9;               // 0 < cfl <= 1
};

class SegregationSolver {
public:
    /// Throws std::invalid_argument (one line) if options.cfl is outside (0, 1].
    SegregationSolver(Grid grid, SegregationOptions options);

    /// cfl * dt_max (see above); +infinity if no coefficient and no diffusion is non-zero.
    /// Checks the fields first (check_frozen_fields).
    double time_step(const FrozenFields& fields) const;

    /// One sub-step of length dt (eq. 52b), split over the axes; phi changes in inside cells only.
    void step(const FrozenFields& fields, double dt, std::vector<double>& phi);

    /// Steps of length time_step(fields) (the last one shortened) until `duration` has passed;
    /// calls after_step(t, dt) after each step if given. Returns the number of steps.
    long advance(const FrozenFields& fields, double duration, std::vector<double>& phi,
                 const std::function<void(double t, double dt)>& after_step = {});

    const Grid& grid() const { return grid_; }
    const SegregationOptions& options() const { return options_; }
    /// Inside-cell updates done so far (one per cell, axis and Runge-Kutta stage).
    long long cell_updates() const { return cell_updates_; }

private:
    /// The interface fluxes of the scheme along `axis` for the state phi (counts the updates).
    void face_fluxes(const FrozenFields& fields, int axis, const std::vector<double>& phi, std::vector<double>& F);

    Grid grid_;
    SegregationOptions options_;
    std::size_t inside_cells_ = 0;
    long long cell_updates_ = 0;
    std::vector<double> F_, F_stage_, at_lower_, at_upper_, stage_;  // work space
};

}  // namespace granseg
