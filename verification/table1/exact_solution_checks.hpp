// The properties an exact Riemann solution of system (52) must have, measured on one solution
// (verify_table1 checks them for every state it draws). Each property is measured from the
// waves and from the sampled profile phi(xi), with formulas written out here, not taken from the
// solver: Rankine-Hugoniot on every shock, Lax entropy condition, equal flux across the standing
// wave and no crossing of Gamma (Isaacson-Temple), rarefactions with lambda_1(phi(xi)) = xi and
// monotone profiles, the wave chain (joined states, speeds <= 0 left of the standing wave, >= 0
// right of it), and the mass balance of each half-line, which gives the interface flux from the
// profile alone and is compared with eq. (63). Header-only (see table1_states.hpp).
#pragma once

#include "harness/tolerances.hpp"
#include "riemann/riemann_sample.hpp"
#include "riemann/riemann_solver.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace granseg::verify {

/// Worst values over the solutions merged into it. Residuals are in flux units; counts are
/// numbers of waves (or solutions) violating a property.
struct SolutionErrors {
    double rankine_hugoniot = 0.0;  // |s (phi_r - phi_l) - (f(phi_r) - f(phi_l))| on shocks
    long lax = 0;                   // shocks with lambda_1(l) < s or s < lambda_1(r)
    double standing = 0.0;          // |f_L(phi_minus) - f_R(phi_plus)|, |F - f_L(phi_minus)|
    long gamma_crossings = 0;       // standing waves with phi_minus, phi_plus on opposite sides of Gamma
    double fan = 0.0;               // |lambda_1(phi(xi)) - xi| inside fans and at their edges
    long fan_order = 0;             // fans with decreasing speeds or a non-monotone profile
    long chain = 0;                 // broken wave chains (see check_exact_solution)
    double mass_flux = 0.0;         // |F from the mass balance of a half-line - eq. (63)|
    double eq63 = 0.0;              // |F of the solution - eq. (63)|
    long solutions = 0;

    void merge(const SolutionErrors& o) {
        rankine_hugoniot = std::max(rankine_hugoniot, o.rankine_hugoniot);
        lax += o.lax;
        standing = std::max(standing, o.standing);
        gamma_crossings += o.gamma_crossings;
        fan = std::max(fan, o.fan);
        fan_order += o.fan_order;
        chain += o.chain;
        mass_flux = std::max(mass_flux, o.mass_flux);
        eq63 = std::max(eq63, o.eq63);
        solutions += o.solutions;
    }
};

/// "S" shock, "R" rarefaction, "C" standing wave (contact), left to right.
inline std::string wave_pattern(const RiemannSolution& s) {
    std::string p;
    for (const Wave& w : s.waves) p += w.kind == WaveKind::shock ? 'S' : w.kind == WaveKind::rarefaction ? 'R' : 'C';
    return p;
}

inline double flux_of(const FluxSide& q) { return q.a * q.phi * (q.phi - q.Phi) / q.Phi; }  // eq. (49)
inline double speed_of(const FluxSide& q) { return q.a * (2.0 * q.phi / q.Phi - 1.0); }     // eq. (55)

/// Integral of phi(xi) over [lo, hi], exact for the piecewise linear profile of the solution
/// (constant states and fans, where phi is linear in xi): midpoint rule between the wave speeds.
inline double profile_integral(const RiemannSolution& s, double lo, double hi) {
    std::vector<double> cuts = {lo, hi};
    for (const Wave& w : s.waves)
        for (double c : {w.speed_left, w.speed_right})
            if (c > lo && c < hi) cuts.push_back(c);
    std::sort(cuts.begin(), cuts.end());
    double sum = 0.0;
    for (std::size_t k = 0; k + 1 < cuts.size(); ++k)
        sum += (cuts[k + 1] - cuts[k]) * sample_phi(s, 0.5 * (cuts[k] + cuts[k + 1]));
    return sum;
}

/// Measures every property of one exact solution; `F_eq63` is the flux eq. (63) gives.
inline SolutionErrors check_exact_solution(const RiemannSolution& s, double F_eq63) {
    SolutionErrors e;
    e.solutions = 1;
    const FluxSide& L = s.L;
    const FluxSide& R = s.R;
    const double scale = std::max({std::fabs(L.a), std::fabs(R.a), 1e-300});
    const double tol = kRoundOff * scale;  // speeds and fluxes are O(|a|)
    const bool same_curve = L.Phi == R.Phi && L.a == R.a;

    //--- The chain: joined states, one standing wave iff (Phi, a) jumps, signs of the speeds.
    bool broken = s.waves.empty() ? (L.phi != R.phi || !same_curve) : false;
    FluxSide at = L;
    bool past_standing = false;
    double last_speed = -INFINITY;
    for (const Wave& w : s.waves) {
        const bool standing = w.kind == WaveKind::standing;
        const FluxSide& side = past_standing || standing ? R : L;
        if (w.left.phi != at.phi || w.left.Phi != at.Phi || w.left.a != at.a) broken = true;
        if (w.right.Phi != side.Phi || w.right.a != side.a) broken = true;
        if (w.speed_left < last_speed - tol || w.speed_right < w.speed_left - tol) broken = true;
        if (!standing && !same_curve && (past_standing ? w.speed_left < -tol : w.speed_right > tol)) broken = true;
        if (standing && (past_standing || w.speed_left != 0.0 || w.speed_right != 0.0 || w.left.phi != s.phi_minus ||
                         w.right.phi != s.phi_plus))
            broken = true;
        past_standing = past_standing || standing;
        last_speed = w.speed_right;
        at = w.right;
    }
    if (!s.waves.empty() && (at.phi != R.phi || at.Phi != R.Phi || at.a != R.a)) broken = true;
    if (past_standing == same_curve) broken = true;
    // The profile next to z = 0 is the trace, unless a shock of speed 0 sits there too (a state
    // at the end of its curve, phi = 0 or Phi, joined to the other end): then it is the state
    // beyond that shock. Just left of 0, a fan ending on Gamma differs from phi_minus by
    // (Phi_L/(2 |a_L|)) |xi|.
    double left_limit = s.phi_minus, right_limit = s.phi_plus;
    for (std::size_t k = 0; k < s.waves.size(); ++k) {
        if (s.waves[k].kind != WaveKind::standing) continue;
        if (k > 0 && s.waves[k - 1].kind == WaveKind::shock && s.waves[k - 1].speed_left == 0.0)
            left_limit = s.waves[k - 1].left.phi;
        if (k + 1 < s.waves.size() && s.waves[k + 1].kind == WaveKind::shock && s.waves[k + 1].speed_left == 0.0)
            right_limit = s.waves[k + 1].right.phi;
    }
    const double xi_minus = -1e-12 * std::max(std::fabs(L.a), 1e-300);
    if (std::fabs(sample_phi(s, xi_minus) - left_limit) > 1e-12 || sample_phi(s, 0.0) != right_limit) broken = true;
    e.chain = broken;

    //--- Each wave on its own.
    for (const Wave& w : s.waves) {
        const double f_l = flux_of(w.left), f_r = flux_of(w.right);
        if (w.kind == WaveKind::shock) {
            const double sp = w.speed_left;
            e.rankine_hugoniot = std::max(e.rankine_hugoniot, std::fabs(sp * (w.right.phi - w.left.phi) - (f_r - f_l)));
            if (speed_of(w.left) < sp - tol || sp < speed_of(w.right) - tol) ++e.lax;
        } else if (w.kind == WaveKind::rarefaction) {
            e.fan = std::max({e.fan, std::fabs(w.speed_left - speed_of(w.left)), std::fabs(w.speed_right - speed_of(w.right))});
            if (!(w.speed_left < w.speed_right)) ++e.fan_order;
            double previous = w.left.phi;
            for (int k = 1; k < 8; ++k) {
                const double xi = w.speed_left + (w.speed_right - w.speed_left) * k / 8.0;
                const double phi = sample_phi(s, xi);
                e.fan = std::max(e.fan, std::fabs(speed_of({phi, w.left.Phi, w.left.a}) - xi));
                if ((phi - previous) * (w.right.phi - w.left.phi) < 0.0) ++e.fan_order;
                previous = phi;
            }
        } else {
            e.standing = std::max({e.standing, std::fabs(f_l - f_r), std::fabs(s.flux - f_l)});
            // Isaacson-Temple: no crossing of Gamma (meaningless on a side with a = 0, where every
            // state is critical).
            const double dL = w.left.phi - 0.5 * w.left.Phi, dR = w.right.phi - 0.5 * w.right.Phi;
            const double g = kRoundOff;
            if (L.a != 0.0 && R.a != 0.0 && ((dL < -g && dR > g) || (dL > g && dR < -g))) ++e.gamma_crossings;
        }
    }

    //--- Mass balance of each half-line over [-X, 0] and [0, X], X beyond every wave:
    // int_{-X}^0 phi dxi = X phi_L + f_L(phi_L) - F,   int_0^X phi dxi = X phi_R + F - f_R(phi_R).
    const double X = 2.0 * scale + 1.0;
    const double F_left = X * L.phi + flux_of(L) - profile_integral(s, -X, 0.0);
    const double F_right = profile_integral(s, 0.0, X) - X * R.phi + flux_of(R);
    e.mass_flux = std::max(std::fabs(F_left - F_eq63), std::fabs(F_right - F_eq63));
    e.eq63 = std::fabs(s.flux - F_eq63);
    return e;
}

}  // namespace granseg::verify
