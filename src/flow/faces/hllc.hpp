// The convective flux of eqs. (8), (9), (14) across one face: an HLLC approximate Riemann solver
// (Toro, "Riemann Solvers and Numerical Methods for Fluid Dynamics", 3rd ed., Sect. 10.4) for the
// system in the conserved variables (Phi, Phi u, Phi T), with a hydrostatic reconstruction of the
// face states (Audusse, Bouchut, Bristeau, Klein & Perthame, SIAM J. Sci. Comput. 25, 2004).
//
//   solves      the Riemann problem of eqs. (8), (9), (14) at one face, approximately (HLLC)
//   inputs      the two face states (FaceState), hydrostatically reconstructed
//   outputs     FaceFlux: fluxes of mass, momentum and Phi T, and p*
//   invariants  no flux between empty states; no mass flux against a mirror state (a wall); a
//               contact at rest between equal pressures stays at rest; 0 <= Phi' <= Phi
//
// The system has no p div u work term in eq. (14), so T is carried like the tangential
// velocities: the waves are u_n - c, u_n (a contact carrying T and u_t), u_n + c with
// c^2 = dp/dPhi at fixed T (closures.hpp). HLLC resolves the contact, so a layer at rest with
// equal pressure on both sides has zero mass flux whatever T does across it, and every flux of a
// passive quantity (u_t, T) is the mass flux times the upwind value: T and u_t then stay convex
// combinations of old values whenever the cell's outflow does not exceed its mass.
//
// Orientation: L is the cell below the face along the axis, R the cell above; u_n is the
// velocity component along the axis. Everything is per intrinsic density rho*.
#pragma once

#include <algorithm>
#include <cmath>

namespace granseg {

/// One side of a face: volume fraction, normal and two tangential velocities, temperature,
/// pressure and sound speed.
struct FaceState {
    double Phi, u_n, u_t1, u_t2, T, p, c;
};

/// Fluxes across the face in the direction of the axis: mass Phi u_n, normal momentum
/// Phi u_n^2 + p, tangential momenta, Phi T u_n; and the pressure p* at the face.
struct FaceFlux {
    double mass, mom_n, mom_t1, mom_t2, energy, p_star;
};

/// HLLC flux (Toro eqs. 10.37-10.40) with Davis wave speeds S_L = min(u_L - c_L, u_R - c_R),
/// S_R = max(u_L + c_L, u_R + c_R). The contact speed S* is kept inside [S_L, S_R], so both star
/// volume fractions are >= 0. Two empty sides give zero flux. Written with selects instead of
/// branches so that loops over faces vectorise.
inline __attribute__((always_inline)) FaceFlux hllc_flux(const FaceState& L, const FaceState& R) {
    const double S_L = std::min(L.u_n - L.c, R.u_n - R.c);
    const double S_R = std::max(L.u_n + L.c, R.u_n + R.c);
    const double d_L = L.Phi * (S_L - L.u_n);  // <= 0: mass flux relative to the left wave
    const double d_R = R.Phi * (S_R - R.u_n);  // >= 0
    const double den = d_L - d_R;
    const bool empty = den == 0.0;
    double S_star = (R.p - L.p + L.u_n * d_L - R.u_n * d_R) / (empty ? 1.0 : den);  // Toro eq. (10.37)
    S_star = std::min(std::max(S_star, S_L), S_R);

    // The star state on the side of the contact that the face sees:
    // Phi* = Phi_K (S_K - u_K)/(S_K - S*), p* = p_K + d_K (S* - u_K), K = L if S* >= 0, else R.
    const bool left = S_star >= 0.0;
    const double S_K = left ? S_L : S_R, d_K = left ? d_L : d_R, u_K = left ? L.u_n : R.u_n;
    const double gap = S_K - S_star;
    double mass = d_K / (gap != 0.0 ? gap : 1.0) * S_star;
    double p_star = (left ? L.p : R.p) + d_K * (S_star - u_K);
    double mom = mass * S_star + p_star;
    double t1 = left ? L.u_t1 : R.u_t1, t2 = left ? L.u_t2 : R.u_t2, T = left ? L.T : R.T;
    // Supersonic faces take the physical flux of the upwind state.
    const bool all_right = S_L >= 0.0, all_left = S_R <= 0.0, supersonic = all_right || all_left;
    const double Phi_K = all_right ? L.Phi : R.Phi, u_n = all_right ? L.u_n : R.u_n, p_K = all_right ? L.p : R.p;
    mass = supersonic ? Phi_K * u_n : mass;
    p_star = supersonic ? p_K : p_star;
    mom = supersonic ? mass * u_n + p_K : mom;
    t1 = supersonic ? (all_right ? L.u_t1 : R.u_t1) : t1;
    t2 = supersonic ? (all_right ? L.u_t2 : R.u_t2) : t2;
    T = supersonic ? (all_right ? L.T : R.T) : T;
    mass = empty ? 0.0 : mass;
    p_star = empty ? 0.5 * (L.p + R.p) : p_star;
    mom = empty ? p_star : mom;
    return {mass, mom, mass * t1, mass * t2, mass * T, p_star};
}

/// The mirror image of a state across a wall (u_n -> -u_n). The HLLC flux between a state and its
/// mirror has S* = 0 exactly, so zero mass, tangential momentum and energy fluxes, and the wall
/// pressure p* = p + Phi u_n (|u_n| + c + u_n) for u_n towards the wall.
inline FaceState mirror(FaceState s) {
    s.u_n = -s.u_n;
    return s;
}

/// Hydrostatic reconstruction of a cell state at one of its faces (the face potential is the
/// mean of the two cells' potentials psi, gravity and centrifugal, m^2/s^2), d_psi = psi_face -
/// psi_cell:
///   uphill,   d_psi > 0: p' = max(p - Phi d_psi, carry), Phi' = max(0, Phi - max(0, p - p')/c^2)
///             (the linearised equation of state; p being convex in Phi, Phi' never exceeds the
///             exact inverse, so 0 <= Phi' <= Phi);
///   downhill, d_psi < 0: p' = p - Phi d_psi + load, Phi' = Phi.
/// `load` is the weight per area the cell cannot pass on through its uphill face because its own
/// pressure is too small (an "unsupported" cell: a partly filled surface cell, dust), plus what
/// rests on it (`carry`, the pressure arriving at its uphill face, which such a cell passes on);
/// see unsupported_loads() in flow/loads.cpp. Where p' exceeds the cell's own p/Phi scale the sound speed
/// is raised to c'^2 = max(c^2, p'/Phi') so that the HLLC waves can release p' into vacuum.
/// Returns p - p', which the cell adds to the face's normal momentum flux. Then every cell feels
/// its full weight Phi (psi_face,up - psi_face,down)/h, and a state whose face pressures agree
/// across every face and whose velocity vanishes has zero net force (well balanced): its
/// discrete equilibrium is p_k - p_(k+1) = (Phi_k + Phi_(k+1)) |g| h / 2, the trapezoidal rule,
/// and a partly filled top cell rests on the cell below with its full weight.
inline __attribute__((always_inline)) double hydrostatic_reconstruction(FaceState& s, double d_psi, double load, double carry) {
    const double p = s.p, Phi = s.Phi, c2 = s.c * s.c;
    const double p_up = std::max(p - Phi * d_psi, carry);
    const double Phi_up = c2 > 0.0 ? std::max(0.0, Phi - std::max(0.0, p - p_up) / (c2 > 0.0 ? c2 : 1.0)) : 0.0;
    const double p_down = p - Phi * d_psi + load;
    const bool up = d_psi > 0.0, down = d_psi < 0.0 && Phi > 0.0;  // selects, so face loops vectorise
    const double p_face = up ? p_up : down ? p_down : p, Phi_face = up ? Phi_up : Phi;
    s.c = std::sqrt(std::max(c2, p_face / (Phi_face > 0.0 ? Phi_face : 1.0)));
    s.p = p_face;
    s.Phi = Phi_face;
    return p - s.p;
}

/// The weight per area a cell cannot pass on through its uphill face (rise: its potential rise
/// there): max(0, Phi rise - p).
inline double unsupported_load(double Phi, double p, double rise) { return std::max(0.0, Phi * rise - p); }

}  // namespace granseg
