// FlowSolver, explicit part of a step: face potentials and fluxes (HLLC with hydrostatic
// reconstruction, walls as mirror states), the effective pressure of the transport coefficients,
// the time step, the conservative update of (Phi, Phi u, Phi T), and the body forces that are not
// carried by the potential (Coriolis, gravity along inactive or periodic axes, sources).
#include "flow/flow_solver.hpp"
#include "flow/hllc.hpp"

#include "core/error.hpp"
#include "core/format.hpp"

#include <algorithm>
#include <cmath>

namespace granseg {

namespace {
// The step is also bounded by kOutflowFraction * Phi / (outflow rate) in every cell, so that
// Phi_new >= (1 - kOutflowFraction) Phi_old > 0 for a cell with outflow, and the transported T
// and u_t stay convex combinations of old values (docs/flow_solver.md, positivity).
constexpr double kOutflowFraction = 0.9;
// And by kCompactionFraction * (Phi_rcp - Phi) / (net inflow rate): a step closes at most this
// share of a cell's gap to random close packing, so Phi < Phi_rcp holds without a cap (the HLLC
// waves are estimated from the states before the step and do not see the pressure diverge).
constexpr double kCompactionFraction = 0.5;
}  // namespace

void FlowSolver::face_potentials(int a) {
    const Vec3 g = frame_.gravity_at(t_);
    const double g_a = !grid_.periodic[a] ? g[a] : 0.0, w2 = frame_.omega * frame_.omega;
    const double centre = a == 0 ? frame_.x_c : frame_.z_c, h = grid_.h[a];
    const std::size_t nx = grid_.n[0];
    // Face potential: the mean of the two cells' potentials; a wall's ghost is the mirror cell.
    // On the domain boundary the mirror cell lies outside the grid: its potential differs from the
    // inside cell's by -g_a (+-h) and the change of the centrifugal term.
    auto ghost = [&](std::size_t c, double sign) {
        double d = -g_a * sign * h;
        if (a != 1) {
            const double r = position_[a][c] - centre, rs = r + sign * h;
            d -= 0.5 * w2 * (rs * rs - r * r);
        }
        return psi_[c] + d;
    };
    double* psi_face = psi_face_[a].data();
    const double* psi = psi_.data();
    const unsigned char* kind = face_kind_[a].data();
    // Each cell writes its upper face; the cells of the first layer also write their lower face.
#pragma omp parallel for schedule(static) if (parallel_)
    for (std::size_t r = 0; r < rows_; ++r) {
        const AxisRow ar = axis_row(a, r);
        const bool first_layer = a == 0 || (a == 1 ? r % grid_.n[1] == 0 : r < static_cast<std::size_t>(grid_.n[1]));
        for (int i = 0; i < static_cast<int>(nx); ++i) {
            const std::size_t c = nx * r + i, fl = ar.face0 + i, fu = fl + ar.face_step;
            const long lo = ar.lo_at(i), hi = ar.hi_at(i);
            psi_face[fu] = 0.5 * (psi[c] + (kind[fu] == kWallAbove && hi == 0 ? ghost(c, 1.0) : psi[c + hi]));
            if (first_layer && (a != 0 || i == 0))
                psi_face[fl] = 0.5 * ((kind[fl] == kWallBelow && lo == 0 ? ghost(c, -1.0) : psi[c + lo]) + psi[c]);
        }
    }
    // Loads pass down chains of unsupported cells along an axis with the weight
    // w = max(0, |g_a| - max_(b != a) |g_b|)/|g|: fully along gravity when it is aligned with the
    // axis (a stack of loose cells, dust on a partly filled cell), not at all when gravity is
    // diagonal; along a row across gravity a chain would make loose surface cells a strut that
    // leans on the wall instead of sliding down the slope. w varies continuously with the
    // direction of gravity as it turns in the drum.
    double g_other = 0.0, g_norm = 0.0;
    for (int b = 0; b < 3; ++b) {
        if (!active_[b] || grid_.periodic[b]) continue;
        g_norm += g[b] * g[b];
        if (b != a) g_other = std::max(g_other, std::fabs(g[b]));
    }
    const double weight = g_norm > 0.0 ? std::max(0.0, std::fabs(g_a) - g_other) / std::sqrt(g_norm) : 0.0;
    flow_loads(a, g_a, weight);
}

void FlowSolver::flow_loads(int a, double g_a, double weight) {
    // Per cell: `load`, the weight its downhill face carries beyond p + Phi |d_psi| (flow/hllc.hpp),
    // and `carry`, the pressure an unsupported cell passes on at its uphill face. A cell is
    // unsupported when p <= Phi rise (rise: potential rise to its uphill face); then its uphill
    // face carries what rests on it (the downhill face pressure of the cell above, if that cell
    // holds material) and its downhill face adds that to its own unsupported weight. Cells are
    // visited in the direction of gravity along the axis so that loads pass down chains of
    // unsupported cells (dust on a partly filled surface cell), scaled by `weight` per link.
    const std::size_t nx = grid_.n[0], ny = grid_.n[1];
    double *load = load_[a].data(), *carry = carry_[a].data(), *out = work_.data();
    const double *Phi = Phi_.data(), *p = p_.data(), *psi = psi_.data(), *psi_face = psi_face_[a].data();
    const double* co = Phi_co_.data();
    const unsigned char *in = inside_.data(), *kind = face_kind_[a].data();
    const double Phi_vac = settings_.Phi_vacuum;
    const int dir = weight == 0.0 ? 0 : g_a < 0.0 ? -1 : 1;  // sweep direction along the axis
    auto visit = [=](std::size_t c, std::size_t fl, std::size_t fu, long lo, long hi) __attribute__((always_inline)) {
        const double rise_lo = psi_face[fl] - psi[c], rise_hi = psi_face[fu] - psi[c];
        const bool up_hi = rise_hi > 0.0 && rise_lo <= 0.0, up_lo = rise_lo > 0.0 && rise_hi <= 0.0;
        const double rise = up_hi ? rise_hi : up_lo ? rise_lo : 0.0, fall = up_hi ? -rise_lo : up_lo ? -rise_hi : 0.0;
        const bool filled = in[c] && Phi[c] > Phi_vac;
        const bool unsupported = filled && (up_hi || up_lo) && p[c] <= Phi[c] * rise;
        // The cell above along the sweep is the uphill neighbour when it was visited just before.
        const bool from_hi = up_hi && dir < 0 && kind[fu] == kInterior, from_lo = up_lo && dir > 0 && kind[fl] == kInterior;
        const double arriving = from_hi ? out[c + hi] : from_lo ? out[c + lo] : 0.0;
        // It passes that on only while it and what rests on it would fit into the cell at the
        // loosest load-bearing packing Phi_co (arriving / (rise + fall) is the volume fraction the
        // material above would add): a partly filled surface cell with dust on it rests on the
        // cell below; loose material that fills the cell holds nothing up and compacts.
        const bool rests = (Phi[c] - co[c]) * (rise + fall) + arriving <= 0.0;
        carry[c] = unsupported && rests ? weight * arriving : 0.0;
        load[c] = filled ? unsupported_load(Phi[c], p[c], rise) + carry[c] : 0.0;
        out[c] = filled ? p[c] + Phi[c] * fall + load[c] : 0.0;
    };
    if (a == 0) {
#pragma omp parallel for schedule(static) if (parallel_)
        for (std::size_t r = 0; r < rows_; ++r) {
            const AxisRow ar = axis_row(0, r);
            for (int q = 0; q < static_cast<int>(nx); ++q) {
                const int i = dir < 0 ? static_cast<int>(nx) - 1 - q : q;
                visit(nx * r + i, ar.face0 + i, ar.face0 + i + 1, ar.lo_at(i), ar.hi_at(i));
            }
        }
        return;
    }
    // y and z: layers in the sweep order, vectorised along x in blocks of columns.
    const int n_a = grid_.n[a];
    const std::size_t others = a == 1 ? grid_.n[2] : ny, blocks = (nx + 31) / 32;
#pragma omp parallel for collapse(2) schedule(static) if (parallel_)
    for (std::size_t o = 0; o < others; ++o)
        for (std::size_t blk = 0; blk < blocks; ++blk)
            for (int q = 0; q < n_a; ++q) {
                const int layer = dir < 0 ? n_a - 1 - q : q;
                const std::size_t r = a == 1 ? layer + ny * o : o + ny * layer;
                const AxisRow ar = axis_row(a, r);
                const std::size_t i1 = std::min(nx, 32 * blk + 32);
#pragma omp simd
                for (std::size_t i = 32 * blk; i < i1; ++i)
                    visit(nx * r + i, ar.face0 + i, ar.face0 + i + ar.face_step, ar.lo, ar.hi);
            }
}

void FlowSolver::face_fluxes(int a) {
    const int t1 = (a + 1) % 3, t2 = (a + 2) % 3;
    const std::size_t nx = grid_.n[0], ny = grid_.n[1];
    const double *Phi = Phi_.data(), *un = u_[a].data(), *ut1 = u_[t1].data(), *ut2 = u_[t2].data();
    const double *T = T_.data(), *p = p_.data(), *cs = c_.data(), *psi = psi_.data(), *load = load_[a].data(),
                 *carry = carry_[a].data();
    const double* psi_face = psi_face_[a].data();
    const unsigned char* kind = face_kind_[a].data();
    double *mass = mass_flux_[a].data(), *energy = energy_flux_[a].data(), *mom_hi = mom_[a][a].data();
    double *mom_lo = mom_below_[a].data(), *mom_t1 = mom_[a][t1].data(), *mom_t2 = mom_[a][t2].data();
    double *p_face = p_face_[a].data(), *speed = speed_[a].data();
    const long n_a = grid_.n[a];
    const bool periodic = grid_.periodic[a];  // used by the x faces

    // Face f between cells lo (below) and hi (above); on a wall the missing cell index is the
    // inside one and its state is replaced by the mirror of the inside state.
    auto face = [=](std::size_t f, std::size_t lo, std::size_t hi) __attribute__((always_inline)) {
        const unsigned char k = kind[f];
        FaceState L{Phi[lo], un[lo], ut1[lo], ut2[lo], T[lo], p[lo], cs[lo]};
        FaceState R{Phi[hi], un[hi], ut1[hi], ut2[hi], T[hi], p[hi], cs[hi]};
        double corr_L = hydrostatic_reconstruction(L, psi_face[f] - psi[lo], load[lo], carry[lo]);
        double corr_R = hydrostatic_reconstruction(R, psi_face[f] - psi[hi], load[hi], carry[hi]);
        if (k == kWallAbove) R = mirror(L), corr_R = 0.0;
        if (k == kWallBelow) L = mirror(R), corr_L = 0.0;
        const FaceFlux F = hllc_flux(L, R);
        // Fluxes of mass, energy and tangential momentum vanish exactly on walls. (The face loops
        // are left scalar: at -O2, 2-wide vectors computing every branch of the HLLC flux were
        // slower than the branches, measured.)
        const double interior = k == kInterior ? 1.0 : 0.0, face = k == kNoFace ? 0.0 : 1.0;
        mass[f] = interior * F.mass;
        energy[f] = interior * F.energy;
        mom_t1[f] = interior * F.mom_t1;
        mom_t2[f] = interior * F.mom_t2;
        mom_hi[f] = face * (F.mom_n + corr_R);
        mom_lo[f] = face * (F.mom_n + corr_L);
        p_face[f] = face * std::max(0.0, F.p_star);
        speed[f] = face * std::max(std::fabs(L.u_n) + L.c, std::fabs(R.u_n) + R.c);
    };

    if (a == 0) {  // faces inside each row, from the first inside cell's lower face to the last one's upper face
#pragma omp parallel for schedule(static) if (parallel_)
        for (std::size_t r = 0; r < rows_; ++r) {
            if (row_lo_[r] >= row_hi_[r]) continue;  // no inside cell in this row
            const std::size_t base = nx * r, f0 = (nx + 1) * r, last = nx - 1;
            // The faces on the domain boundary (i = 0, nx) join the first and the last cell of the
            // row (periodic) or are walls (the inside cell's index stands for the missing one).
            if (row_lo_[r] == 0) face(f0, base + (periodic ? last : 0), base);
            if (row_hi_[r] == static_cast<int>(nx)) face(f0 + nx, base + last, base + (periodic ? 0 : last));
            const int i0 = std::max(row_lo_[r], 1), i1 = std::min(row_hi_[r], static_cast<int>(nx) - 1);
            for (int i = i0; i <= i1; ++i) face(f0 + i, base + i - 1, base + i);
        }
        return;
    }
    // Axes y and z: the layer of faces between rows; a face row joins cell rows (j, k) and its
    // lower neighbour along the axis.
    const std::size_t layers = n_a + 1, others = a == 1 ? grid_.n[2] : ny;
#pragma omp parallel for collapse(2) schedule(static) if (parallel_)
    for (std::size_t l = 0; l < layers; ++l)
        for (std::size_t o = 0; o < others; ++o) {
            const std::size_t j_hi = a == 1 ? (l < static_cast<std::size_t>(n_a) ? l : periodic ? 0 : l - 1) : o;
            const std::size_t k_hi = a == 2 ? (l < static_cast<std::size_t>(n_a) ? l : periodic ? 0 : l - 1) : o;
            const std::size_t j_lo = a == 1 ? (l > 0 ? l - 1 : periodic ? n_a - 1 : 0) : o;
            const std::size_t k_lo = a == 2 ? (l > 0 ? l - 1 : periodic ? n_a - 1 : 0) : o;
            const std::size_t r_hi = j_hi + ny * k_hi, r_lo = j_lo + ny * k_lo;
            const int i0 = std::min(row_lo_[r_hi], row_lo_[r_lo]), i1 = std::max(row_hi_[r_hi], row_hi_[r_lo]);
            const std::size_t f0 = a == 1 ? nx * (l + (ny + 1) * o) : nx * (o + ny * l);
            for (int i = i0; i < i1; ++i) face(f0 + i, nx * r_lo + i, nx * r_hi + i);
        }
}

double FlowSolver::effective_pressure_and_step(double t_end) {
    // Per inside cell, from the fluxes of its faces:
    //  - the effective pressure: eta, lambda and eps Phi are proportional to p at fixed T
    //    (eta = eta0 p/sqrt(T), eqs. 16-20); they are evaluated with the larger of the cell's own
    //    pressure and, per axis, the mean normal stress on its two faces (docs/flow_solver.md: a
    //    cell holding the free surface rests on the face below with its full weight although its
    //    own p(Phi) is nearly 0);
    //  - the time step: the CFL condition on the explicit waves |u_n| + c of its faces
    //    (first-order unsplit scheme), the outflow bound dt * outflow <= kOutflowFraction * Phi and
    //    the compaction bound dt * net inflow <= kCompactionFraction * (Phi_rcp - Phi).
    const std::size_t nx = grid_.n[0];
    double *eta = eta_.data(), *lambda = lambda_.data(), *epsPhi = epsPhi_.data();
    const double *p = p_.data(), *Phi = Phi_.data(), *rcp = Phi_rcp_.data();
    const unsigned char* in = inside_.data();
    const double* M[3] = {mass_flux_[0].data(), mass_flux_[1].data(), mass_flux_[2].data()};
    const double* P[3] = {p_face_[0].data(), p_face_[1].data(), p_face_[2].data()};
    const double* S[3] = {speed_[0].data(), speed_[1].data(), speed_[2].data()};
    double inv_h[3];
    for (int a = 0; a < 3; ++a) inv_h[a] = active_[a] ? 1.0 / grid_.h[a] : 0.0;
    double rate = 0.0, outflow_rate = 0.0, compaction_rate = 0.0;
#pragma omp parallel for reduction(max : rate, outflow_rate, compaction_rate) schedule(static) if (parallel_)
    for (std::size_t r = 0; r < rows_; ++r) {
        AxisRow ar[3];
        for (int a = 0; a < 3; ++a) ar[a] = axis_row(a, r);
        for (int i = row_lo_[r]; i < row_hi_[r]; ++i) {
            const std::size_t c = nx * r + i;
            if (!in[c]) continue;
            double p_eff = p[c], cfl = 0.0, out = 0.0, div = 0.0;
            for (int a = 0; a < 3; ++a) {
                if (inv_h[a] == 0.0) continue;
                const std::size_t fl = ar[a].face0 + i, fu = fl + ar[a].face_step;
                p_eff = std::max(p_eff, 0.5 * (P[a][fl] + P[a][fu]));
                cfl += std::max(S[a][fl], S[a][fu]) * inv_h[a];
                out += (std::max(0.0, M[a][fu]) + std::max(0.0, -M[a][fl])) * inv_h[a];
                div += (M[a][fu] - M[a][fl]) * inv_h[a];
            }
            const double scale = p[c] > 0.0 ? p_eff / p[c] : 0.0;
            eta[c] *= scale, lambda[c] *= scale, epsPhi[c] *= scale;
            rate = std::max(rate, cfl);
            if (out > 0.0) outflow_rate = std::max(outflow_rate, Phi[c] > 0.0 ? out / Phi[c] : INFINITY);
            if (div < 0.0) compaction_rate = std::max(compaction_rate, -div / (rcp[c] - Phi[c]));
        }
    }
    double dt = std::min(settings_.dt_max, t_end - t_);
    const double dt_cfl = rate > 0.0 ? settings_.cfl / rate : INFINITY;
    const double dt_outflow = outflow_rate > 0.0 ? kOutflowFraction / outflow_rate : INFINITY;
    const double dt_compaction = compaction_rate > 0.0 ? kCompactionFraction / compaction_rate : INFINITY;
    dt = std::min({dt, dt_cfl, dt_outflow, dt_compaction});
    if (!(dt >= settings_.dt_min) && t_end - t_ > settings_.dt_min) {
        double c_max = 0.0, Phi_at = 0.0;
        for (std::size_t c : inside_cells_)
            if (c_[c] > c_max) c_max = c_[c], Phi_at = Phi_[c];
        const std::string cause =
            dt == dt_compaction ? "the compaction bound: the bed is compacted towards Phi_rcp faster than this resolution can follow"
            : dt == dt_outflow  ? "the outflow bound: a cell loses more than its mass (outflow rate " + format_number(outflow_rate) + " 1/s)"
                                : "the CFL condition";
        throw InvariantError("flow: time step " + format_number(dt) + " s fell below dt_min = " +
                             format_number(settings_.dt_min) + " s at t = " + format_number(t_) + " s, set by " + cause +
                             " (largest sound speed c = " + format_number(c_max) + " m/s at Phi = " + format_number(Phi_at, 8) + ")");
    }
    return dt;
}

void FlowSolver::explicit_update(double dt) {
    // Conservative update of (Phi, Phi u, Phi T) from the face fluxes; then the body forces not
    // carried by the potential: gravity along inactive or periodic axes (explicit), optional
    // sources, and Coriolis, du/dt = 2 omega (u_z, -u_x), a rotation of (u_x, u_z) by -2 omega dt
    // (exact); finally the primitives u and T for the implicit steps.
    const Vec3 g = frame_.gravity_at(t_);
    Vec3 g_source{};
    for (int a = 0; a < 3; ++a) g_source[a] = active_[a] && !grid_.periodic[a] ? 0.0 : g[a];
    const double angle = -2.0 * frame_.omega * dt, ca = std::cos(angle), sa = std::sin(angle);
    const double Phi_vac = settings_.Phi_vacuum, T_floor = settings_.T_floor;
    double inv_h[3];
    for (int a = 0; a < 3; ++a) inv_h[a] = active_[a] ? 1.0 / grid_.h[a] : 0.0;
    const double* M[3] = {mass_flux_[0].data(), mass_flux_[1].data(), mass_flux_[2].data()};
    const double* Ef[3] = {energy_flux_[0].data(), energy_flux_[1].data(), energy_flux_[2].data()};
    const double* below[3] = {mom_below_[0].data(), mom_below_[1].data(), mom_below_[2].data()};
    const double* mom[3][3];
    for (int a = 0; a < 3; ++a)
        for (int b = 0; b < 3; ++b) mom[a][b] = mom_[a][b].data();
    double *Phi = Phi_.data(), *E = E_.data(), *T = T_.data(), *m[3] = {m_[0].data(), m_[1].data(), m_[2].data()};
    double* u[3] = {u_[0].data(), u_[1].data(), u_[2].data()};
    const double *before = Phi_before_.data(), *X = position_[0].data(), *Y = position_[1].data(), *Z = position_[2].data();
    for_inside_cells([&](std::size_t c, int i, const AxisRow* ar) {
        double dPhi = 0.0, dE = 0.0, dm[3] = {0.0, 0.0, 0.0};
        for (int a = 0; a < 3; ++a) {
            if (inv_h[a] == 0.0) continue;
            const std::size_t fl = ar[a].face0 + i, fu = fl + ar[a].face_step;
            dPhi += (M[a][fu] - M[a][fl]) * inv_h[a];
            dE += (Ef[a][fu] - Ef[a][fl]) * inv_h[a];
            for (int b = 0; b < 3; ++b) dm[b] += ((b == a ? below[a][fu] : mom[a][b][fu]) - mom[a][b][fl]) * inv_h[a];
        }
        Phi[c] = before[c] - dt * dPhi;  // the coupling identity (flow_solver.hpp)
        E[c] -= dt * dE;
        for (int b = 0; b < 3; ++b) m[b][c] += dt * (before[c] * g_source[b] - dm[b]);
        if (source_) {
            double rates[5];
            source_(t_, X[c], Y[c], Z[c], rates);
            Phi[c] += dt * rates[0];
            for (int b = 0; b < 3; ++b) m[b][c] += dt * rates[1 + b];
            E[c] += dt * rates[4];
        }
        const bool empty = Phi[c] <= Phi_vac;
        const double inv = empty ? 0.0 : 1.0 / Phi[c];
        const double ux = m[0][c] * inv, uz = m[2][c] * inv;
        u[0][c] = ca * ux - sa * uz;
        u[1][c] = m[1][c] * inv;
        u[2][c] = sa * ux + ca * uz;
        T[c] = empty ? T_floor : E[c] * inv;
    });
}

}  // namespace granseg
