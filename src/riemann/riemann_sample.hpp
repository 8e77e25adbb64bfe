// Sampling the exact Riemann solution (riemann_solver.hpp) at xi = z/t, Toro's SAMPLE step:
// walk the waves from the left until the first one whose speeds lie above xi.
//
//   solves      nothing new: evaluates the self-similar solution of riemann_solver.hpp at xi = z/t
//   inputs      a RiemannSolution and xi
//   outputs     phi(xi), Phi(xi), a(xi); the xi range that shows every wave
//   invariants  phi(xi) = Q_L left of every wave, Q_R right of them, continuous across a fan
#pragma once

#include "riemann/riemann_solver.hpp"

namespace granseg {

/// phi(xi) of the self-similar solution. Inside a rarefaction lambda_1(phi) = xi, i.e.
/// phi = (Phi/2)(1 + xi/a) (eq. 55). At xi = 0 it returns the right trace phi_plus (the standing
/// wave is taken to sit at 0-); at a shock speed, the state behind (right of) the shock.
double sample_phi(const RiemannSolution& s, double xi);

/// Phi(xi) = Phi_L for xi < 0 and Phi_R for xi >= 0 (eq. 52b: Phi does not move).
double sample_Phi(const RiemannSolution& s, double xi);

/// The flux coefficient a(xi), a_L for xi < 0 and a_R for xi >= 0.
double sample_a(const RiemannSolution& s, double xi);

/// A range [-xi_max, xi_max] holding every wave: 1.25 max(|a_L|, |a_R|) (|lambda_1| <= |a|), or 1.
double sample_range(const RiemannSolution& s);

}  // namespace granseg
