// The equation of state of eqs. (15)-(19) solved for the volume fraction: Phi(p; T) with
// p(Phi) = g(Phi) (Phi T + Theta(Phi - Phi_co) T0 (Phi - Phi_co)), g = (1 - Phi/Phi_rcp)^(-beta)
// (closures/closures.hpp, assumption A1).
//
//   solves      p(Phi; T) = p for Phi
//   inputs      Material, p, T > 0, Phi_rcp, Phi_co, a guess (the cell's Phi)
//   outputs     Phi, dPhi/dp, the closure evaluations it took
//   invariants  0 <= Phi < Phi_rcp for p >= 0; Phi(p) increasing and concave
//
// p(Phi) is increasing and convex on [0, Phi_rcp) (g is increasing and convex, and the yield term
// switches on with a jump of the slope), so its inverse Phi(p) is increasing and concave, maps
// [0, inf) onto [0, Phi_rcp), and never reaches Phi_rcp: the pressure-implicit step solves for p
// and takes Phi = Phi(p) (docs/flow_solver.md Sect. 2, pressure_solve). Below p = 0 the inverse is continued by
// its tangent at 0, Phi = p/T (slope 1/c^2 = 1/T at Phi = 0), which keeps it concave and smooth
// for Newton's method.
//
// For the power law with beta = 1 (the default), p (1 - Phi/Phi_rcp) = Phi T + T0 (Phi - Phi_co)^+
// is linear in Phi and the inverse has a closed form; other laws are inverted by a safeguarded
// Newton iteration on p(Phi), started at a guess (the cell's Phi before the step), which takes a
// few closure evaluations per call (docs/flow_solver_choices.md, "Cost of a step").
#pragma once

#include "closures/closures.hpp"

#include <algorithm>
#include <cmath>

namespace granseg {

/// Phi(p) and dPhi/dp at one pressure, and how many closure evaluations that took (0: closed form).
struct VolumeAtPressure {
    double Phi, slope;
    int evaluations = 0;
};

/// Phi(p; T) (see the header comment) at the packing limits Phi_rcp, Phi_co, with dPhi/dp;
/// `Phi_guess` in (0, Phi_rcp) starts the iteration of the laws without a closed form (any other
/// value: start near Phi_rcp). Preconditions: T > 0, 0 < Phi_co < Phi_rcp.
inline VolumeAtPressure volume_at_pressure(const Material& m, double p, double T, double Phi_rcp, double Phi_co,
                                           double Phi_guess = 0.0) {
    if (p <= 0.0) return {p / T, 1.0 / T};
    const bool power_one = m.g_law == CompressibilityLaw::power && m.beta == 1.0;
    if (power_one) {
        const double p_co = Phi_co * T / (1.0 - Phi_co / Phi_rcp);  // p(Phi_co)
        const double D = T + p / Phi_rcp;
        if (p <= p_co) return {p / D, T / (D * D)};
        const double Dy = D + m.T0;
        return {(p + m.T0 * Phi_co) / Dy, (T + m.T0 * (1.0 - Phi_co / Phi_rcp)) / (Dy * Dy)};
    }
    // Newton on q(Phi) = p(Phi) - p: q is convex and increasing, so iterates starting where q >= 0
    // decrease monotonically to the root, and a step from below the root lands above it (or,
    // beyond the bracket, bisection takes over); bisection guards the bracket.
    const bool guessed = Phi_guess > 0.0 && Phi_guess < Phi_rcp;
    double lo = 0.0, hi = Phi_rcp, Phi = guessed ? Phi_guess : Phi_rcp * (1.0 - 1e-3);
    int evaluations = 0;
    while (evaluations < 200) {
        ++evaluations;
        const ClosureValues v = evaluate_closures_at(m, Phi, T, Phi_rcp, Phi_co);
        const double q = v.p - p;
        (q > 0.0 ? hi : lo) = Phi;
        if (q == 0.0 || hi - lo <= 4e-16 * hi) break;
        // Converged when Newton's own step is below round-off. Tested before the bracket: such a
        // step can round onto the bracket's end (next == hi), and bisecting then would throw away
        // the converged iterate for ~50 halvings back to it.
        const double next = Phi - q / v.c2;
        if (std::fabs(next - Phi) <= 2e-16 * Phi) {
            Phi = next;
            break;
        }
        Phi = next > lo && next < hi ? next : 0.5 * (lo + hi);
    }
    return {Phi, 1.0 / evaluate_closures_at(m, Phi, T, Phi_rcp, Phi_co).c2, evaluations + 1};  // + the slope's
}

}  // namespace granseg
