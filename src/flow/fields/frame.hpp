// The frame of reference of the flow solver (Sect. 2.1, eq. 9 body force F = Phi g, and the
// rotating drum of Sect. 4.2): gravity, an optional rotation about an axis along y, and the
// potential psi whose differences the hydrostatic reconstruction uses.
//
//   solves      nothing: gravity and the lab-frame transforms at time t
//   inputs      |g|, tilt, omega, the rotation axis (x_c, z_c)
//   outputs     g(t), positions and velocities in the lab frame
//   invariants  |g(t)| = |g|; the transforms are rotations (lengths are kept)
//
// Conventions (docs/flow_solver.md): the x-z plane is plotted with x to the right and z up, so
// the y axis (the drum axis) points into the page. `omega` > 0 turns the drum counter-clockwise
// as plotted. The solver works in the frame turning with the drum, in which
//   gravity turns at -omega:      g(t) = R(-omega t) g0,  R(a) the counter-clockwise rotation by a,
//   Coriolis acceleration:        -2 Omega x u = 2 omega (u_z, -u_x)   (in x-z components),
//   centrifugal acceleration:     omega^2 (x - x_c, z - z_c).
// g0 = |g| (sin(tilt), 0, -cos(tilt)): tilt > 0 tips gravity towards +x (an inclined plane whose
// downhill direction is +x). Units: m, s.
#pragma once

#include <array>
#include <cmath>

namespace granseg {

using Vec3 = std::array<double, 3>;

struct Frame {
    double gravity = 9.81;  // |g|, m/s^2
    double tilt = 0.0;      // rad, angle of g0 from -z towards +x
    double omega = 0.0;     // rad/s, rotation rate of the frame (counter-clockwise as plotted)
    double x_c = 0.0;       // rotation axis: the line (x_c, y, z_c)
    double z_c = 0.0;

    /// Gravity at time t in this frame: R(-omega t) g0 in the x-z plane.
    Vec3 gravity_at(double t) const {
        const double gx0 = gravity * std::sin(tilt), gz0 = -gravity * std::cos(tilt);
        const double a = -omega * t, ca = std::cos(a), sa = std::sin(a);
        return {ca * gx0 - sa * gz0, 0.0, sa * gx0 + ca * gz0};
    }

    /// Position of the frame point (x, z) in the inertial (lab) frame at time t: R(omega t) about the axis.
    std::array<double, 2> to_lab_position(double t, double x, double z) const {
        const double a = omega * t, ca = std::cos(a), sa = std::sin(a), rx = x - x_c, rz = z - z_c;
        return {x_c + ca * rx - sa * rz, z_c + sa * rx + ca * rz};
    }

    /// Lab-frame velocity of a particle at frame point (x, z) with frame velocity (u_x, u_z):
    /// R(omega t) (u + Omega x r), where Omega x r = omega (-(z - z_c), x - x_c).
    std::array<double, 2> to_lab_velocity(double t, double x, double z, double u_x, double u_z) const {
        const double a = omega * t, ca = std::cos(a), sa = std::sin(a);
        const double vx = u_x - omega * (z - z_c), vz = u_z + omega * (x - x_c);
        return {ca * vx - sa * vz, sa * vx + ca * vz};
    }
};

}  // namespace granseg
