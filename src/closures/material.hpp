// Material parameters of the Latz-Schmidt closures (Sect. 2.1): eta0, lambda0, eps0, T0, the
// compressibility law g standing in for the lost eq. (18), and the packing fits Phi_rcp(phi_hat),
// Phi_co(phi_hat). The paper's Table 2 (glass particles) was lost in the OCR; the defaults are the
// substitute set documented, value by value, in docs/assumptions.md (A2-A5).
//
// Units: all flow equations are divided by the intrinsic density rho*, so p and T are in m^2/s^2,
// eta and lambda in m^2/s, eta0 and lambda0 in m, eps0 in 1/m, T0 in m^2/s^2.
#pragma once

#include "closures/packing.hpp"
#include "core/choice.hpp"

namespace granseg {

/// Degree of the default packing fits (docs/assumptions.md A3: max residual 0.0022 on the table).
constexpr int kDefaultPackingDegree = 4;

/// The compressibility factor's functional form (eq. 18 substitute, docs/assumptions.md A1);
/// its exponent is compressibility_exponent() in closures.hpp.
enum class CompressibilityLaw { power, lun_savage };
inline constexpr Choice<CompressibilityLaw> kCompressibilityLaws[] = {
    {CompressibilityLaw::power, "power", "g = (1 - Phi/Phi_rcp)^(-beta), beta = [material] beta (default 1)"},
    {CompressibilityLaw::lun_savage, "lun-savage", "g = (1 - Phi/Phi_rcp)^(-2.5 Phi_rcp) (Lun & Savage)"},
};

struct Material {
    PackingFit packing;  // Phi_rcp(phi_hat), Phi_co(phi_hat)
    // The values below are the Table 2 substitute; each is justified in docs/assumptions.md.
    double eta0 = 1.9e-4;      // m,  viscosity scale (eq. 17)
    double lambda0 = 3.8e-4;   // m,  conductivity scale (eq. 17)
    double eps0 = 1.3e3;       // 1/m, dissipation scale (eq. 17)
    double T0 = 1.0;           // m^2/s^2, yield parameter (eq. 19)
    double rho_star = 2500.0;  // kg/m^3, intrinsic density; only converts p to Pa in output
    CompressibilityLaw g_law = CompressibilityLaw::power;
    double beta = 1.0;  // exponent of the power law

    /// The substitute for Table 2 (docs/assumptions.md) with the built-in packing table.
    static Material glass_substitute();
    /// Friction coefficient of steady simple shear implied by eqs. (14), (20), (43)-(45):
    /// tau/p = sqrt(2 eta0 eps0 / 3); eq. (21) prints sqrt(eps0 eta0) (docs/assumptions.md A6).
    double shear_friction() const;
};

}  // namespace granseg
