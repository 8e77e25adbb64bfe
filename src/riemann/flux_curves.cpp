#include "riemann/flux_curves.hpp"

#include "core/error.hpp"
#include "core/format.hpp"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <string>

namespace granseg {

namespace {

/// Relative slack for F outside [min(0, -a Phi/4), max(0, -a Phi/4)] that still counts as the
/// end point: the callers pass values of f computed with a few roundings.
constexpr double kClampSlack = 1e3 * DBL_EPSILON;

/// d = 1 + 4F/(a Phi) in [0, 1]: the discriminant of a phi^2/Phi - a phi - F = 0, scaled.
double discriminant(double F, double Phi, double a) {
    if (!(Phi > 0.0) || a == 0.0)
        throw InputError("flux inverse: needs Phi > 0 and a != 0 (Phi = " + format_number(Phi) + ", a = " + format_number(a) +
                         ")");
    const double d = 1.0 + 4.0 * F / (a * Phi);
    if (d < -kClampSlack || d > 1.0 + kClampSlack)
        throw InputError("flux inverse: F = " + format_exact(F) + " is not a value of f(.; Phi = " + format_number(Phi) +
                         ", a = " + format_number(a) + ")");
    return std::clamp(d, 0.0, 1.0);
}

}  // namespace

double phi_left_of_gamma(double F, double Phi, double a) {
    const double d = discriminant(F, Phi, a);
    // Phi/2 (1 - sqrt(d)) rewritten as Phi/2 (1 - d)/(1 + sqrt(d)) with 1 - d = -4F/(a Phi).
    return std::clamp(-2.0 * F / (a * (1.0 + std::sqrt(d))), 0.0, 0.5 * Phi);
}

double phi_right_of_gamma(double F, double Phi, double a) {
    return std::clamp(Phi - phi_left_of_gamma(F, Phi, a), 0.5 * Phi, Phi);
}

}  // namespace granseg
