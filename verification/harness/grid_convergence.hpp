// Solution verification: how far a quantity computed on the finest of a few grids lies from the
// same model's h -> 0 value (Roache's grid convergence index, GCI; the three-grid procedure of
// Celik et al., J. Fluids Eng. 130:078001, 2008), restated in docs/sect4.2_tumbler.md,
// section "Results".
//
// Grids 1 (finest) to 3 (coarsest) with cell sizes h1 < h2 < h3, values f1, f2, f3,
// e21 = f2 - f1, e32 = f3 - f2, r21 = h2/h1, r32 = h3/h2:
//   convergence condition R = e21/e32: 0 < R < 1 monotone, R < 0 oscillatory, R >= 1 divergent,
//                                     R = 0 or undefined (a difference exactly 0) undetermined;
//   observed order p (monotone only): the p for which f = f_ext + C h^p passes through all three
//     values, p = |ln|e32/e21| + q(p)| / ln r21 with q(p) = ln((r21^p - 1)/(r32^p - 1)), solved by
//     fixed-point iteration (q = 0 for a constant ratio);
//   Richardson extrapolation f_ext = f1 - e21/(r21^p - 1);
//   GCI = Fs |e21|/(r21^p - 1), Fs = 1.25: here an absolute uncertainty of f1 (the relative form
//     divides by f1, which for a share near 0 - the periphery - means nothing).
// Not monotone: no extrapolation; the uncertainty is half the range of the three values when
// oscillatory (Celik et al.) and the whole range when divergent or undetermined (our choice: a bound
// that does not pretend to know the direction of the error).
// Observed order far from the scheme's formal order pf (outside [pf/2, 2 pf]; given pf > 0): the
// grids are not in the asymptotic range, and a GCI formed with that p would mean nothing (p = 9
// makes it vanish). The GCI then takes p = min(max(1/2, p), pf) and Fs = 3 (Oberkampf & Roy,
// Verification and Validation in Scientific Computing, Sect. 8.7); f_ext keeps the observed p.
// Two grids: the order is assumed (the scheme's formal order) and Fs = 3.
#pragma once

#include <array>
#include <string>

namespace granseg::verify {

enum class Convergence { monotone, oscillatory, divergent, undetermined, two_grids };

/// "monotone", "oscillatory", "divergent", "undetermined", "two grids".
std::string convergence_name(Convergence c);

struct GridConvergence {
    Convergence condition = Convergence::undetermined;
    double R = 0;           // e21/e32 (NaN with two grids or a zero e32)
    double p = 0;           // observed order (monotone), the assumed one (two grids), else NaN
    double p_gci = 0;       // order the GCI is formed with (p, or the limited one above), else NaN
    double f_ext = 0;       // Richardson-extrapolated value (monotone or two grids), else NaN
    double uncertainty = 0; // absolute: the GCI (monotone, two grids) or the range rule above
    double asymptotic = 0;  // GCI_32 / (r21^p GCI_21): 1 in the asymptotic range (monotone), else NaN
    double lo = 0, hi = 0;  // smallest and largest of the values
    double fs = 0;          // factor of safety used (NaN where no GCI is formed)
};

/// Three grids: h fine to coarse (h[0] < h[1] < h[2], all > 0), f the values on them; Fs the factor
/// of safety; formal_order > 0 applies the rule for an observed order far from it (above), 0 does
/// not. InputError for cell sizes not strictly increasing and positive or a non-finite value.
GridConvergence three_grid_convergence(const std::array<double, 3>& h, const std::array<double, 3>& f,
                                       double Fs = 1.25, double formal_order = 0.0);

/// Two grids (h[0] < h[1]) with the assumed order p: f_ext = f1 - e21/(r^p - 1), GCI = Fs |e21|/(r^p - 1).
GridConvergence two_grid_convergence(const std::array<double, 2>& h, const std::array<double, 2>& f, double p,
                                     double Fs = 3.0);

}  // namespace granseg::verify
