// Exact solutions of the Gray-Thornton segregation equation, the constant-Phi, constant-T limit
// of eq. (47): with psi = phi/Phi and q = S sqrt(T),
//     d_t psi - d_z(q psi (1 - psi)) = 0 on [0, 1], zero flux at z = 0 and z = 1
// (docs/paper_notes.md, section 4; Gray & Thornton 2005, Gray, Shearer & Thornton 2006,
// Gray & Chugunov 2006). They are built from the wave structure (shock speeds from the
// Rankine-Hugoniot condition, fans from the characteristic speed q(2 psi - 1)), not from any
// code under test, and are piecewise linear in z, so their cell averages are exact.
#pragma once

#include <functional>
#include <vector>

namespace granseg::verify {

/// A profile psi(z) that is linear between consecutive breakpoints.
struct PiecewiseLinear {
    std::function<double(double z)> value;
    std::vector<double> breaks;  // every z where psi or its slope jumps
};

/// Homogeneous batch psi(z, 0) = psi0: pure small below z = q psi0 t, pure large above
/// z = 1 - q (1 - psi0) t, psi0 between; complete segregation at z = psi0 from t = 1/q on.
PiecewiseLinear homogeneous_batch(double psi0, double q, double t);

/// Normally graded batch, small on top (psi = 0 below z0, 1 above): a centred fan
/// psi = (1 + (z - z0)/(q t))/2, then the shocks z_l = (sqrt(qt) - sqrt(z0))^2 (after t = z0/q)
/// and z_u = 1 - (sqrt(qt) - sqrt(1 - z0))^2 (after t = (1 - z0)/q); valid until they meet at
/// t = (1 + 2 sqrt(z0 (1 - z0)))/q (InputError after that).
PiecewiseLinear graded_batch(double z0, double q, double t);

/// Averages of the profile over `cells` equal cells of [0, length] (midpoint rule on each linear
/// piece: exact).
std::vector<double> cell_averages(const PiecewiseLinear& profile, int cells, double length = 1.0);

/// Steady state with diffusive remixing D (Gray & Chugunov): zero total flux
/// -q psi (1 - psi) - D psi' = 0 with mean psi0 gives psi = 1/(1 + C exp(P z)), P = q/D,
/// C = (exp(-P psi0) - exp(-P))/(1 - exp(-P psi0)). Returns its exact cell averages (from the
/// antiderivative z - ln(1 + C exp(P z))/P).
std::vector<double> logistic_cell_averages(double P, double psi0, int cells);

/// Smooth periodic data psi(z, 0) = 1/2 + A sin(2 pi z) on [0, 1) before the first shock forms
/// (t < 1/(4 pi q A)): psi is constant along the characteristics z = xi + q (2 psi0(xi) - 1) t,
/// solved for xi by Newton's method; cell averages by 4-point Gauss-Legendre quadrature.
std::vector<double> smooth_periodic_averages(double A, double q, double t, int cells);

/// Integral of f over [a, b] by 4-point Gauss-Legendre quadrature (exact for degree <= 7).
double gauss_legendre4(const std::function<double(double)>& f, double a, double b);

/// h * sum |u - v| (the discrete L1 norm of the difference on cells of width h).
double l1_distance(const std::vector<double>& u, const std::vector<double>& v, double h);

/// Observed order log(e_coarse/e_fine)/log(refinement).
double observed_order(double e_coarse, double e_fine, double refinement = 2.0);

}  // namespace granseg::verify
