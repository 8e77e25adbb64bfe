// A layer on a rough inclined plane (verify_flow_incline; docs/flow_solver.md Sect. 3): a column
// of the substitute material 1 cm deep in a 2 cm domain, periodic along the slope, started in
// linear shear at 20 1/s with T from eq. (45); its run, the solver's critical angle by bisection,
// and the comparison of the profiles at that angle with the boundary-value solution (T uniform,
// u = mu sqrt(T) z/eta0, Phi lithostatic for the simulated T(z), GSL odeiv2). Shared by
// verify_flow_incline and bench_flow_work.
#pragma once

#include "closures/material.hpp"
#include "flow/fields/flow_settings.hpp"
#include "flow/flow_solver.hpp"
#include "harness/program.hpp"
#include "run/output.hpp"

#include <vector>

namespace granseg::verify {

/// Domain height and layer depth (m), gravity (m/s^2); the kinetic energy is compared between
/// the two times of kInclineWindow (s).
inline constexpr double kInclineDomain = 0.02, kInclineDepth = 0.01, kInclineGravity = 9.81;
inline constexpr double kInclineWindow[2] = {0.5, 1.5};

struct InclineRun {
    double kinetic[2] = {0.0, 0.0};    // at kInclineWindow[0], kInclineWindow[1] (or t_end if earlier)
    std::vector<double> z, Phi, u, T;  // at t_end, per cell
    double T_max = 0.0;
    Timing time;  // of the solver's time loop
    long steps = 0;
    FlowCounters work;  // the semi-implicit step's pressure solves, Newton steps, CG iterations
};

/// The layer at slope theta_deg (degrees) on nz cells, run to t_end (s) with `settings`.
InclineRun run_incline(const Material& m, const FlowSettings& settings, double theta_deg, int nz, double t_end);

/// The solver's critical angle (degrees): bisection on [20, 24] on the sign of the kinetic-energy
/// trend over kInclineWindow, to 0.002 degrees; `time` (if given) receives the time loops' sum.
double critical_angle(const Material& m, const FlowSettings& settings, int nz, Timing* time = nullptr);

/// A bed cell: one holding at least half of Phi_co (the surface cell and dust are left out).
bool in_bed(const Material& m, double Phi);

struct InclineProfileErrors {
    double T_spread = 0.0;  // (max - min)/max of T over bed cells
    double u = 0.0;         // max |u - u_bvp| / u_bvp(depth) over bed cells below the surface cell
    double Phi = 0.0;       // max |Phi - Phi_bvp(GSL)| over the same cells
};

/// Compares the profiles of `r` (a run at theta_deg) with the boundary-value solution; appends
/// rows (nz, z, Phi, Phi_bvp, u_x, u_bvp, T, T_bvp) and a gnuplot index break to `rows` if given.
InclineProfileErrors incline_profile_errors(const Material& m, const InclineRun& r, double theta_deg, DataTable* rows = nullptr);

}  // namespace granseg::verify
