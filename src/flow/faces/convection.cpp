#include "flow/faces/convection.hpp"

#include "core/error.hpp"
#include "core/threads.hpp"
#include "flow/faces/hllc.hpp"
#include "flow/fields/face_balance.hpp"

#include <algorithm>
#include <cmath>

namespace granseg {

namespace {

/// Calls face(f, lo, hi) for every face of axis a next to an inside cell, f between cells lo
/// (below) and hi (above): x faces inside each row, y and z faces in the layers between rows. On
/// a wall the missing cell's index is the inside one's; on a periodic axis the boundary faces join
/// the first and the last cell.
template <class Face>
void for_each_face(const FlowMesh& mesh, int a, const Face& face) {
    const Grid& grid = mesh.grid;
    const std::size_t nx = grid.n[0], ny = grid.n[1];
    const long n_a = grid.n[a];
    const bool periodic = grid.periodic[a];
    if (a == 0) {  // faces inside each row, from the first inside cell's lower face to the last one's upper face
        parallel_for(mesh.parallel, mesh.rows, [&](std::size_t r) {
            if (mesh.row_lo[r] >= mesh.row_hi[r]) return;  // no inside cell in this row
            const std::size_t base = nx * r, f0 = (nx + 1) * r, last = nx - 1;
            // The faces on the domain boundary (i = 0, nx) join the first and the last cell of the
            // row (periodic) or are walls (the inside cell's index stands for the missing one).
            if (mesh.row_lo[r] == 0) face(f0, base + (periodic ? last : 0), base);
            if (mesh.row_hi[r] == static_cast<int>(nx)) face(f0 + nx, base + last, base + (periodic ? 0 : last));
            const int i0 = std::max(mesh.row_lo[r], 1), i1 = std::min(mesh.row_hi[r], static_cast<int>(nx) - 1);
            for (int i = i0; i <= i1; ++i) face(f0 + i, base + i - 1, base + i);
        });
        return;
    }
    // Axes y and z: the layer of faces between rows; a face row joins cell rows (j, k) and its
    // lower neighbour along the axis.
    const std::size_t layers = n_a + 1, others = a == 1 ? grid.n[2] : ny;
    parallel_for_pairs(mesh.parallel, layers, others, [&](std::size_t l, std::size_t o) {
        const std::size_t j_hi = a == 1 ? (l < static_cast<std::size_t>(n_a) ? l : periodic ? 0 : l - 1) : o;
        const std::size_t k_hi = a == 2 ? (l < static_cast<std::size_t>(n_a) ? l : periodic ? 0 : l - 1) : o;
        const std::size_t j_lo = a == 1 ? (l > 0 ? l - 1 : periodic ? n_a - 1 : 0) : o;
        const std::size_t k_lo = a == 2 ? (l > 0 ? l - 1 : periodic ? n_a - 1 : 0) : o;
        const std::size_t r_hi = j_hi + ny * k_hi, r_lo = j_lo + ny * k_lo;
        const int i0 = std::min(mesh.row_lo[r_hi], mesh.row_lo[r_lo]), i1 = std::max(mesh.row_hi[r_hi], mesh.row_hi[r_lo]);
        const std::size_t f0 = a == 1 ? nx * (l + (ny + 1) * o) : nx * (o + ny * l);
        for (int i = i0; i < i1; ++i) face(f0 + i, nx * r_lo + i, nx * r_hi + i);
    });
}

}  // namespace

// The face kernel is a lambda over the raw pointers set up here, inlined into the loops of both
// face layouts (for_each_face); split further, those pointers would travel as a dozen parameters.
void hllc_face_fluxes(const FlowMesh& mesh, int a, const FlowState& state, const CellClosures& cl, const Potential& potential,
                      const AxisLoads& loads, AxisFaces& out) {
    const int t1 = (a + 1) % 3, t2 = (a + 2) % 3;
    const double *Phi = state.Phi.data(), *un = state.u[a].data(), *ut1 = state.u[t1].data(), *ut2 = state.u[t2].data();
    const double *T = state.T.data(), *p = cl.p.data(), *cs = cl.c.data(), *psi = potential.cell.data();
    const double *load = loads.load.data(), *carry = loads.carry.data(), *psi_face = potential.face[a].data();
    const unsigned char* kind = mesh.face_kind[a].data();
    double *mass = out.mass.data(), *energy = out.energy.data(), *mom_hi = out.mom[a].data();
    double *mom_lo = out.mom_below.data(), *mom_t1 = out.mom[t1].data(), *mom_t2 = out.mom[t2].data();
    double *p_face = out.p.data(), *speed = out.speed.data();

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
    for_each_face(mesh, a, face);
}

void explicit_update(const FlowMesh& mesh, const FlowSettings& settings, const Frame& frame, const FlowSource& source, double t,
                     double dt, const FlowFaces& faces, FlowState& state) {
    const Vec3 g = frame.gravity_at(t);
    Vec3 g_source{};
    for (int a = 0; a < 3; ++a) g_source[a] = mesh.active[a] && !mesh.grid.periodic[a] ? 0.0 : g[a];
    const double angle = -2.0 * frame.omega * dt, ca = std::cos(angle), sa = std::sin(angle);
    const double Phi_vac = settings.Phi_vacuum, T_floor = settings.T_floor;
    const AxisWeights inv_h = axis_weights(mesh);
    const AxisFields M = axis_fields(faces, &AxisFaces::mass), Ef = axis_fields(faces, &AxisFaces::energy);
    // Momentum component b: the flux on a cell's upper face along b's own axis is the one seen from below.
    AxisFields mom_upper[3], mom_lower[3];
    for (int b = 0; b < 3; ++b)
        for (int a = 0; a < 3; ++a) {
            mom_lower[b][a] = faces[a].mom[b].data();
            mom_upper[b][a] = b == a ? faces[a].mom_below.data() : mom_lower[b][a];
        }
    double *Phi = state.Phi.data(), *E = state.E.data(), *T = state.T.data();
    double* m[3] = {state.m[0].data(), state.m[1].data(), state.m[2].data()};
    double* u[3] = {state.u[0].data(), state.u[1].data(), state.u[2].data()};
    const double *X = mesh.position[0].data(), *Y = mesh.position[1].data(), *Z = mesh.position[2].data();
    mesh.parallel_for_inside_cells([&](std::size_t c, int i, const AxisRow* ar) {
        const double dE = face_balance(Ef, inv_h, i, ar);
        double dm[3];
        for (int b = 0; b < 3; ++b) dm[b] = face_balance(mom_upper[b], mom_lower[b], inv_h, i, ar);
        const double Phi_start = Phi[c];
        Phi[c] = mass_balance(Phi_start, dt, M, inv_h, i, ar);  // the coupling identity (flow_solver.hpp)
        E[c] -= dt * dE;
        for (int b = 0; b < 3; ++b) m[b][c] += dt * (Phi_start * g_source[b] - dm[b]);
        if (source) {
            double rates[5];
            source(t, X[c], Y[c], Z[c], rates);
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

void transport_update(const FlowMesh& mesh, const FlowSettings& settings, double dt, const FlowFaces& faces, FlowState& state) {
    Frame still;  // no gravity and no rotation: the update of the fluxes alone
    still.gravity = 0.0;
    explicit_update(mesh, settings, still, FlowSource{}, 0.0, dt, faces, state);
}

void apply_mass_fluxes(const Grid& grid, const FaceFields& M, double dt, std::vector<double>& Phi) {
    apply_mass_fluxes(FlowMesh(grid), M, dt, Phi);
}

void apply_mass_fluxes(const FlowMesh& mesh, const FaceFields& M, double dt, std::vector<double>& Phi) {
    const Grid& grid = mesh.grid;
    AxisWeights inv_h = axis_weights(mesh);
    AxisFields fields{};
    for (int a = 0; a < 3; ++a) {
        if (M[a].empty())
            inv_h[a] = 0.0;  // nothing along this axis
        else if (M[a].size() != grid.faces(a))
            throw InputError("apply_mass_fluxes: M needs one value per face");
        fields[a] = M[a].data();
    }
    if (Phi.size() != grid.cells()) throw InputError("apply_mass_fluxes: Phi needs one value per cell");
    double* out = Phi.data();
    mesh.parallel_for_inside_cells(
        [&](std::size_t c, int i, const AxisRow* ar) { out[c] = mass_balance(out[c], dt, fields, inv_h, i, ar); });
}

}  // namespace granseg
