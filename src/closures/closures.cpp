#include "closures/closures.hpp"

namespace granseg {

ClosureValues evaluate_closures(const Material& m, double Phi, double phi_hat, double T) {
    return evaluate_closures_at(m, Phi, T, m.packing.Phi_rcp(phi_hat), m.packing.Phi_co(phi_hat));
}

double steady_shear_temperature(const Material& m, double gamma_dot) {
    return 1.5 * (m.eta0 / m.eps0) * gamma_dot * gamma_dot;  // eq. (45): gamma_dot^2 = (2/3)(eps0/eta0) T
}

}  // namespace granseg
