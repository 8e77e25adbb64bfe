#include "riemann/riemann_sample.hpp"

#include <algorithm>
#include <cmath>

namespace granseg {

double sample_phi(const RiemannSolution& s, double xi) {
    double phi = s.L.phi;
    for (const Wave& w : s.waves) {
        if (xi < w.speed_left) return phi;
        if (w.kind == WaveKind::rarefaction && xi < w.speed_right)
            return 0.5 * w.left.Phi * (1.0 + xi / w.left.a);  // lambda_1(phi) = xi (eq. 55)
        phi = w.right.phi;
    }
    return phi;
}

double sample_Phi(const RiemannSolution& s, double xi) { return xi < 0.0 ? s.L.Phi : s.R.Phi; }

double sample_a(const RiemannSolution& s, double xi) { return xi < 0.0 ? s.L.a : s.R.a; }

double sample_range(const RiemannSolution& s) {
    const double a_max = std::max(std::fabs(s.L.a), std::fabs(s.R.a));
    return a_max > 0.0 ? 1.25 * a_max : 1.0;
}

}  // namespace granseg
