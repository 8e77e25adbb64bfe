// A prescribed rolling-regime flow in the drum of Sect. 4.2, for scenes that skip the flow solver.
//
//   solves      nothing over time: a prescribed steady rolling flow (assumptions K1-K3)
//   inputs      RollingDrumParameters: diameter, fill fraction, rotation rate, repose angle, layer
//   outputs     the stream function, u, u_rel, grad u_rel; on a grid the face mass fluxes M
//   invariants  psi = 0 on the wall and on the free surface: no flux through either; the discrete
//               divergence of M vanishes in every bed cell (verify_kinematic_flow)
//
// Model (docs/assumptions.md K1-K3; after Khakhar, McCarthy, Shinbrot & Ottino, Phys. Fluids 9,
// 31 (1997), and Gray, J. Fluid Mech. 441, 1 (2001)): a drum of radius R turning at Omega about
// its axis y, filled at rest to the height fill_fraction * diameter. In the rolling regime the
// free surface is the flat chord at distance d = (2 fill_fraction - 1) R from the centre, tilted
// by the dynamic angle of repose beta (same filled area as at rest). Below a thin flowing layer
// the bed turns with the drum; in the layer of thickness delta(s) = delta0 sqrt(1 - s^2/L^2)
// (L = sqrt(R^2 - d^2) the half chord, s the downslope distance from the middle of the surface)
// the material runs down the slope with Khakhar's linear velocity profile.
//
// FRAME. Everything is given in the INERTIAL (lab) frame: drum centre at the origin, x to the
// right, z up, gravity -z, Omega > 0 counter-clockwise as plotted. There the field is steady (the
// surface and the layer stay put while the material circulates) and the drum wall, a circle, is
// fixed: these are the coordinates of the pictures of Fig. 7, with no back-transformation. The
// paper solves in the frame turning with the drum; its velocity is the relative velocity
// u_rel = u - Omega x x (zero in the solid-body core), which relative_velocity() returns in
// inertial components; at time t its drum-frame components are R(-Omega t) u_rel. The direction
// procedure (Sect. 2.3) and the shear rate of eqs. (43), (45) need u_rel and grad u_rel.
//
// Stream function (volume flux per unit depth, m^2/s), u_x = d psi/dz, u_z = -d psi/dx:
//   psi = psi_sb m(chi),  psi_sb = Omega (R^2 - x^2 - z^2)/2  (solid-body rotation, 0 on the wall),
//   chi = -n/delta(s)  (n: height above the surface), m(chi) = 2 chi - chi^2 in the layer, m = 1 below.
// psi = 0 on the wall and on the free surface, so no material crosses either; psi and u are
// continuous at the layer bottom (m'(1) = 0); the shear rate jumps there, as in Khakhar's model.
// Consequences (docs/sect2.3_direction.md, section 6): surface speed Omega (L^2 - s^2)/delta(s) =
// (Omega L^2/delta0) sqrt(1 - s^2/L^2) downslope, shear rate ~ Omega L^2/delta0^2 along the layer.
// Units: m, s; Omega in rad/s; psi in m^2/s.
#pragma once

#include "core/grid.hpp"

#include <Eigen/Core>

#include <array>
#include <vector>

namespace granseg {

/// The drum of Sect. 4.2 and the kinematic layer (defaults: docs/assumptions.md K2).
struct RollingDrumParameters {
    double diameter = 0.1;           // m
    double fill_fraction = 0.75;     // filled height at rest / diameter
    double rotation_rate = 0.1;      // revolutions per second; > 0 counter-clockwise as plotted
    double repose_angle = 25.0;      // degrees: slope beta of the free surface
    double layer_thickness = 0.008;  // m: delta0, the layer thickness at the middle of the surface
};

class RollingDrumFlow {
public:
    /// Throws InputError naming the parameter if one is out of range (0 < diameter,
    /// 0 < fill_fraction < 1, rotation_rate != 0, 0 <= repose_angle < 90, 0 < delta0 < min(L, R + d)).
    explicit RollingDrumFlow(const RollingDrumParameters& parameters);

    const RollingDrumParameters& parameters() const { return p_; }
    double radius() const { return R_; }
    double Omega() const { return Omega_; }                // signed angular velocity, rad/s
    double surface_distance() const { return d_; }         // d: distance of the surface from the centre, m
    double half_chord() const { return L_; }               // L: half length of the free surface, m
    const Eigen::Vector3d& tangent() const { return t_; }  // downslope unit tangent of the surface
    const Eigen::Vector3d& normal() const { return n_; }   // unit normal of the surface, out of the bed

    /// (s, n): downslope distance from the middle of the surface, height above the surface.
    std::array<double, 2> surface_coordinates(double x, double z) const;
    /// delta(s) = delta0 sqrt(1 - s^2/L^2) for |s| < L, else 0.
    double layer_depth(double s) const;
    /// Documented surface speed Omega (L^2 - s^2)/delta(s) (downslope; 0 for |s| >= L).
    double surface_speed(double s) const;
    /// Documented shear rate of the layer, Omega L^2/delta0^2 (leading order in delta0/L).
    double layer_shear_rate() const;

    bool in_drum(double x, double z) const;   // x^2 + z^2 < R^2
    bool in_bed(double x, double z) const;    // in the drum and n <= 0
    bool in_layer(double x, double z) const;  // in the bed and -delta(s) < n

    // The model at a point (x, z) of the bed; every function returns 0 outside the bed (no material).
    double stream_function(double x, double z) const;                      // psi, m^2/s
    Eigen::Vector3d velocity(double x, double z) const;                    // inertial u (u_y = 0)
    Eigen::Matrix3d velocity_gradient(double x, double z) const;           // grad u, (i, j) = du_i/dx_j
    Eigen::Vector3d relative_velocity(double x, double z) const;           // u - Omega x x
    Eigen::Matrix3d relative_velocity_gradient(double x, double z) const;  // grad u - grad(Omega x x)

private:
    struct StreamDerivatives;  // psi, its gradient and Hessian at a point (kinematic_flow.cpp)
    StreamDerivatives derivatives(double x, double z) const;

    RollingDrumParameters p_;
    double R_, Omega_, d_, L_, delta0_;
    Eigen::Vector3d t_, n_;
};

/// The kinematic flow on the Cartesian drum grid, ready for transport and for the direction.
struct RollingDrumFields {
    Grid grid;                                    // x-z plane, ny = 1, covering [-R, R]^2; inside = bed cells
    std::vector<unsigned char> in_drum;           // 1 where the cell centre is in the drum (bed or air)
    std::vector<unsigned char> in_layer;          // 1 where the cell centre is in the flowing layer
    std::array<std::vector<double>, 3> M;         // face mass fluxes Phi u.n, grid.face_index layout; M[1] empty
    std::array<std::vector<double>, 3> u;         // inertial velocity at cell centres (0 outside the bed)
    std::array<std::vector<double>, 3> u_rel;     // relative (drum-frame) velocity at cell centres
    std::array<std::vector<double>, 9> grad_rel;  // d u_rel_i / d x_j at cell centres, index 3 i + j
};

/// Samples `flow` on cells_per_diameter^2 cells with constant granular volume fraction Phi.
/// A cell belongs to the bed if its centre does (stair-stepped wall and surface). Phi psi is sampled
/// at the cell corners and set to its wall value 0 on every corner of a cell outside the bed (the
/// grid-boundary corners lie outside the drum, where psi = 0 too); the face fluxes are differences
/// of corner values (stream_function_mass_fluxes),
///   M_x(face) = (psi_top - psi_bottom)/h_z,   M_z(face) = -(psi_right - psi_left)/h_x,
/// so the discrete divergence of every cell cancels to round-off and every face next to the wall,
/// the free surface or the grid boundary carries exactly 0.
RollingDrumFields discretize(const RollingDrumFlow& flow, int cells_per_diameter, double Phi);

/// The vector of a per-component cell field at cell c.
inline Eigen::Vector3d cell_vector(const std::array<std::vector<double>, 3>& f, std::size_t c) {
    return {f[0][c], f[1][c], f[2][c]};
}

/// The tensor of a per-component cell field (index 3 i + j) at cell c.
inline Eigen::Matrix3d cell_tensor(const std::array<std::vector<double>, 9>& f, std::size_t c) {
    Eigen::Matrix3d m;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) m(i, j) = f[3 * i + j][c];
    return m;
}

}  // namespace granseg
