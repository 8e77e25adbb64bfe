// The segregation sub-step: phi segregates with Phi and T frozen (eq. 52b).
//
//   solves      eq. (52b), d_t phi + sum_k d_k (a_k phi (phi - Phi)/Phi) = 0 with Phi and T frozen,
//               by eq. (64) split over the axes as in eq. (65)
//   inputs      the Grid, FrozenFields (Phi, a_k, interface values, D), phi, dt; SegregationOptions
//               (a row of the scheme table, the limiter, the CFL number)
//   outputs     phi after the sub-step (inside cells only); time_step(), the largest safe dt
//   invariants  sum of phi changes only through open domain-boundary faces; a bounded scheme
//               keeps 0 <= phi <= Phi for cfl <= 1 (the guard records its largest round-off clip)
//
// On any Grid (1-D column, 2-D x-z plane with embedded walls, periodic axes) the sub-step is
// split over the axes (eq. 65, Lie splitting x, then y, then z; docs/assumptions.md G1): along
// each axis that has coefficients a_k, eq. (64) with the interface fluxes of face_fluxes.hpp.
// First-order schemes take one forward-Euler stage per axis. modified-godunov-2 takes the
// three-stage second-order strong-stability-preserving Runge-Kutta method SSP-RK(3,2)
// (Ketcheson 2008): three Euler stages of dt/2 and the average (u(0) + 2 u(3))/3, so it keeps
// every bound an Euler stage of dt/2 keeps (SSP coefficient 2).
//
// Time step: dt = cfl * dt_max with
//     first order:       dt_max = min over axes k of 1 / (max|a_k|/h_k + 2 D/h_k^2)
//     modified-godunov-2 dt_max = min over axes k of 2 / (2 max|a_k|/h_k + 2 D/h_k^2)
// the largest steps for which the modified schemes keep 0 <= phi <= Phi (the reconstructed
// update is an average of first-order updates at twice the step, hence the 2 in front of
// max|a_k|; docs/sect2.2_segregation.md "Bounds"). So cfl <= 1 is safe for every scheme, and
// cfl > 1 is rejected.
//
// Round-off guard, after each axis (docs/assumptions.md G5):
//  - underflow floor: above a pure-large layer phi decays geometrically and would sink into the
//    subnormal range, where arithmetic is ~100 times slower; |phi| < kUnderflowFloor is set to 0
//    (the amount removed is below 1e-200 per cell);
//  - for the modified schemes, whose update keeps 0 <= phi <= Phi exactly in real arithmetic,
//    phi is clipped to [0, Phi], which removes the last-bit rounding (-1e-33, Phi + 1 ulp) so
//    the bounds hold exactly in floating point. The largest clip is recorded
//    (largest_correction) so a run can prove it was round-off and not a broken scheme.
#pragma once

#include "run/state_io.hpp"
#include "segregation/frozen_fields.hpp"
#include "segregation/scheme.hpp"

#include <functional>
#include <vector>

namespace granseg {

/// Stages of the SSP-RK(3,2) method of modified-godunov-2.
constexpr int kSspStages = 3;

/// Values of phi below this magnitude are set to 0 after each axis (see above).
constexpr double kUnderflowFloor = 1e-200;

struct SegregationOptions {
    SegregationScheme scheme = SegregationScheme::modified_godunov;
    Limiter limiter = Limiter::mc;  // modified-godunov-2 only
    double cfl = 0.9;               // 0 < cfl <= 1
};

class SegregationSolver {
public:
    /// Throws InputError (one line) if options.cfl is outside (0, 1].
    SegregationSolver(Grid grid, SegregationOptions options);

    /// cfl * dt_max (see above); +infinity if no coefficient and no diffusion is non-zero.
    /// Checks the fields first (check_frozen_fields).
    double time_step(const FrozenFields& fields) const;

    /// One sub-step of length dt (eq. 52b), split over the axes; phi changes in inside cells only.
    void step(const FrozenFields& fields, double dt, std::vector<double>& phi);

    /// One step of a run from t to `duration`: of length min(dt_max, duration - t), dt_max =
    /// time_step(fields); t moves on by it, to `duration` itself on the last step. Returns the
    /// step's length.
    double step_towards(const FrozenFields& fields, double dt_max, double duration, double& t, std::vector<double>& phi);

    /// Steps of length time_step(fields) (the last one shortened) until `duration` has passed;
    /// calls after_step(t, dt) after each step if given. Returns the number of steps.
    long advance(const FrozenFields& fields, double duration, std::vector<double>& phi,
                 const std::function<void(double t, double dt)>& after_step = {});

    const Grid& grid() const { return grid_; }
    const SegregationOptions& options() const { return options_; }
    /// Inside-cell updates done so far (one per cell, axis and Runge-Kutta stage).
    long long cell_updates() const { return cell_updates_; }
    /// Largest amount the round-off guard moved phi back into [0, Phi] so far (0 for the
    /// classic schemes, which are not clipped).
    double largest_correction() const { return largest_correction_; }

private:
    /// Underflow floor and, for the modified schemes, the clip to [0, Phi] (see above).
    void round_off_guard(const std::vector<double>& Phi, std::vector<double>& phi);
    /// The interface fluxes of the scheme along `axis` for the state phi (counts the updates).
    void face_fluxes(const FrozenFields& fields, int axis, const std::vector<double>& phi, std::vector<double>& F);

    Grid grid_;
    SegregationOptions options_;
    std::size_t inside_cells_ = 0;
    long long cell_updates_ = 0;
    double largest_correction_ = 0.0;
    std::vector<double> F_, F_sum_, at_lower_, at_upper_, stage_;  // work space

public:
    /// Saves or restores (run/state_io.hpp) the counts a run reports.
    void checkpoint(StateIO& io) { io("cell_updates", cell_updates_)("largest_correction", largest_correction_); }
};

}  // namespace granseg
