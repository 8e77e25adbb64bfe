#include "harness/gray_thornton.hpp"

#include "core/error.hpp"

#include <algorithm>
#include <cmath>

namespace granseg::verify {

PiecewiseLinear homogeneous_batch(double psi0, double q, double t) {
    if (q * t >= 1.0) return {[psi0](double z) { return z < psi0 ? 1.0 : 0.0; }, {psi0}};
    const double lower = q * psi0 * t;                // shock speed (F(1) - F(psi0))/(1 - psi0) = q psi0
    const double upper = 1.0 - q * (1.0 - psi0) * t;  // shock speed (F(0) - F(psi0))/(0 - psi0) = -q (1 - psi0)
    return {[=](double z) { return z < lower ? 1.0 : z < upper ? psi0 : 0.0; }, {lower, upper}};
}

PiecewiseLinear graded_batch(double z0, double q, double t) {
    const double s = q * t;
    if (s > 1.0 + 2.0 * std::sqrt(z0 * (1.0 - z0)))
        throw InputError("graded_batch: the shocks have met; the formula no longer holds");
    const double fan_lo = z0 - s, fan_hi = z0 + s;  // edges of the centred fan
    const double lower = fan_lo > 0.0 ? 0.0 : std::pow(std::sqrt(s) - std::sqrt(z0), 2);
    const double upper = fan_hi < 1.0 ? 1.0 : 1.0 - std::pow(std::sqrt(s) - std::sqrt(1.0 - z0), 2);
    const auto value = [=](double z) {
        if (z < lower) return 1.0;  // small particles that reached the base (after the fan hit it)
        if (z > upper) return 0.0;  // large particles that reached the surface
        if (z < fan_lo) return 0.0;
        if (z > fan_hi) return 1.0;
        return 0.5 * (1.0 + (z - z0) / s);  // characteristic speed q (2 psi - 1) = (z - z0)/t
    };
    std::vector<double> breaks = {lower, upper};
    if (fan_lo > 0.0) breaks.push_back(fan_lo);
    if (fan_hi < 1.0) breaks.push_back(fan_hi);
    return {value, breaks};
}

std::vector<double> cell_averages(const PiecewiseLinear& profile, int cells, double length) {
    const double h = length / cells;
    std::vector<double> averages(cells);
    for (int k = 0; k < cells; ++k) {
        const double a = k * h, b = (k + 1) * h;
        std::vector<double> cuts = {a, b};
        for (double z : profile.breaks)
            if (z > a && z < b) cuts.push_back(z);
        std::sort(cuts.begin(), cuts.end());
        double sum = 0.0, lowest = INFINITY, highest = -INFINITY;
        for (std::size_t p = 0; p + 1 < cuts.size(); ++p) {
            const double v = profile.value(0.5 * (cuts[p] + cuts[p + 1]));  // exact on a linear piece
            sum += (cuts[p + 1] - cuts[p]) / (b - a) * v;
            lowest = std::min({lowest, v, profile.value(cuts[p]), profile.value(cuts[p + 1])});
            highest = std::max({highest, v, profile.value(cuts[p]), profile.value(cuts[p + 1])});
        }
        // The weights sum to 1 up to round-off; keep the average inside the range of the values
        // (a constant 1 must average to exactly 1, or phi0 = Phi psi would start above Phi).
        averages[k] = std::clamp(sum, lowest, highest);
    }
    return averages;
}

std::vector<double> logistic_cell_averages(double P, double psi0, int cells) {
    const double C = (std::exp(-P * psi0) - std::exp(-P)) / (1.0 - std::exp(-P * psi0));
    // Antiderivative of 1/(1 + C e^{Pz}): z - ln(1 + C e^{Pz})/P (log1p keeps it accurate).
    const auto antiderivative = [&](double z) { return z - std::log1p(C * std::exp(P * z)) / P; };
    const double h = 1.0 / cells;
    std::vector<double> averages(cells);
    for (int k = 0; k < cells; ++k) averages[k] = (antiderivative((k + 1) * h) - antiderivative(k * h)) / h;
    return averages;
}

std::vector<double> smooth_periodic_averages(double A, double q, double t, int cells) {
    if (!(4.0 * M_PI * q * A * t < 1.0)) throw InputError("smooth_periodic_averages: past the breaking time");
    const auto psi = [&](double z) {
        double xi = z;
        for (int i = 0; i < 100; ++i) {  // g(xi) = xi + 2 q A t sin(2 pi xi) - z, g' >= 1 - 4 pi q A t > 0
            const double step = (xi + 2.0 * q * A * t * std::sin(2.0 * M_PI * xi) - z) /
                                (1.0 + 4.0 * M_PI * q * A * t * std::cos(2.0 * M_PI * xi));
            xi -= step;
            if (std::fabs(step) < 1e-16) break;
        }
        return 0.5 + A * std::sin(2.0 * M_PI * xi);
    };
    const double h = 1.0 / cells;
    std::vector<double> averages(cells);
    for (int k = 0; k < cells; ++k) averages[k] = gauss_legendre4(psi, k * h, (k + 1) * h) / h;
    return averages;
}

double gauss_legendre4(const std::function<double(double)>& f, double a, double b) {
    static const double node[4] = {-0.8611363115940526, -0.3399810435848563, 0.3399810435848563, 0.8611363115940526};
    static const double weight[4] = {0.3478548451374538, 0.6521451548625461, 0.6521451548625461, 0.3478548451374538};
    const double mid = 0.5 * (a + b), half = 0.5 * (b - a);
    double sum = 0.0;
    for (int g = 0; g < 4; ++g) sum += weight[g] * f(mid + half * node[g]);
    return half * sum;
}

double l1_distance(const std::vector<double>& u, const std::vector<double>& v, double h) {
    double sum = 0.0;
    for (std::size_t i = 0; i < u.size(); ++i) sum += std::fabs(u[i] - v[i]);
    return h * sum;
}

double observed_order(double e_coarse, double e_fine, double refinement) {
    return std::log(e_coarse / e_fine) / std::log(refinement);
}

}  // namespace granseg::verify
