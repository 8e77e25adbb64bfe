#include "flow/faces/semi_implicit_faces.hpp"

#include "flow/faces/hllc.hpp"
#include "flow/faces/transport_flux.hpp"
#include "flow/fields/face_balance.hpp"
#include "transport/muscl_hancock.hpp"

#include <algorithm>
#include <cmath>

namespace granseg {

namespace {
/// A face whose mass leaves a cell with less than donor/kDonorExcess gets the smaller donor and
/// the solve is repeated; below that the outflow bound (flow/time_step.hpp) is the guard.
constexpr double kDonorExcess = 1.1;

/// The state of cell c for the faces of `axis` (normal and tangential velocity components).
FaceState face_state(const FlowState& s, const CellClosures* cl, int a, std::size_t c) {
    return {s.Phi[c], s.u[a][c], s.u[(a + 1) % 3][c], s.u[(a + 2) % 3][c], s.T[c], cl ? cl->p[c] : 0.0, cl ? cl->c[c] : 0.0};
}

/// The mass-weighted mean (Phi_lo x_lo + Phi_hi x_hi)/(Phi_lo + Phi_hi) (the plain mean without mass).
double mass_mean(double Phi_lo, double Phi_hi, double x_lo, double x_hi) {
    const double mass = Phi_lo + Phi_hi;
    return mass > 0.0 ? (Phi_lo * x_lo + Phi_hi * x_hi) / mass : 0.5 * (x_lo + x_hi);
}

/// The share Phi_lo/(Phi_lo + Phi_hi) of the lower cell (1/2 when both are empty).
double mass_share(double Phi_lo, double Phi_hi) {
    const double mass = Phi_lo + Phi_hi;
    return mass > 0.0 ? Phi_lo / mass : 0.5;
}

/// The face pressure that gives each cell the share Phi_cell/(Phi_lo + Phi_hi) of P_lo - P_hi.
double face_pressure(double Phi_lo, double Phi_hi, double P_lo, double P_hi) { return mass_mean(Phi_hi, Phi_lo, P_lo, P_hi); }
}  // namespace

void pressure_faces(const FlowMesh& mesh, int a, double gravity, const FlowState& state, const CellClosures& cl,
                    const Potential& potential, const AxisLoads& loads, AxisPressureFaces& pf, AxisFaces& faces) {
    const double *psi = potential.cell.data(), *psi_face = potential.face[a].data();
    const double *load = loads.load.data(), *carry = loads.carry.data(), h = mesh.grid.h[a];
    mesh.parallel_for_faces(a, [&](const MeshFace& F) {
        const std::size_t f = F.f, lo = F.lo, hi = F.hi;
        FaceState L = face_state(state, &cl, a, lo), R = face_state(state, &cl, a, hi);
        if (F.kind != kWallBelow) hydrostatic_reconstruction(L, psi_face[f] - psi[lo], load[lo], carry[lo]);
        if (F.kind != kWallAbove) hydrostatic_reconstruction(R, psi_face[f] - psi[hi], load[hi], carry[hi]);
        pf.p_lo[f] = L.p, pf.p_hi[f] = R.p;
        pf.reversed[f] = 0;
        const bool dilute = L.Phi < 0.5 * cl.Phi_co[lo] && R.Phi < 0.5 * cl.Phi_co[hi];
        const double D = F.kind == kInterior ? L.p - R.p : 0.0, cap = 2.0 * gravity * h * 0.5 * (L.Phi + R.Phi);
        pf.force[f] = dilute ? std::max(-cap, std::min(cap, D)) : D;
        faces.p[f] = std::max(0.0, F.kind == kInterior    ? face_pressure(L.Phi, R.Phi, L.p, R.p)
                                   : F.kind == kWallAbove ? L.p
                                                          : R.p);
    });
}

void predictor_faces(const FlowMesh& mesh, int a, double dt, const FlowState& state, const CellClosures& cl,
                     const AxisPressureFaces& pf, AxisFaces& out) {
    const int t1 = (a + 1) % 3, t2 = (a + 2) % 3;
    const double h = mesh.grid.h[a];
    mesh.parallel_for_faces(a, [&](const MeshFace& F) {
        const std::size_t f = F.f, lo = F.lo, hi = F.hi;
        // Each side's p' plus its correction p - p' is its own p: the face fluxes are p less the
        // side's share of the (limited) face force, so a cell's net force is its shares of D alone,
        // exactly 0 where D = 0 (no rounding of p' + (p - p') to move a bed at rest).
        double P_lo, P_hi;
        if (F.kind == kInterior) {
            const double s_lo = mass_share(state.Phi[lo], state.Phi[hi]);
            P_lo = cl.p[lo] - s_lo * pf.force[f];
            P_hi = cl.p[hi] + (1.0 - s_lo) * pf.force[f];
        } else {  // a wall: the inside cell's p plus the impedance of its motion towards the wall
            const bool above = F.kind == kWallAbove;
            const std::size_t c = above ? lo : hi;
            const double towards = std::max(0.0, above ? state.u[a][c] : -state.u[a][c]);
            P_lo = P_hi = cl.p[c] + state.Phi[c] * cl.c[c] * towards / (1.0 + cl.c[c] * dt / h);
        }
        out.mass[f] = out.energy[f] = out.mom[t1][f] = out.mom[t2][f] = 0.0;
        out.mom[a][f] = P_hi;
        out.mom_below[f] = P_lo;
    });
}

void face_force_part(const FlowMesh& mesh, double dt, const FlowState& state, const FlowFaces& faces,
                     std::array<std::vector<double>, 3>& A) {
    const double* Phi = state.Phi.data();
    mesh.parallel_for_inside_cells([&](std::size_t c, int i, const AxisRow* ar) {
        for (int b = 0; b < 3; ++b) {
            AxisWeights w{};  // axis b alone: the predictor's faces carry no tangential momentum
            w[b] = mesh.active[b] ? dt / mesh.grid.h[b] : 0.0;
            AxisFields upper{}, lower{};
            upper[b] = faces[b].mom_below.data(), lower[b] = faces[b].mom[b].data();
            A[b][c] = Phi[c] > 0.0 ? -face_balance(upper, lower, w, i, ar) / Phi[c] : 0.0;
        }
    });
}

namespace {
/// Whether material can cross an interior face: either of its cells holds more than Phi_vacuum.
bool open_face(const MeshFace& F, const double* Phi, double Phi_vac) {
    return F.kind == kInterior && std::max(Phi[F.lo], Phi[F.hi]) > Phi_vac;
}
}  // namespace

void face_velocity_predictor(const FlowMesh& mesh, const FlowSettings& settings, int a, double dt, const FlowState& state,
                             const CellClosures& closures, const std::array<std::vector<double>, 3>& A, AxisPressureFaces& pf) {
    const double h = mesh.grid.h[a], Phi_vac = settings.Phi_vacuum;
    const double *Phi = state.Phi.data(), *u = state.u[a].data(), *acc = A[a].data();
    const double *Phi_co = closures.Phi_co.data(), *c = closures.c.data();
    mesh.parallel_for_faces(a, [&](const MeshFace& F) {
        const std::size_t f = F.f, lo = F.lo, hi = F.hi;
        if (!open_face(F, Phi, Phi_vac)) {
            pf.predictor[f] = pf.smoothing[f] = 0.0;
            return;
        }
        // The mass-weighted mean; but a donor holding (almost) nothing moves its material at its
        // own velocity (upwind), so dust left behind by a moving cell is not dragged along (it
        // would feed that cell's velocity back to it with no friction in between). Dust moving
        // away from the face while the other cell moves away too opens a gap: no flow (its own
        // velocity would carry the other cell's material after it).
        const double mean = mass_mean(Phi[lo], Phi[hi], u[lo], u[hi]);
        const std::size_t up = mean > 0.0 ? lo : hi;
        const double Phi_f = 0.5 * (Phi[lo] + Phi[hi]);
        // The smoothing: tau times the face's compact acceleration D/(h Phi_f) less the cells'
        // accelerations interpolated to the face (A/dt: the force part per unit time).
        const double compact = pf.force[f] / (h * Phi_f), interpolated = mass_mean(Phi[lo], Phi[hi], acc[lo], acc[hi]) / dt;
        const bool dust = is_dust(Phi[up], Phi_co[up]);
        pf.smoothing[f] = dust ? 0.0 : smoothing_time(settings, h, std::max(c[lo], c[hi]), dt) * (compact - interpolated);
        pf.predictor[f] = dust ? (u[up] * mean > 0.0 ? u[up] : 0.0) : mean + pf.smoothing[f];
    });
}

void face_donors(const FlowMesh& mesh, const FlowSettings& settings, int a, double dt, const FlowState& state,
                 const CellClosures& closures, const MusclHancock* reconstruction, AxisPressureFaces& pf) {
    const double h = mesh.grid.h[a], Phi_vac = settings.Phi_vacuum;
    const double *Phi = state.Phi.data(), *Phi_co = closures.Phi_co.data();
    const double* from_lower = reconstruction ? reconstruction->from_lower()[a].data() : nullptr;
    const double* from_upper = reconstruction ? reconstruction->from_upper()[a].data() : nullptr;
    mesh.parallel_for_faces(a, [&](const MeshFace& F) {
        const std::size_t f = F.f, lo = F.lo, hi = F.hi;
        if (!open_face(F, Phi, Phi_vac)) {
            pf.coupling[f] = pf.donor[f] = pf.flux[f] = 0.0;
            return;
        }
        // What each cell gives the face: its Phi (donor cell), or its reconstruction; a face with
        // dust on either side is first order (dust takes its velocity from the mass that enters it).
        const bool dust_lo = is_dust(Phi[lo], Phi_co[lo]), dust_hi = is_dust(Phi[hi], Phi_co[hi]);
        const bool reconstructed = from_lower && !dust_lo && !dust_hi;
        const double value_lo = reconstructed ? from_lower[f] : Phi[lo];
        const double value_hi = reconstructed ? from_upper[f] : Phi[hi];
        const double U = pf.predictor[f];
        const bool careful = pf.reversed[f] || U == 0.0;
        const double donor = careful ? std::min(value_lo, value_hi) : U > 0.0 ? value_lo : value_hi;
        pf.value_lo[f] = value_lo, pf.value_hi[f] = value_hi;
        pf.donor[f] = donor;
        pf.flux[f] = donor * U;
        // Between two dust cells the face stays explicit (dry face): the pressure increments there
        // are only an extension of their neighbours' and would push on almost no mass.
        pf.coupling[f] = dust_lo && dust_hi ? 0.0 : (dt / h) * (dt / h) * donor / (0.5 * (Phi[lo] + Phi[hi]));
    });
}

void explicit_mass_change(const FlowMesh& mesh, double dt, const PressureFaces& pf, std::vector<double>& change) {
    const AxisFields flux = axis_fields(pf, &AxisPressureFaces::flux);
    const AxisWeights rate = axis_weights(mesh, dt);
    double* r = change.data();
    mesh.parallel_for_inside_cells([&](std::size_t c, int i, const AxisRow* ar) { r[c] = -face_balance(flux, rate, i, ar); });
}

long mark_reversed_faces(const FlowMesh& mesh, int a, const AxisFaces& faces, AxisPressureFaces& pf) {
    long marked = 0;
    for (const MeshFace& F : mesh.faces[a]) {
        const std::size_t f = F.f;
        if (F.kind != kInterior || pf.reversed[f] || pf.donor[f] == 0.0) continue;
        const double M = faces.mass[f], source = M > 0.0 ? pf.value_lo[f] : pf.value_hi[f];
        if (M != 0.0 && pf.donor[f] > kDonorExcess * source) pf.reversed[f] = 1, ++marked;
    }
    return marked;
}

void corrected_face_velocities(const FlowMesh& mesh, int a, double dt, const FlowState& state, const CellClosures& closures,
                               const AxisPressureFaces& pf, const std::vector<double>& dp, AxisFaces& out) {
    const double h = mesh.grid.h[a], *Phi = state.Phi.data(), *Phi_co = closures.Phi_co.data();
    mesh.parallel_for_faces(a, [&](const MeshFace& F) {
        const std::size_t f = F.f, lo = F.lo, hi = F.hi;
        double U = 0.0;
        if (F.kind == kInterior)
            U = pf.predictor[f] + (pf.coupling[f] > 0.0 ? dt * (dp[lo] - dp[hi]) / (h * 0.5 * (Phi[lo] + Phi[hi])) : 0.0);
        const std::size_t from = U > 0.0 ? lo : hi;
        out.mass[f] = pf.donor[f] * U;
        out.speed[f] = is_dust(Phi[from], Phi_co[from]) ? 0.0 : std::fabs(U);
    });
}

void cap_dust_outflow(const FlowMesh& mesh, double dt, const FlowState& state, const CellClosures& closures,
                      std::vector<double>& scale, FlowFaces& faces) {
    const AxisWeights rate = axis_weights(mesh, dt);
    const AxisFields M = axis_fields(faces, &AxisFaces::mass);
    const double *Phi = state.Phi.data(), *Phi_co = closures.Phi_co.data();
    double* s = scale.data();
    mesh.parallel_for_inside([&](std::size_t c) { s[c] = 1.0; });
    mesh.parallel_for_inside_cells([&](std::size_t c, int i, const AxisRow* ar) {
        if (!is_dust(Phi[c], Phi_co[c])) return;
        const double out = face_outflow(M, rate, i, ar);  // the share of Phi that leaves in this step
        if (out > kDustOutflow * Phi[c]) s[c] = kDustOutflow * Phi[c] / out;
    });
    for (int a = 0; a < 3; ++a)
        if (mesh.active[a])
            mesh.parallel_for_faces(a, [&](const MeshFace& F) {
                double& M = faces[a].mass[F.f];
                M *= s[M > 0.0 ? F.lo : F.hi];
            });
}

void volume_fraction_after(const FlowMesh& mesh, double dt, const std::vector<double>& Phi, const FlowFaces& faces,
                           std::vector<double>& Phi_after) {
    const AxisFields M = axis_fields(faces, &AxisFaces::mass);
    const AxisWeights inv_h = axis_weights(mesh);
    const double* before = Phi.data();
    double* after = Phi_after.data();
    mesh.parallel_for_inside_cells(
        [&](std::size_t c, int i, const AxisRow* ar) { after[c] = mass_balance(before[c], dt, M, inv_h, i, ar); });
}

void semi_implicit_face_fluxes(const FlowMesh& mesh, int a, const FlowState& state, const AxisPressureFaces& pf,
                               const std::vector<double>& dp, const std::vector<double>& Phi_after, AxisFaces& out) {
    const int t1 = (a + 1) % 3, t2 = (a + 2) % 3;
    mesh.parallel_for_faces(a, [&](const MeshFace& F) {
        const std::size_t f = F.f, lo = F.lo, hi = F.hi;
        const FaceState L = face_state(state, nullptr, a, lo), R = face_state(state, nullptr, a, hi);
        double P_lo = dp[lo], P_hi = dp[hi];  // walls: the inside cell's increment, no force
        if (F.kind == kInterior && pf.coupling[f] > 0.0) {
            // Face pressures as seen by each side: its share of the increment force, by the masses
            // the two cells hold at the end of the step.
            const double force = dp[lo] - dp[hi], s_lo = mass_share(Phi_after[lo], Phi_after[hi]);
            P_lo = dp[lo] - s_lo * force;
            P_hi = dp[hi] + (1.0 - s_lo) * force;
        }
        const FaceFlux G = transport_flux(L, R, out.mass[f], 0.0);
        out.mass[f] = G.mass, out.energy[f] = G.energy;
        out.mom[t1][f] = G.mom_t1, out.mom[t2][f] = G.mom_t2;
        out.mom[a][f] = G.mom_n + P_hi;
        out.mom_below[f] = G.mom_n + P_lo;
    });
}

}  // namespace granseg
