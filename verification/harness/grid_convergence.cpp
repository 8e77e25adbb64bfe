#include "harness/grid_convergence.hpp"

#include "core/error.hpp"

#include <gsl/gsl_cdf.h>
#include <gsl/gsl_errno.h>
#include <gsl/gsl_fit.h>
#include <gsl/gsl_min.h>

#include <algorithm>
#include <cmath>
#include <memory>

namespace granseg::verify {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
// The fit's order is sought in [kMinOrder, kMaxOrder]: an order of 10 already makes every grid but
// the coarsest equal to the limit to the digits a run prints; it stands for "faster than any".
constexpr double kMaxOrder = 10.0;
// The noise test's level: a constant is rejected when chi^2 exceeds its 95 % quantile.
constexpr double kNoiseLevel = 0.95;
// A sampling error of 0 (an exact value) still needs a finite weight: the round-off of a double
// relative to the values' magnitude stands in for it (all exact: equal weights, the plain fit).
constexpr double kRoundoff = 1e-13;
// Roy's band for an observed order "in agreement" with the formal one, and the order limits.
constexpr double kRoyBand = 0.1, kRoyMinOrder = 0.5, kFsClose = 1.25, kFsFar = 3.0;

/// The weighted least-squares fit f = g0 + beta (h/h1)^p at a fixed order p (gsl_fit_wlinear).
struct FixedFit {
    double g0 = 0, beta = 0, chisq = 0;
};

FixedFit fit_at(double p, const std::vector<double>& x_h, const std::vector<double>& w, const std::vector<double>& f) {
    std::vector<double> x(x_h.size());
    for (std::size_t i = 0; i < x.size(); ++i) x[i] = std::pow(x_h[i], p);
    FixedFit fit;
    double c00, c01, c11;
    gsl_fit_wlinear(x.data(), 1, w.data(), 1, f.data(), 1, x.size(), &fit.g0, &fit.beta, &c00, &c01, &c11, &fit.chisq);
    return fit;
}

/// The order minimising the weighted residual of fit_at over [kMinOrder, kMaxOrder]: a scan on a
/// logarithmic grid brackets the minimum, GSL's Brent minimiser refines it to round-off.
double best_order(const std::vector<double>& x_h, const std::vector<double>& w, const std::vector<double>& f) {
    constexpr int kScan = 240;
    std::vector<double> p(kScan + 1), S(kScan + 1);
    for (int k = 0; k <= kScan; ++k) {
        p[k] = kMinOrder * std::pow(kMaxOrder / kMinOrder, static_cast<double>(k) / kScan);
        S[k] = fit_at(p[k], x_h, w, f).chisq;
    }
    const int k = static_cast<int>(std::min_element(S.begin(), S.end()) - S.begin());
    if (k == 0 || k == kScan || !(S[k] < S[k - 1] && S[k] < S[k + 1])) return p[k];
    struct Data {
        const std::vector<double>*x_h, *w, *f;
    } data{&x_h, &w, &f};
    gsl_function F;
    F.function = [](double q, void* d) {
        const Data& a = *static_cast<const Data*>(d);
        return fit_at(q, *a.x_h, *a.w, *a.f).chisq;
    };
    F.params = &data;
    std::unique_ptr<gsl_min_fminimizer, decltype(&gsl_min_fminimizer_free)> m(gsl_min_fminimizer_alloc(gsl_min_fminimizer_brent),
                                                                              gsl_min_fminimizer_free);
    gsl_min_fminimizer_set_with_values(m.get(), &F, p[k], S[k], p[k - 1], S[k - 1], p[k + 1], S[k + 1]);
    for (int i = 0; i < 200; ++i) {
        gsl_min_fminimizer_iterate(m.get());
        const double a = gsl_min_fminimizer_x_lower(m.get()), b = gsl_min_fminimizer_x_upper(m.get());
        if (gsl_min_test_interval(a, b, 1e-14, 1e-12) == GSL_SUCCESS) break;
    }
    return gsl_min_fminimizer_x_minimum(m.get());
}

void require_grids(const std::vector<double>& h, const std::vector<double>& f, const std::vector<double>& se) {
    if (h.size() < 2 || f.size() != h.size() || se.size() != h.size())
        throw InputError("grid convergence: need two or more grids with one value and one sampling error each");
    for (std::size_t i = 0; i < h.size(); ++i) {
        if (!(h[i] > 0.0) || !std::isfinite(h[i]) || (i > 0 && !(h[i] > h[i - 1])))
            throw InputError("grid convergence: cell sizes must be positive and increase from the finest grid");
        if (!std::isfinite(f[i])) throw InputError("grid convergence: a value is not finite");
        if (se[i] < 0.0) throw InputError("grid convergence: a sampling error is negative");
    }
}

/// Neighbouring differences change sign (a zero difference changes nothing).
bool sign_changes(const std::vector<double>& f) {
    int sign = 0;
    for (std::size_t i = 0; i + 1 < f.size(); ++i) {
        const double d = f[i + 1] - f[i];
        const int s = d > 0.0 ? 1 : (d < 0.0 ? -1 : 0);
        if (s != 0 && sign != 0 && s != sign) return true;
        if (s != 0) sign = s;
    }
    return false;
}

}  // namespace

std::string convergence_name(Convergence c) {
    switch (c) {
        case Convergence::monotone:
            return "monotone";
        case Convergence::oscillatory:
            return "oscillatory";
        case Convergence::divergent:
            return "divergent";
        case Convergence::within_noise:
            return "within noise";
        case Convergence::two_grids:
            return "two grids";
        case Convergence::undetermined:
            return "undetermined";
    }
    return "?";
}

std::pair<double, double> roy_order_and_safety(double p, double pf) {
    if (!(pf > 0.0)) throw InputError("grid convergence: the formal order must be positive");
    if (std::fabs(p - pf) <= kRoyBand * pf) return {pf, kFsClose};
    return {std::min(std::max(kRoyMinOrder, p), pf), kFsFar};
}

GridConvergence grid_convergence(const std::vector<double>& h, const std::vector<double>& f, const std::vector<double>& se_in,
                                 double formal_order, Bounds bounds) {
    std::vector<double> se(se_in);
    for (double& s : se)
        if (std::isnan(s)) s = 0.0;
    require_grids(h, f, se);
    if (!(formal_order > 0.0)) throw InputError("grid convergence: the formal order must be positive");
    const std::size_t n = h.size();
    GridConvergence g;
    g.grids = static_cast<int>(n);
    g.lo = *std::min_element(f.begin(), f.end()), g.hi = *std::max_element(f.begin(), f.end());
    g.data_range = (g.hi - g.lo) / static_cast<double>(n - 1);
    g.e_a = f[0] != 0.0 ? std::fabs((f[0] - f[1]) / f[0]) : kNaN;
    g.p = g.f0 = g.p_u = g.fs = g.eps = g.g0_u = g.sigma = g.e_ext = kNaN;

    double scale = 0.0;
    for (double v : f) scale = std::max(scale, std::fabs(v));
    std::vector<double> w(n), x_h(n);
    double sw = 0.0, swf = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
        const double s = std::max(se[i], kRoundoff * std::max(scale, 1e-300));
        w[i] = 1.0 / (s * s), x_h[i] = h[i] / h[0], sw += w[i], swf += w[i] * f[i];
    }
    g.chi2 = 0.0;
    for (std::size_t i = 0; i < n; ++i) g.chi2 += w[i] * (f[i] - swf / sw) * (f[i] - swf / sw);
    g.chi2_limit = gsl_cdf_chisq_Pinv(kNoiseLevel, static_cast<double>(n - 1));
    if (g.chi2 <= g.chi2_limit) {
        g.condition = Convergence::within_noise, g.uncertainty = g.hi - g.lo;
        return g;
    }
    if (sign_changes(f)) {
        g.condition = Convergence::oscillatory, g.uncertainty = 0.5 * (g.hi - g.lo);
        return g;
    }
    if (n == 2) {
        g.condition = Convergence::two_grids, g.p_u = formal_order, g.fs = kFsFar;
    } else {
        g.p = best_order(x_h, w, f);
        if (g.p <= kMinOrder * (1.0 + 1e-9)) {
            g.condition = Convergence::divergent, g.uncertainty = g.hi - g.lo, g.p = kNaN;
            return g;
        }
        g.condition = Convergence::monotone;
        std::tie(g.p_u, g.fs) = roy_order_and_safety(g.p, formal_order);
    }
    const FixedFit observed = fit_at(n == 2 ? formal_order : g.p, x_h, w, f), at_pu = fit_at(g.p_u, x_h, w, f);
    g.f0 = observed.g0;
    g.e_ext = g.f0 != 0.0 ? std::fabs((g.f0 - f[0]) / g.f0) : kNaN;
    g.outside_bounds = g.f0 < bounds.lower || g.f0 > bounds.upper;
    g.eps = at_pu.beta, g.g0_u = at_pu.g0;
    g.sigma = n > 2 ? std::sqrt(static_cast<double>(n) * at_pu.chisq / sw / static_cast<double>(n - 2)) : 0.0;
    g.uncertainty = uncertainty_at(g, h, f, 0);
    return g;
}

double uncertainty_at(const GridConvergence& g, const std::vector<double>& h, const std::vector<double>& f, std::size_t k) {
    if (k >= h.size() || k >= f.size()) throw InputError("grid convergence: no grid " + std::to_string(k));
    if (std::isnan(g.eps)) return g.uncertainty;  // a range: within noise, oscillatory, divergent
    const double eps = g.eps * std::pow(h[k] / h[0], g.p_u), miss = std::fabs(f[k] - g.g0_u - eps);
    return g.sigma < g.data_range ? g.fs * std::fabs(eps) + g.sigma + miss
                                  : kFsFar * (g.sigma / g.data_range) * (std::fabs(eps) + g.sigma + miss);
}

}  // namespace granseg::verify
