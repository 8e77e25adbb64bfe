// Independent oracle for Table 1 (Sect. 3, Table 1): each Riemann problem is solved again
// on a fine grid with the jump replaced by smooth ramps of width w,
//   Phi(z) = Phi_L + (Phi_R - Phi_L) s(z/w),  T(z) = T_L + (T_R - T_L) s(z/w),
//   S(z) = S_L + (S_R - S_L) s(z/w),  a(z) = S(z) sqrt(T(z)),  s = C^1 smoothstep on [-1/2, 1/2],
// (sides given by a: T = a^2, S = sign(a)), a problem with a smooth spatially varying flux that
// the Engquist-Osher scheme with the exact face values Phi(z_f), a(z_f) solves consistently
// (written out below, f included: the oracle uses nothing of src/riemann but the exact solution
// and eq. (63) it is compared with). The time-averaged numerical flux through the face z = 0 over
// [t_end/2, t_end] is
// compared with the exact interface flux of src/riemann/riemann_solver.cpp for w = 1/100 ...
// 1/800 (h = w/16, so the grid is refined with w), and the states just outside the ramp with the
// exact profile there. Every case of Table 1, for T_L = T_R, T_L != T_R (one state with crossing
// flux curves per case), a_L, a_R < 0, and every sign class of a_L a_R <= 0.
// Assumption S2: the same oracle with the T ramp placed before the Phi ramp (staggered) converges
// to a different flux when a and Phi jump in opposite directions; eq. (63) is the limit of
// co-located ramps (docs/assumptions.md S2).
//
// Run: build/verification/verify_table1_oracle [--data DIR]   (a few seconds)
#include "harness/check_table.hpp"
#include "harness/program.hpp"
#include "riemann/riemann_sample.hpp"
#include "table1/table1_states.hpp"

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

using namespace granseg;
using namespace granseg::verify;

namespace {

constexpr double kTravel = 0.1;                               // |a|_max t_end: how far the fastest wave goes
constexpr double kWidths[] = {0.01, 0.005, 0.0025, 0.00125};  // ramp widths w, w/kTravel = 1/10 ... 1/80
constexpr int kCellsPerWidth = 16;                            // h = w/16
constexpr double kCfl = 0.9;                                  // dt max|f'| / h on the ramped grid
constexpr double kMargin = 0.05;                              // states well inside their region
// Tolerances at the finest width, each observed with a margin (the problem is self-similar: the
// errors depend on w/kTravel and h/w only).
// Both a != 0: the ramp settles to its steady profile well before t_end/2, after which the
// numerical flux is the same through every face of the ramp and equals the flux of the traces;
// the transient left in [t_end/2, t_end] decays like exp(-c t/w): observed <= 2e-10 |a|.
constexpr double kFluxTol = 1e-8;
// A side with a = 0: the ramp empties or fills at a rate a(z) that vanishes at its end, so the
// window average converges only at first order in w: observed 4.4e-4 |a| at w/kTravel = 1/80.
constexpr double kFluxTolZeroSide = 2.5e-3;
// The error must fall by at least 4 between the coarsest and the finest width (first order
// gives 8), unless it is at the round-off of the time average from the start.
constexpr double kReduction = 4.0;
// Round-off of a time average of O(|a|) fluxes over a few thousand steps.
constexpr double kRoundOffFloor = 1e-13;
// States next to the ramp against the exact profile there. A fan that touches z = 0 (cases C, D,
// E, F, J and mirrors) is centred, in the ramped problem, where the ramp ends (there f_min is
// extreme: the sonic point), so the numerical profile is the exact one shifted by up to w/2, plus
// first-order smearing over about two cells: allowed error (w/2 + 2h) |dphi/dz| + round-off.
constexpr double kTraceCells = 2.0;
// Where the exact profile is constant: the round-off a state accumulates over ~2000 steps.
constexpr double kProfileFloor = 1e-11;
// A side with a = 0 next to the ramp: no fan, but the slow filling or emptying of the ramp end
// (see kFluxTolZeroSide) leaves an error of first order in w: observed 2.6e-4.
constexpr double kTraceTolZeroSide = 2.5e-3;

double smoothstep(double x) {
    if (x <= -0.5) return 0.0;
    if (x >= 0.5) return 1.0;
    const double y = x + 0.5;
    return y * y * (3.0 - 2.0 * y);
}

double f(double phi, double Phi, double a) { return a * phi * (phi - Phi) / Phi; }  // eq. (49)

/// Engquist-Osher flux of f(.; Phi, a): f(0) + int_0^u max(f', 0) + int_0^v min(f', 0).
double engquist_osher(double u, double v, double Phi, double a) {
    const double theta = 0.5 * Phi, f_theta = f(theta, Phi, a);
    if (a > 0.0) return f(std::max(u, theta), Phi, a) + f(std::min(v, theta), Phi, a) - f_theta;
    if (a < 0.0) return f(std::min(u, theta), Phi, a) + f(std::max(v, theta), Phi, a) - f_theta;
    return 0.0;
}

/// The ramped problem: Phi ramps around z_Phi, T and S around z_T, both of width w.
struct Ramped {
    FluxSide L, R;
    double w, z_T, z_Phi;
    double Phi(double z) const { return L.Phi + (R.Phi - L.Phi) * smoothstep((z - z_Phi) / w); }
    double a(double z) const {
        const double s = smoothstep((z - z_T) / w);
        const double S = sign(L.a) + (sign(R.a) - sign(L.a)) * s, T = L.a * L.a + (R.a * R.a - L.a * L.a) * s;
        return S * std::sqrt(T);
    }
    static double sign(double a) { return (a > 0.0) - (a < 0.0); }
};

struct OracleRun {
    double flux = 0.0;  // time average over [t_end/2, t_end] through z = 0
    double t_end = 0.0;
    double z_left = 0.0, z_right = 0.0;  // cell centres just outside the ramps
    double phi_left = 0.0, phi_right = 0.0;
};

OracleRun solve_ramped(const Ramped& p) {
    const double h = p.w / kCellsPerWidth, a_max = std::max(std::fabs(p.L.a), std::fabs(p.R.a));
    const double ramp_lo = std::min(p.z_T, p.z_Phi) - 0.5 * p.w, ramp_hi = std::max(p.z_T, p.z_Phi) + 0.5 * p.w;
    const int N = static_cast<int>(std::ceil((kTravel + std::max(-ramp_lo, ramp_hi)) / h)) + 4;
    // Cells i = 0 .. 2N-1 on [(i-N) h, (i-N+1) h]; face j = 0 .. 2N at (j-N) h; face N is z = 0.
    std::vector<double> Phi_face(2 * N + 1), a_face(2 * N + 1), phi(2 * N), F(2 * N + 1);
    for (int j = 0; j <= 2 * N; ++j) Phi_face[j] = p.Phi((j - N) * h), a_face[j] = p.a((j - N) * h);
    for (int i = 0; i < 2 * N; ++i) {
        const double z = (i - N + 0.5) * h;
        phi[i] = (z < 0.0 ? p.L.phi / p.L.Phi : p.R.phi / p.R.Phi) * p.Phi(z);
    }
    OracleRun r;
    const int i_left = N + static_cast<int>(std::floor(ramp_lo / h)) - 3,
              i_right = N + static_cast<int>(std::ceil(ramp_hi / h)) + 2;
    r.z_left = (i_left - N + 0.5) * h;
    r.z_right = (i_right - N + 0.5) * h;
    if (a_max == 0.0) {  // nothing moves, the flux vanishes identically
        r.phi_left = phi[i_left], r.phi_right = phi[i_right];
        return r;
    }
    r.t_end = kTravel / a_max;
    double t = 0.0, window = 0.0, sum = 0.0;
    while (t < r.t_end) {
        double speed = a_max;  // max |f'| over the faces, for the states on both sides
        for (int j = 1; j < 2 * N; ++j)
            for (double u : {phi[j - 1], phi[j]}) speed = std::max(speed, std::fabs(a_face[j] * (2.0 * u / Phi_face[j] - 1.0)));
        const double dt = std::min(kCfl * h / speed, r.t_end - t);
        for (int j = 1; j < 2 * N; ++j) F[j] = engquist_osher(phi[j - 1], phi[j], Phi_face[j], a_face[j]);
        F[0] = engquist_osher(phi[0], phi[0], Phi_face[0], a_face[0]);  // zero-gradient ends, never reached
        F[2 * N] = engquist_osher(phi[2 * N - 1], phi[2 * N - 1], Phi_face[2 * N], a_face[2 * N]);
        for (int i = 0; i < 2 * N; ++i) phi[i] -= dt / h * (F[i + 1] - F[i]);
        if (t >= 0.5 * r.t_end) sum += F[N] * dt, window += dt;
        t += dt;
    }
    r.flux = sum / window;
    r.phi_left = phi[i_left], r.phi_right = phi[i_right];
    return r;
}

/// Errors of the co-located ramp at each width, against the exact solution, and at the finest
/// width how far the profile next to the ramp exceeds the allowed shift (kTraceCells).
struct Convergence {
    std::vector<double> flux_error, trace_error;
    double trace_excess = 0.0;
};

Convergence converge(const FluxSide& L, const FluxSide& R) {
    const RiemannSolution exact = solve_riemann(L, R);
    Convergence c;
    for (double w : kWidths) {
        const OracleRun r = solve_ramped({L, R, w, 0.0, 0.0});
        const double h = w / kCellsPerWidth;
        double error = 0.0, excess = 0.0;
        for (const auto& [z, phi] : {std::make_pair(r.z_left, r.phi_left), std::make_pair(r.z_right, r.phi_right)}) {
            const double xi = r.t_end > 0.0 ? z / r.t_end : (z < 0.0 ? -1.0 : 1.0), d = 1e-7;
            const double slope =
                r.t_end > 0.0 ? std::fabs(sample_phi(exact, xi + d) - sample_phi(exact, xi - d)) / (2 * d * r.t_end) : 0.0;
            const double e = std::fabs(phi - sample_phi(exact, xi));
            error = std::max(error, e);
            excess = std::max(excess, e - (0.5 * w + kTraceCells * h) * slope);
        }
        c.flux_error.push_back(std::fabs(r.flux - exact.flux));
        c.trace_error.push_back(error);
        c.trace_excess = excess;  // the last, finest width wins
    }
    return c;
}

std::string series(const std::vector<double>& e) {
    std::string s;
    char buf[64];
    for (std::size_t k = 0; k < e.size(); ++k) {
        std::snprintf(buf, sizeof buf, " %.1e", e[k]);
        s += buf;
    }
    s += "  rates";
    for (std::size_t k = 1; k < e.size(); ++k) {
        if (e[k - 1] > kRoundOffFloor && e[k] > kRoundOffFloor)
            std::snprintf(buf, sizeof buf, " %.1f", std::log2(e[k - 1] / e[k]));
        else
            std::snprintf(buf, sizeof buf, " -");
        s += buf;
    }
    return s;
}

void check_family(CheckTable& t, Family family, StateSampler& sampler) {
    const std::string tag = family_tag(family);
    const int per_group = family == Family::equal_T || family == Family::unequal_T ? 2 : 1;
    t.note(std::string("--- ") + family_name(family) + ": errors at w/travel = 1/10, 1/20, 1/40, 1/80 ---");
    long slow = 0, missing = 0;
    double trace = 0.0, trace_zero_side = 0.0;
    for (int group = 1; group <= group_count(family); ++group) {
        double worst = 0.0, scale = 0.0;
        bool zero_side = false;
        for (int k = 0; k < per_group; ++k) {
            std::pair<FluxSide, FluxSide> q;
            const bool crossing = family == Family::unequal_T && k == 0;
            if (!state_in_group(sampler, family, group, kMargin, crossing, q)) {
                ++missing;
                continue;
            }
            const auto& [L, R] = q;
            const Convergence c = converge(L, R);
            t.note("  " + group_name(family, group) + (crossing ? " (curves cross)" : "") +
                   "  |F_ramp - F|:" + series(c.flux_error));
            t.note("      profile next to the ramp:" + series(c.trace_error));
            worst = std::max(worst, c.flux_error.back());
            scale = std::max({scale, std::fabs(L.a), std::fabs(R.a)});
            zero_side = zero_side || L.a == 0.0 || R.a == 0.0;
            slow += c.flux_error.back() > std::max(c.flux_error.front() / kReduction, kRoundOffFloor);
            (L.a == 0.0 || R.a == 0.0 ? trace_zero_side : trace) =
                std::max(L.a == 0.0 || R.a == 0.0 ? trace_zero_side : trace, c.trace_excess);
        }
        t.at_most(tag + " " + group_name(family, group) + ": |F_ramp - F| at w = 1/800", worst,
                  (zero_side ? kFluxTolZeroSide : kFluxTol) * scale + kRoundOffFloor);
    }
    t.count(tag + " states not found inside their region", missing, 0);
    t.count(tag + " flux errors not reduced 4x from w = 1/100 to 1/800", slow, 0);
    t.at_most(tag + " profile next to the ramp: error - (w/2 + 2h)|phi_z|", trace, kProfileFloor);
    if (family == Family::mixed) t.at_most(tag + " same, next to a side with a = 0", trace_zero_side, kTraceTolZeroSide);
}

/// Assumption S2: with Q_L = (0.1, 0.4, a = 2), Q_R = (0.6, 0.7, a = 1), a Phi drops from 0.8 to
/// 0.4 in between if T jumps before Phi. Two interfaces of vanishing distance carry
/// max(f_up, f_M^min, f_down) with the middle curve f_M = f(.; Phi_L, a_R) (docs/sect3_riemann.md).
void check_staggered(CheckTable& t) {
    const FluxSide L{0.1, 0.4, 2.0}, R{0.6, 0.7, 1.0};
    const double F63 = modified_godunov_flux({L, R});
    const double f_up = f(std::max(L.phi, 0.5 * L.Phi), L.Phi, L.a), f_down = f(std::min(R.phi, 0.5 * R.Phi), R.Phi, R.a);
    const double F_composite = std::max({f_up, f_down, -0.25 * R.a * L.Phi});
    const double w = kWidths[3];
    t.note("--- assumption S2: Phi and T jump in opposite directions, Q_L = (0.1, 0.4, a 2), Q_R = (0.6, 0.7, a 1) ---");
    const OracleRun together = solve_ramped({L, R, w, 0.0, 0.0});
    const OracleRun T_first = solve_ramped({L, R, w, -w, w});
    const OracleRun Phi_first = solve_ramped({L, R, w, w, -w});
    t.near("S2 co-located ramps -> eq. (63)", together.flux, F63, kFluxTol * L.a);
    t.near("S2 Phi ramp, then T ramp -> eq. (63)", Phi_first.flux, F63, kFluxTol * L.a);
    t.near("S2 T ramp, then Phi ramp -> max(f_up, f_M^min, f_down)", T_first.flux, F_composite, kFluxTol * L.a);
    t.at_least("S2 |eq. (63) - that composite flux| (the order matters)", std::fabs(F63 - F_composite), 0.05);
}

}  // namespace

int main(int argc, char** argv) {
    return run_over_families(argc, argv, "Table 1: fine-grid oracle with ramps of shrinking width, four coefficient families",
                             20200047, check_family, check_staggered);
}
