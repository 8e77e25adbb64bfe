#include "closures/closures.hpp"

namespace granseg {

ClosureValues evaluate_closures(const Material& m, double Phi, double phi_hat, double T) {
    return evaluate_closures_at(m, Phi, T, m.packing.Phi_rcp(phi_hat), m.packing.Phi_co(phi_hat));
}

TableRow closure_columns(const ClosureValues& v, const Material* in_pascal) {
    TableRow row{{"Phi_rcp", v.Phi_rcp}, {"Phi_co", v.Phi_co}, {"g", v.g}, {"p_k", v.p_k}, {"p_y", v.p_y}, {"p", v.p}};
    if (in_pascal) row.add("p_Pa", v.p * in_pascal->rho_star);
    return row.add(
        {{"eta", v.eta}, {"lambda", v.lambda}, {"eps", v.eps}, {"dissipation", v.dissipation}, {"c", std::sqrt(v.c2)}});
}

double steady_shear_temperature(const Material& m, double gamma_dot) {
    return 1.5 * (m.eta0 / m.eps0) * gamma_dot * gamma_dot;  // eq. (45): gamma_dot^2 = (2/3)(eps0/eta0) T
}

}  // namespace granseg
