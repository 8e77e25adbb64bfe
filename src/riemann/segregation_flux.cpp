#include "riemann/segregation_flux.hpp"

#include <algorithm>
#include <cmath>

namespace granseg {

InterfaceStates mean_interface(const FluxSide& L, const FluxSide& R) { return {L, R, 0.5 * (L.Phi + R.Phi), 0.5 * (L.a + R.a)}; }

double modified_godunov_flux(const InterfaceStates& q) {
    const FluxSide &L = q.L, &R = q.R;
    const double theta_L = 0.5 * L.Phi, theta_R = 0.5 * R.Phi;  // extremum of f_L, f_R (on Gamma)
    if (L.a >= 0.0 && R.a >= 0.0) {
        const double f_up = segregation_flux(std::max(L.phi, theta_L), L.Phi, L.a);    // eq. (61)
        const double f_down = segregation_flux(std::min(R.phi, theta_R), R.Phi, R.a);  // eq. (62)
        return std::max(f_up, f_down);                                                 // eq. (63)
    }
    if (L.a <= 0.0 && R.a <= 0.0) {
        const double demand = segregation_flux(std::min(L.phi, theta_L), L.Phi, L.a);
        const double supply = segregation_flux(std::max(R.phi, theta_R), R.Phi, R.a);
        return std::min(demand, supply);
    }
    return 0.0;  // a_L a_R < 0: f_L and f_R have opposite signs on [0, Phi]
}

double classic_upwind_flux(const InterfaceStates& q) {
    const double phi_L = q.L.phi, phi_R = q.R.phi, Phi_face = q.Phi_face, a_face = q.a_face;
    const double f_L = segregation_flux(phi_L, Phi_face, a_face);
    const double f_R = segregation_flux(phi_R, Phi_face, a_face);
    // Rankine-Hugoniot speed (f_R - f_L)/(phi_R - phi_L) = a (phi_L + phi_R - Phi)/Phi for this
    // quadratic f; at phi_L = phi_R it is the characteristic speed.
    const double speed = Phi_face > 0.0 ? a_face * (phi_L + phi_R - Phi_face) : 0.0;
    return speed >= 0.0 ? f_L : f_R;
}

double classic_godunov_flux(const InterfaceStates& q) {
    const double phi_L = q.L.phi, phi_R = q.R.phi, Phi_face = q.Phi_face, a_face = q.a_face;
    const double f_L = segregation_flux(phi_L, Phi_face, a_face);
    const double f_R = segregation_flux(phi_R, Phi_face, a_face);
    const double theta = 0.5 * Phi_face;
    const double f_theta = segregation_flux(theta, Phi_face, a_face);  // min (a > 0) or max (a < 0)
    if (phi_L <= phi_R) {
        const bool inside = phi_L <= theta && theta <= phi_R && a_face > 0.0;
        return std::min({f_L, f_R, inside ? f_theta : f_L});
    }
    const bool inside = phi_R <= theta && theta <= phi_L && a_face < 0.0;
    return std::max({f_L, f_R, inside ? f_theta : f_L});
}

double rusanov_flux(const InterfaceStates& q) {
    const FluxSide &L = q.L, &R = q.R;
    const double alpha =
        std::max(std::fabs(segregation_speed(L.phi, L.Phi, L.a)), std::fabs(segregation_speed(R.phi, R.Phi, R.a)));  // (eq. 55)
    return 0.5 * (segregation_flux(L.phi, L.Phi, L.a) + segregation_flux(R.phi, R.Phi, R.a)) - 0.5 * alpha * (R.phi - L.phi);
}

}  // namespace granseg
