// Solution verification: how far a quantity computed on the finest of several grids lies from the
// same model's h -> 0 value, restated in docs/sect4.2_fig7_study.md, "The method".
//
// Grids 1 (finest) to n (coarsest), cell sizes h1 < ... < hn, values f_i with sampling errors s_i
// (the standard error of a time average, or the jitter of a value read at one instant):
//
//  1. Noise first: if the values agree with one constant within their sampling errors
//     (chi^2 = sum (f_i - f_w)^2 / s_i^2 at or below its 95 % quantile with n - 1 degrees of
//     freedom, f_w the weighted mean), the grids resolve no trend: no order is claimed
//     ("within noise") and the uncertainty is the range of the values.
//  2. Sign changes between neighbouring grids: "oscillatory", no order, half the range (Celik et
//     al., J. Fluids Eng. 130:078001, 2008).
//  3. Monotone: the least-squares fit f = f0 + alpha h^p over all grids (Eca & Hoekstra, "A
//     procedure for the estimation of the numerical uncertainty of CFD calculations based on grid
//     refinement studies", J. Comput. Phys. 262:104-130, 2014), each grid weighted by 1/s_i^2 so
//     that a noisy run counts less. p at or below kMinOrder: "divergent" (the differences do not
//     shrink), the whole range.
//  4. The uncertainty's order and factor of safety, Roy's rule (C. J. Roy, "Review of
//     discretization error estimators in scientific computing", AIAA 2010-126; Oberkampf & Roy,
//     Verification and Validation in Scientific Computing, 2010, Sect. 8.7):
//       |p - pf| / pf <= 0.1:  Fs = 1.25 with p_u = pf;
//       otherwise:             Fs = 3    with p_u = min(max(0.5, p), pf).
//     Two grids: p_u = pf, Fs = 3 (Roache's rule for an assumed order).
//  5. The uncertainty of f1 in Eca & Hoekstra's form, with the fit at the fixed order p_u
//     (f = g0 + beta h^p_u, least squares, same weights): its error estimate eps = beta h1^p_u,
//     its standard deviation sigma (n - 2 degrees of freedom; 0 for two grids) and its miss at h1,
//     d1 = |f1 - g0 - eps|:
//       sigma <  Delta:  U = Fs |eps| + sigma + d1,
//       sigma >= Delta:  U = 3 (sigma / Delta) (|eps| + sigma + d1)   (the fit is poor),
//     with the data range Delta = (max f - min f)/(n - 1). For three grids with a constant ratio
//     and p_u = p this is Roache's GCI, Fs |e21|/(r^p - 1).
// Reported besides: f0 (the extrapolated value, observed order), e_a = |(f1 - f2)/f1| and
// e_ext = |(f0 - f1)/f0| (relative; NaN where the denominator is 0), and whether f0 lies outside
// the quantity's physical range (a share below 0, a thickness below 0): the fit is then used
// outside its range, and its f0 must not be read as a limit.
#pragma once

#include <limits>
#include <string>
#include <utility>
#include <vector>

namespace granseg::verify {

/// The conditions of the header; `undetermined` is for callers whose runs allow no study (the
/// abscissae do not increase, or a value is undefined).
enum class Convergence { monotone, oscillatory, divergent, within_noise, two_grids, undetermined };

/// "monotone", "oscillatory", "divergent", "within noise", "two grids", "undetermined".
std::string convergence_name(Convergence c);

/// Smallest observed order the fit resolves; at or below it the series is called divergent.
constexpr double kMinOrder = 0.05;

/// Roy's rule (header, step 4): the order p_u and factor of safety Fs of the uncertainty for an
/// observed order p and the formal order pf > 0.
std::pair<double, double> roy_order_and_safety(double p, double pf);

/// The physical range of a quantity (an extrapolated value outside it is flagged).
struct Bounds {
    double lower = -std::numeric_limits<double>::infinity();
    double upper = std::numeric_limits<double>::infinity();
};

struct GridConvergence {
    Convergence condition = Convergence::within_noise;
    int grids = 0;
    double chi2 = 0, chi2_limit = 0;  // the noise test: chi^2 of a constant and its 95 % quantile
    double p = 0;                     // observed order of the fit (monotone), else NaN
    double f0 = 0;                    // extrapolated value f(h -> 0) (monotone, two grids), else NaN
    double p_u = 0, fs = 0;           // order and factor of safety of U (NaN where none is formed)
    double eps = 0;                   // error estimate of f1 at the order p_u (NaN where none)
    double g0_u = 0;                  // the fit's limit at the order p_u (NaN where none)
    double sigma = 0;                 // standard deviation of the fit at p_u (NaN where none)
    double data_range = 0;            // (max - min)/(n - 1)
    double uncertainty = 0;           // absolute, of f1 (the band f1 +- U)
    double e_a = 0, e_ext = 0;        // relative change f1 -> f2, relative distance f1 -> f0
    double lo = 0, hi = 0;            // smallest and largest value
    bool outside_bounds = false;      // f0 outside the quantity's physical range
};

/// The uncertainty of the value on grid k (0 the finest, the `uncertainty` above; h and f as given
/// to grid_convergence) by the same rule, with the fit's error estimate at h_k, eps (h_k/h_1)^p_u,
/// and its miss there. Within noise, oscillatory, divergent: the same range as `uncertainty`.
double uncertainty_at(const GridConvergence& g, const std::vector<double>& h, const std::vector<double>& f, std::size_t k);

/// The procedure of the header. h fine to coarse (strictly increasing, > 0), f and se (sampling
/// errors >= 0, NaN read as 0) of the same length >= 2, the scheme's formal order pf > 0.
/// InputError for sizes not increasing, a non-finite value, or mismatched lengths.
GridConvergence grid_convergence(const std::vector<double>& h, const std::vector<double>& f, const std::vector<double>& se,
                                 double formal_order, Bounds bounds = {});

}  // namespace granseg::verify
