// The manufactured solution of the full flow system (eqs. 8, 9, 14 with the closures of eqs.
// 15-20), in the rotating frame with gravity, walls on all sides, and one run of the flow solver
// against it: shared by verify_flow_order (orders of accuracy) and bench_flow_work (error
// against CPU time).
//
// Manufactured fields on the square [0, L]^2 turning at Omega = 20 rad/s about its centre, with
// a(t) = 1 + sin(2 pi t/tau)/2:
//   Phi = Phi0 + dPhi cos(pi x/L) cos(pi z/L) a(t)           (yield regime: Phi_co < Phi < Phi_rcp)
//   u_x =  U sin(pi x/L) sin(2 pi z/L) a(t),  u_z = -U sin(2 pi x/L) sin(pi z/L) a(t)  (0 on walls)
//   T   = T0 (1 + dT cos(pi x/L) cos(pi z/L) a(t))         (zero normal gradient on walls)
// The source terms that make them exact solutions are the residuals of the PDEs,
//   S = d_t U + div F(U) - (viscous, heating, conduction, dissipation, gravity, Coriolis,
//       centrifugal terms),
// evaluated with the closures at the exact state and fourth-order central differences of the
// exact fields (step 1e-4 m, relative error ~1e-9), at 35 time points and interpolated in time by
// Catmull-Rom cubics (error ~1e-7); these errors are far below the discretisation errors.
#pragma once

#include "closures/material.hpp"
#include "core/grid.hpp"
#include "flow/fields/flow_settings.hpp"
#include "flow/flow_solver.hpp"
#include "harness/program.hpp"

#include <array>
#include <vector>

namespace granseg::verify {

/// Side L of the manufactured solution's square (m) and the time t_end at which it is compared (s).
inline constexpr double kManufacturedSide = 0.05, kManufacturedEnd = 0.05;

struct ManufacturedRun {
    double error_Phi = 0.0, error_u = 0.0, error_T = 0.0;  // volume-averaged |numerical - exact| at t_end
    std::vector<double> Phi, u_x, u_z, T;                  // the numerical fields at t_end, per cell
    Timing time;                                           // of the solver's time loop alone (the sources are set up before)
    long steps = 0;
    FlowCounters work;       // the semi-implicit step's pressure solves, Newton steps, CG iterations
    double smoothing = 0.0;  // semi-implicit: mean |face smoothing velocity| over the interior faces of the last step (m/s)
};

/// The problem on n x n cells: its source terms at the time nodes, computed once (they cost
/// more than a run at the coarser sizes), for the default phi_hat of FlowSettings.
class ManufacturedFlow {
public:
    ManufacturedFlow(const Material& m, int n);

    /// Runs the flow solver with `settings` (default phi_hat) from the exact state at t = 0 to
    /// t_end and compares with the exact fields there (|u| is the length of the velocity error).
    ManufacturedRun run(const FlowSettings& settings) const;

private:
    Material m_;
    int n_;
    Grid grid_;
    std::vector<std::array<double, 5>> nodes_;  // sources, [time node][cell]
};

}  // namespace granseg::verify
