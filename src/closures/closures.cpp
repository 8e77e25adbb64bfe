#include "closures/closures.hpp"

#include <cmath>
#include <limits>

namespace granseg {

namespace {

/// The exponent b of g = (1 - Phi/Phi_rcp)^(-b) for the chosen law.
double exponent(const Material& m, double Phi_rcp) {
    return m.g_law == CompressibilityLaw::power ? m.beta : 2.5 * Phi_rcp;
}

}  // namespace

double compressibility_factor(const Material& m, double Phi, double Phi_rcp) {
    const double gap = 1.0 - Phi / Phi_rcp;
    if (!(gap > 0.0)) return std::numeric_limits<double>::infinity();
    const double b = exponent(m, Phi_rcp);
    return b == 1.0 ? 1.0 / gap : std::pow(gap, -b);
}

double compressibility_factor_slope(const Material& m, double Phi, double Phi_rcp) {
    const double gap = 1.0 - Phi / Phi_rcp;
    if (!(gap > 0.0)) return std::numeric_limits<double>::infinity();
    const double b = exponent(m, Phi_rcp);
    return b / Phi_rcp * std::pow(gap, -b - 1.0);
}

ClosureValues evaluate_closures(const Material& m, double Phi, double phi_hat, double T) {
    ClosureValues v{};
    v.Phi_rcp = m.packing.Phi_rcp(phi_hat);
    v.Phi_co = m.packing.Phi_co(phi_hat);
    v.g = compressibility_factor(m, Phi, v.Phi_rcp);

    const double excess = yield_excess(m.T0, Phi, v.Phi_co);  // p_y / g
    v.p_k = kinetic_pressure(Phi, v.g, T);                    // eq. (16)
    v.p_y = yield_pressure(m.T0, Phi, v.Phi_co, v.g);         // eq. (19)
    v.p = v.p_k + v.p_y;                                      // eq. (15)

    // Eqs. (17) and (20) in expanded form: eta_k (1 + p_y/p_k) = eta0 g (Phi sqrt(T) + excess/sqrt(T)).
    const double sqrtT = std::sqrt(T);
    const double yield_term = excess > 0.0 ? excess / sqrtT : 0.0;  // +inf at T = 0 in the yield regime
    v.eta = m.eta0 * v.g * (Phi * sqrtT + yield_term);
    v.lambda = m.lambda0 * v.g * (Phi * sqrtT + yield_term);
    v.eps = m.eps0 * v.g * (sqrtT + (excess > 0.0 ? yield_term / Phi : 0.0));
    v.dissipation = m.eps0 * v.g * sqrtT * (Phi * T + excess);

    // c^2 = d/dPhi [g (Phi T + excess)] at fixed T: g' (Phi T + excess) + g (T + s T0).
    const double dg = compressibility_factor_slope(m, Phi, v.Phi_rcp);
    v.c2 = dg * (Phi * T + excess) + v.g * (T + (excess > 0.0 ? m.T0 : 0.0));
    return v;
}

double steady_shear_temperature(const Material& m, double gamma_dot) {
    return 1.5 * (m.eta0 / m.eps0) * gamma_dot * gamma_dot;  // eq. (45): gamma_dot^2 = (2/3)(eps0/eta0) T
}

}  // namespace granseg
