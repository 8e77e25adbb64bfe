// Closures of the Latz-Schmidt granular flow model (Sect. 2.1, eqs. 15-20).
//
//   solves      eqs. (15)-(20) at one state (algebraic: nothing over time)
//   inputs      the Material, Phi, phi_hat, T
//   outputs     ClosureValues: Phi_rcp, Phi_co, g, p_k, p_y, p, eta, lambda, eps, the dissipation, c^2
//   invariants  no 0/0 for any T >= 0; g -> 1 as Phi -> 0, g = +inf at Phi >= Phi_rcp (verify_closures)
//
// Symbols (docs/notation.md): Phi granular volume fraction, phi_hat = phi/Phi small-particle
// share, T granular temperature, g compressibility factor, p = p_k + p_y pressure, eta viscosity,
// lambda conductivity, eps dissipation rate. With s = Theta(Phi - Phi_co) the yield factor (eq. 20)
// is 1 + p_y/p_k = 1 + s T0 (Phi - Phi_co) / (Phi T), so the coefficients are written expanded:
//
//   eta    = eta0    g (Phi sqrt(T) + s T0 (Phi - Phi_co) / sqrt(T))
//   lambda = lambda0 g (Phi sqrt(T) + s T0 (Phi - Phi_co) / sqrt(T))
//   eps    = eps0    g (sqrt(T)     + s T0 (Phi - Phi_co) / (Phi sqrt(T)))
//   eps Phi T = eps0 g sqrt(T) (Phi T + s T0 (Phi - Phi_co))          (finite as T -> 0)
//
// No 0/0 appears: below Phi_co the yield terms are skipped, so everything vanishes with T.
// Above Phi_co, eta, lambda and eps grow like T^(-1/2) and are +inf at T = 0 (the flow solver keeps
// T above a floor); the dissipation eps Phi T still goes to 0 like sqrt(T).
// Preconditions: 0 <= Phi, T >= 0. For Phi >= Phi_rcp, g is +inf (the packing limit is a wall).
#pragma once

#include "closures/material.hpp"
#include "run/output.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace granseg {

/// The exponent b of g = (1 - Phi/Phi_rcp)^(-b) for the material's law (docs/assumptions.md A1).
/// A case per law and no default: a new law without its case draws -Wswitch at compile time and,
/// run anyway, throws instead of taking another law's exponent.
inline double compressibility_exponent(const Material& m, double Phi_rcp) {
    switch (m.g_law) {
        case CompressibilityLaw::power:
            return m.beta;
        case CompressibilityLaw::lun_savage:
            return 2.5 * Phi_rcp;
    }
    throw std::logic_error("compressibility_exponent: no case for the law \"" + choice_name(kCompressibilityLaws, m.g_law) +
                           "\"");
}

/// Compressibility factor g(Phi; Phi_rcp), the substitute for the lost eq. (18): g -> 1 as
/// Phi -> 0 and g -> inf as Phi -> Phi_rcp (docs/assumptions.md A1). +inf for Phi >= Phi_rcp.
inline double compressibility_factor(const Material& m, double Phi, double Phi_rcp) {
    const double gap = 1.0 - Phi / Phi_rcp;
    if (!(gap > 0.0)) return std::numeric_limits<double>::infinity();
    const double b = compressibility_exponent(m, Phi_rcp);
    return b == 1.0 ? 1.0 / gap : std::pow(gap, -b);
}

/// dg/dPhi at fixed Phi_rcp (for the sound speed) from g = compressibility_factor(m, Phi, Phi_rcp):
/// b gap^(-b-1) / Phi_rcp = b g / (Phi_rcp gap), without a second power.
inline double compressibility_factor_slope(const Material& m, double Phi, double Phi_rcp, double g) {
    const double gap = 1.0 - Phi / Phi_rcp;
    if (!(gap > 0.0)) return std::numeric_limits<double>::infinity();
    const double b = compressibility_exponent(m, Phi_rcp);
    return b == 1.0 ? 1.0 / (Phi_rcp * gap * gap) : b * g / (Phi_rcp * gap);
}

/// Kinetic pressure p_k = Phi g T (eq. 16).
inline double kinetic_pressure(double Phi, double g, double T) { return Phi * g * T; }

/// p_y / g = Theta(Phi - Phi_co) T0 (Phi - Phi_co): the yield pressure of eq. (19) without g.
inline double yield_excess(double T0, double Phi, double Phi_co) {
    return Phi > Phi_co ? T0 * (Phi - Phi_co) : 0.0;  // the Heaviside switch of eq. (19)
}

/// Yield pressure p_y = Theta(Phi - Phi_co) T0 (Phi - Phi_co) g (eq. 19).
inline double yield_pressure(double T0, double Phi, double Phi_co, double g) { return yield_excess(T0, Phi, Phi_co) * g; }

/// Every closure at one state (Phi, phi_hat, T).
struct ClosureValues {
    double Phi_rcp, Phi_co;   // packing limits at phi_hat
    double g;                 // compressibility factor (eq. 18 substitute)
    double p_k, p_y, p;       // pressures (eqs. 16, 19, 15)
    double eta, lambda, eps;  // transport coefficients (eqs. 17, 20)
    double dissipation;       // eps Phi T, the sink of eq. (14)
    double c2;                // dp/dPhi at fixed T and phi_hat: squared sound speed of eqs. (8)-(9)
};

/// Evaluates eqs. (15)-(20) at (Phi, T) with the packing limits Phi_rcp, Phi_co already known
/// (inline, for the flow solver's cell loops; evaluate_closures calls it).
inline ClosureValues evaluate_closures_at(const Material& m, double Phi, double T, double Phi_rcp, double Phi_co) {
    ClosureValues v{};
    v.Phi_rcp = Phi_rcp;
    v.Phi_co = Phi_co;
    v.g = compressibility_factor(m, Phi, Phi_rcp);

    const double excess = yield_excess(m.T0, Phi, Phi_co);  // p_y / g
    v.p_k = kinetic_pressure(Phi, v.g, T);                  // eq. (16)
    v.p_y = excess * v.g;                                   // eq. (19)
    v.p = v.p_k + v.p_y;                                    // eq. (15)

    // Eqs. (17) and (20) in expanded form: eta_k (1 + p_y/p_k) = eta0 g (Phi sqrt(T) + excess/sqrt(T)).
    const double sqrtT = std::sqrt(T);
    const double yield_term = excess > 0.0 ? excess / sqrtT : 0.0;  // +inf at T = 0 in the yield regime
    v.eta = m.eta0 * v.g * (Phi * sqrtT + yield_term);
    v.lambda = m.lambda0 * v.g * (Phi * sqrtT + yield_term);
    v.eps = m.eps0 * v.g * (sqrtT + (excess > 0.0 ? yield_term / Phi : 0.0));
    v.dissipation = m.eps0 * v.g * sqrtT * (Phi * T + excess);

    // c^2 = d/dPhi [g (Phi T + excess)] at fixed T: g' (Phi T + excess) + g (T + s T0).
    const double dg = compressibility_factor_slope(m, Phi, Phi_rcp, v.g);
    v.c2 = dg * (Phi * T + excess) + v.g * (T + (excess > 0.0 ? m.T0 : 0.0));
    return v;
}

/// Evaluates eqs. (15)-(20) at (Phi, phi_hat, T) for material m.
ClosureValues evaluate_closures(const Material& m, double Phi, double phi_hat, double T);

/// The closures' output columns, listed once for closures.dat (closure-sweep) and `granseg
/// closures`: Phi_rcp Phi_co g p_k p_y p eta lambda eps dissipation c (c = sqrt(c^2)); given the
/// material, p_Pa = p rho* follows p.
TableRow closure_columns(const ClosureValues& v, const Material* in_pascal = nullptr);

/// Granular temperature of steady homogeneous shear at shear rate gamma_dot, eq. (45) solved
/// for T: T = (3/2) (eta0/eps0) gamma_dot^2.
double steady_shear_temperature(const Material& m, double gamma_dot);

}  // namespace granseg
