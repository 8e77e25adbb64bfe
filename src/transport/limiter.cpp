#include "transport/limiter.hpp"

#include <algorithm>
#include <cmath>

namespace granseg {

double limited_slope(double below, double above, Limiter limiter) {
    if (below * above <= 0.0) return 0.0;  // extremum or flat side: first order
    const double sign = below > 0.0 ? 1.0 : -1.0;
    const double a = std::fabs(below), b = std::fabs(above);
    if (limiter == Limiter::minmod) return sign * std::min(a, b);
    return sign * std::min({2.0 * a, 2.0 * b, 0.5 * (a + b)});  // monotonized central
}

}  // namespace granseg
