#include "riemann/riemann_solver.hpp"

#include "core/error.hpp"
#include "core/format.hpp"
#include "riemann/flux_curves.hpp"

#include <cfloat>
#include <cmath>
#include <string>

namespace granseg {

namespace {

double f(const FluxSide& s, double phi) { return segregation_flux(phi, s.Phi, s.a); }

/// The interface traces and flux the solution is built from.
struct Connection {
    double F, phi_minus, phi_plus;
};

/// The wave of one flux curve (Phi, a) from phi_l (left) to phi_r (right). lambda_1 grows with
/// phi when a > 0, so phi_r > phi_l fans out (rarefaction) and phi_r < phi_l is a Lax shock; for
/// a < 0 the other way round.
Wave curve_wave(double phi_l, double phi_r, double Phi, double a) {
    const FluxSide l{phi_l, Phi, a}, r{phi_r, Phi, a};
    if (a * (phi_r - phi_l) > 0.0)
        return {WaveKind::rarefaction, l, r, segregation_speed(phi_l, Phi, a), segregation_speed(phi_r, Phi, a)};
    // Rankine-Hugoniot speed (f(phi_r) - f(phi_l))/(phi_r - phi_l) of the quadratic f.
    const double s = a * (phi_l + phi_r - Phi) / Phi;
    return {WaveKind::shock, l, r, s, s};
}

/// The trace of `side` at flux F on one side of Gamma: the side's own phi if it already lies
/// there with that flux (no wave), else the root of f = F on that side (flux_curves.hpp).
double trace(const FluxSide& side, double F, bool right_of_gamma) {
    const double theta = gamma_phi(side.Phi);
    const bool on_that_side = right_of_gamma ? side.phi >= theta : side.phi <= theta;
    if (on_that_side && f(side, side.phi) == F) return side.phi;
    return right_of_gamma ? phi_right_of_gamma(F, side.Phi, side.a) : phi_left_of_gamma(F, side.Phi, side.a);
}

//--- Convex fluxes (a_L, a_R > 0), the cases of Table 1.
// Which interface fluxes F can each side carry, with waves of the right sign (<= 0 on the left,
// >= 0 on the right) between its state and its trace?
//   left,  phi_L <= theta_L: every F in [f_L^min, 0], trace left of Gamma (a shock down to it or
//          a rarefaction up to it, at most up to theta_L, where lambda_1 = 0);
//   left,  phi_L >  theta_L: F in [f_L(phi_L), 0] with a trace left of Gamma (a shock), or
//          F = f_L(phi_L) with the trace phi_L itself (no wave);
//   right, phi_R >= theta_R: every F in [f_R^min, 0], trace right of Gamma;
//   right, phi_R <  theta_R: F in [f_R(phi_R), 0] with a trace right of Gamma (a shock), or
//          F = f_R(phi_R) with the trace phi_R itself.
// The standing wave joins the traces and must not cross Gamma (Isaacson-Temple): both traces on
// the same side, or one of them on Gamma. Four connections remain, each fixing F:
//   (i)   both left of Gamma, phi_plus = phi_R:          F = f_R(phi_R)
//   (ii)  both right of Gamma, phi_minus = phi_L:        F = f_L(phi_L)
//   (iii) phi_minus = theta_L on Gamma, phi_plus right:  F = f_L^min
//   (iv)  phi_plus = theta_R on Gamma, phi_minus left:   F = f_R^min
// In the interior of a region exactly one is admissible; on a boundary two are, with equal F.
Connection convex_connection(const FluxSide& L, const FluxSide& R) {
    const double theta_L = gamma_phi(L.Phi), theta_R = gamma_phi(R.Phi);
    const double f_L = f(L, L.phi), f_R = f(R, R.phi);
    const double fL_min = flux_extremum(L.Phi, L.a), fR_min = flux_extremum(R.Phi, R.a);
    const bool L_left = L.phi <= theta_L, R_right = R.phi >= theta_R;
    const double left_floor = L_left ? fL_min : f_L;    // lowest F with a left-of-Gamma trace
    const double right_floor = R_right ? fR_min : f_R;  // lowest F with a right-of-Gamma trace

    Connection found[4];
    int n = 0;
    if (R.phi <= theta_R && f_R >= left_floor) found[n++] = {f_R, trace(L, f_R, false), R.phi};    // (i)
    if (L.phi >= theta_L && f_L >= right_floor) found[n++] = {f_L, L.phi, trace(R, f_L, true)};    // (ii)
    if (L_left && fL_min >= right_floor) found[n++] = {fL_min, theta_L, trace(R, fL_min, true)};   // (iii)
    if (R_right && fR_min >= left_floor) found[n++] = {fR_min, trace(L, fR_min, false), theta_R};  // (iv)

    // Two admissible connections differ only by the rounding of f(theta) against -a Phi/4.
    const double tie = 16 * DBL_EPSILON * (L.a * L.Phi + R.a * R.Phi);
    if (n == 0) throw InvariantError("Riemann solver: no admissible connection (a bug)");
    for (int k = 1; k < n; ++k)
        if (std::fabs(found[k].F - found[0].F) > tie)
            throw InvariantError("Riemann solver: two admissible interface fluxes " + format_exact(found[0].F) + " and " +
                                 format_exact(found[k].F) + " (a bug)");
    return found[0];
}

//--- a_L a_R <= 0: F = 0 (docs/assumptions.md S1, S3).
// A side with a = 0 keeps its state (its flux vanishes identically). Otherwise its flux points
// away from z = 0 (a_L > 0 on the left, a_R < 0 on the right: the side empties, trace 0) or
// towards it (it fills, trace Phi), and one shock moving away from z = 0 joins state and trace.
// A state already at the other end (phi = Phi where the side empties, 0 where it fills) carries
// f = 0 too; it is still joined to the trace by a shock, of speed 0, so that the standing wave
// does not cross Gamma: both traces are 0 (both sides empty) or both full, or one side has a = 0.
double zero_flux_trace(const FluxSide& side, bool left_side) {
    if (side.a == 0.0) return side.phi;
    const bool points_away = left_side ? side.a > 0.0 : side.a < 0.0;
    return points_away ? 0.0 : side.Phi;
}

RiemannSolution assemble(const FluxSide& L, const FluxSide& R, const Connection& c) {
    RiemannSolution s;
    s.L = L;
    s.R = R;
    s.phi_minus = c.phi_minus;
    s.phi_plus = c.phi_plus;
    s.flux = c.F;
    if (c.phi_minus != L.phi) s.waves.push_back(curve_wave(L.phi, c.phi_minus, L.Phi, L.a));
    if (L.Phi != R.Phi || L.a != R.a)
        s.waves.push_back({WaveKind::standing, {c.phi_minus, L.Phi, L.a}, {c.phi_plus, R.Phi, R.a}, 0.0, 0.0});
    if (c.phi_plus != R.phi) s.waves.push_back(curve_wave(c.phi_plus, R.phi, R.Phi, R.a));
    return s;
}

//--- a_L, a_R < 0: mirror image. With z' = -z, d_t phi + d_z f = 0 becomes
// d_t phi + d_z' (-f) = 0 and -f(.; Phi, a) = f(.; Phi, -a): the convex problem with the sides
// swapped. Mapping back reverses the wave order and negates speeds and flux.
FluxSide flipped(const FluxSide& s) { return {s.phi, s.Phi, 0.0 - s.a}; }

RiemannSolution mirrored(const RiemannSolution& m) {
    RiemannSolution s;
    s.L = flipped(m.R);
    s.R = flipped(m.L);
    for (auto w = m.waves.rbegin(); w != m.waves.rend(); ++w)
        s.waves.push_back({w->kind, flipped(w->right), flipped(w->left), 0.0 - w->speed_right, 0.0 - w->speed_left});
    s.phi_minus = m.phi_plus;
    s.phi_plus = m.phi_minus;
    s.flux = 0.0 - m.flux;
    return s;
}

void require_state(const FluxSide& s, const char* side) {
    if (!(s.Phi > 0.0 && s.phi >= 0.0 && s.phi <= s.Phi && std::isfinite(s.Phi) && std::isfinite(s.a)))
        throw InputError(std::string("Riemann solver: state ") + side + " = (phi " + format_number(s.phi) + ", Phi " +
                         format_number(s.Phi) + ", a " + format_number(s.a) + ") is outside 0 <= phi <= Phi, Phi > 0");
}

}  // namespace

RiemannSolution solve_riemann(const FluxSide& L, const FluxSide& R) {
    require_state(L, "left");
    require_state(R, "right");
    if (L.a > 0.0 && R.a > 0.0) return assemble(L, R, convex_connection(L, R));
    if (L.a < 0.0 && R.a < 0.0) {
        const FluxSide mL = flipped(R), mR = flipped(L);
        return mirrored(assemble(mL, mR, convex_connection(mL, mR)));
    }
    return assemble(L, R, {0.0, zero_flux_trace(L, true), zero_flux_trace(R, false)});
}

const char* wave_kind_name(WaveKind kind) {
    switch (kind) {
        case WaveKind::shock:
            return "shock";
        case WaveKind::rarefaction:
            return "rarefaction";
        case WaveKind::standing:
            return "standing";
    }
    return "?";
}

}  // namespace granseg
