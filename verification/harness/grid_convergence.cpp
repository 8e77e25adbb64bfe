#include "harness/grid_convergence.hpp"

#include "core/error.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

namespace granseg::verify {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// The fixed-point iteration for p contracts by about |d q/d p| / ln r21, small when r21 and r32 are
// close (refinement ratios within a few per cent of each other): 200 iterations reach round-off for
// any ratio a grid study uses; a pair of ratios for which it does not converge is reported, not guessed.
constexpr int kOrderIterations = 200;
constexpr double kOrderTolerance = 1e-13;

/// The observed order of a monotone triple (Celik et al. 2008, eqs. 3-4, s = 1), NaN if the
/// iteration does not settle.
double observed_order(double e21, double e32, double r21, double r32) {
    const double log_ratio = std::log(std::fabs(e32 / e21));
    double p = log_ratio / std::log(r21);
    for (int i = 0; i < kOrderIterations; ++i) {
        const double q = std::log((std::pow(r21, p) - 1.0) / (std::pow(r32, p) - 1.0));
        const double next = std::fabs(log_ratio + q) / std::log(r21);
        if (!std::isfinite(next)) return kNaN;
        if (std::fabs(next - p) <= kOrderTolerance * (1.0 + next)) return next;
        p = next;
    }
    return kNaN;
}

/// The result for values that allow no extrapolation: their range, and the uncertainty `share` of it.
GridConvergence range_only(Convergence condition, double R, double lo, double hi, double share) {
    GridConvergence g;
    g.condition = condition, g.R = R, g.p = kNaN, g.p_gci = kNaN, g.f_ext = kNaN, g.asymptotic = kNaN, g.fs = kNaN;
    g.lo = lo, g.hi = hi, g.uncertainty = share * (hi - lo);
    return g;
}

void require_grids(const double* h, const double* f, int n) {
    for (int i = 0; i < n; ++i) {
        if (!(h[i] > 0.0) || !std::isfinite(h[i]) || (i > 0 && !(h[i] > h[i - 1])))
            throw InputError("grid convergence: cell sizes must be positive and increase from the finest grid");
        if (!std::isfinite(f[i])) throw InputError("grid convergence: a value is not finite");
    }
}

/// The GCI's order and factor of safety (first, second) for an observed order p and a factor Fs
/// under the rule for an order far from the formal one (header); formal_order <= 0: (p, Fs).
std::pair<double, double> gci_order(double p, double Fs, double formal_order) {
    if (!(formal_order > 0.0) || (p >= 0.5 * formal_order && p <= 2.0 * formal_order)) return {p, Fs};
    return {std::min(std::max(0.5, p), formal_order), 3.0};
}

}  // namespace

std::string convergence_name(Convergence c) {
    switch (c) {
        case Convergence::monotone: return "monotone";
        case Convergence::oscillatory: return "oscillatory";
        case Convergence::divergent: return "divergent";
        case Convergence::undetermined: return "undetermined";
        case Convergence::two_grids: return "two grids";
    }
    return "?";
}

GridConvergence three_grid_convergence(const std::array<double, 3>& h, const std::array<double, 3>& f, double Fs,
                                       double formal_order) {
    require_grids(h.data(), f.data(), 3);
    const double e21 = f[1] - f[0], e32 = f[2] - f[1];
    const double lo = *std::min_element(f.begin(), f.end()), hi = *std::max_element(f.begin(), f.end());
    if (e21 == 0.0 || e32 == 0.0) return range_only(Convergence::undetermined, e32 == 0.0 ? kNaN : 0.0, lo, hi, 1.0);
    const double R = e21 / e32;
    if (R < 0.0) return range_only(Convergence::oscillatory, R, lo, hi, 0.5);
    if (R >= 1.0) return range_only(Convergence::divergent, R, lo, hi, 1.0);
    const double r21 = h[1] / h[0], r32 = h[2] / h[1];
    const double p = observed_order(e21, e32, r21, r32);
    if (!std::isfinite(p)) return range_only(Convergence::undetermined, R, lo, hi, 1.0);
    GridConvergence g;
    const auto [q, fs] = gci_order(p, Fs, formal_order);
    g.condition = Convergence::monotone, g.R = R, g.p = p, g.p_gci = q, g.lo = lo, g.hi = hi, g.fs = fs;
    g.f_ext = f[0] - e21 / (std::pow(r21, p) - 1.0);
    g.uncertainty = fs * std::fabs(e21) / (std::pow(r21, q) - 1.0);
    const double gci32 = fs * std::fabs(e32) / (std::pow(r32, q) - 1.0);
    g.asymptotic = gci32 / (std::pow(r21, q) * g.uncertainty);
    return g;
}

GridConvergence two_grid_convergence(const std::array<double, 2>& h, const std::array<double, 2>& f, double p,
                                     double Fs) {
    require_grids(h.data(), f.data(), 2);
    if (!(p > 0.0)) throw InputError("grid convergence: the assumed order must be positive");
    const double r = h[1] / h[0], e21 = f[1] - f[0];
    GridConvergence g;
    g.condition = Convergence::two_grids, g.R = kNaN, g.p = p, g.p_gci = p, g.asymptotic = kNaN, g.fs = Fs;
    g.lo = std::min(f[0], f[1]), g.hi = std::max(f[0], f[1]);
    g.f_ext = f[0] - e21 / (std::pow(r, p) - 1.0);
    g.uncertainty = Fs * std::fabs(e21) / (std::pow(r, p) - 1.0);
    return g;
}

}  // namespace granseg::verify
