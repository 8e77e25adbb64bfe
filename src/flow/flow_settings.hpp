// Numerical parameters of the flow solver, the optional source terms, and the wall velocities
// (docs/flow_solver.md Sect. 6; every default is justified in docs/assumptions.md F1-F8).
#pragma once

#include "flow/frame.hpp"

#include <array>
#include <functional>

namespace granseg {

/// Numerical parameters of the flow solver; each default is justified in docs/assumptions.md (F*).
struct FlowSettings {
    double cfl = 0.9;           // dt * sum_axis (|u_axis| + c)/h_axis <= cfl (first-order unsplit stability)
    double T_floor = 1e-12;     // m^2/s^2, lower bound of T (finite eta, lambda ~ T^(-1/2))
    double Phi_vacuum = 1e-12;  // cells with Phi <= this are empty: u = 0, T = T_floor
    double dt_min = 1e-9;       // s; a smaller step stops the run with InvariantError
    double dt_max = 1e-3;       // s
    double phi_hat = 0.5;       // small-particle share used for Phi_rcp, Phi_co when no phi field is set
};

/// Sources added to the conserved variables (manufactured solutions): called per inside cell with
/// time and cell centre, fills rates for (Phi, Phi u_x, Phi u_y, Phi u_z, Phi T).
using FlowSource = std::function<void(double t, double x, double y, double z, double rates[5])>;

/// Velocity of the domain-boundary walls: [axis][side] (side 0 lower, 1 upper), tangential.
using WallVelocities = std::array<std::array<Vec3, 2>, 3>;

}  // namespace granseg
