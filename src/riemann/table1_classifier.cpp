#include "riemann/table1_classifier.hpp"

#include "riemann/flux_curves.hpp"

namespace granseg {

namespace {

/// Table 1 for convex fluxes (a_L, a_R > 0), in the flux form of the header.
int convex_case(const FluxSide& L, const FluxSide& R) {
    const double f_L = segregation_flux(L.phi, L.Phi, L.a);  // f(Q_L)
    const double f_R = segregation_flux(R.phi, R.Phi, R.a);  // f(Q_R)
    const double fL_min = flux_extremum(L.Phi, L.a);         // f(Q*), Q* = (Phi_L/2, Phi_L)
    const double fR_min = flux_extremum(R.Phi, R.a);
    const bool R_left = R.phi < gamma_phi(R.Phi);
    if (L.phi <= gamma_phi(L.Phi)) {
        if (f_R < fL_min) return 3;            // C
        if (R_left) return f_R > f_L ? 1 : 2;  // A, B
        if (fR_min <= fL_min) return 4;        // D
        return fR_min < f_L ? 5 : 6;           // E, F
    }
    if (f_R < f_L) return 8;       // H
    if (R_left) return 7;          // G
    return fR_min < f_L ? 9 : 10;  // I, J
}

Table1Case make_case(int number, bool mirrored) { return {number, static_cast<char>('A' + number - 1), mirrored}; }

}  // namespace

Table1Case classify_table1(const FluxSide& L, const FluxSide& R) {
    if (L.a > 0.0 && R.a > 0.0) return make_case(convex_case(L, R), false);
    if (L.a < 0.0 && R.a < 0.0) return make_case(convex_case({R.phi, R.Phi, -R.a}, {L.phi, L.Phi, -L.a}), true);
    return {};
}

}  // namespace granseg
