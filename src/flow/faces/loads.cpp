#include "flow/faces/loads.hpp"

#include "core/threads.hpp"
#include "flow/faces/hllc.hpp"

#include <algorithm>
#include <cmath>

namespace granseg {

void cell_potential(const FlowMesh& mesh, const Frame& frame, double t, std::vector<double>& psi_out) {
    const Grid& grid = mesh.grid;
    const Vec3 g = frame.gravity_at(t);
    // Potential psi = -g . x over the bounded active axes, minus the centrifugal potential.
    std::array<double, 3> g_pot{};
    for (int a = 0; a < 3; ++a) g_pot[a] = mesh.active[a] && !grid.periodic[a] ? g[a] : 0.0;
    const double w2 = frame.omega * frame.omega, x_c = frame.x_c, z_c = frame.z_c;
    const std::size_t cells = grid.cells();
    const double *X = mesh.position[0].data(), *Y = mesh.position[1].data(), *Z = mesh.position[2].data();
    double* psi = psi_out.data();
    parallel_for(mesh.parallel, cells, [&](std::size_t c) {
        const double rx = X[c] - x_c, rz = Z[c] - z_c;
        psi[c] = -(g_pot[0] * X[c] + g_pot[1] * Y[c] + g_pot[2] * Z[c]) - 0.5 * w2 * (rx * rx + rz * rz);
    });
}

void face_potential(const FlowMesh& mesh, const Frame& frame, double t, int a, const std::vector<double>& psi_cell,
                    std::vector<double>& psi_face_out) {
    const Grid& grid = mesh.grid;
    const Vec3 g = frame.gravity_at(t);
    const double g_a = !grid.periodic[a] ? g[a] : 0.0, w2 = frame.omega * frame.omega;
    const double centre = a == 0 ? frame.x_c : frame.z_c, h = grid.h[a];
    const std::size_t nx = grid.n[0];
    // On the domain boundary the mirror cell lies outside the grid: its potential differs from the
    // inside cell's by -g_a (+-h) and the change of the centrifugal term.
    auto ghost = [&](std::size_t c, double sign) {
        double d = -g_a * sign * h;
        if (a != 1) {
            const double r = mesh.position[a][c] - centre, rs = r + sign * h;
            d -= 0.5 * w2 * (rs * rs - r * r);
        }
        return psi_cell[c] + d;
    };
    double* psi_face = psi_face_out.data();
    const double* psi = psi_cell.data();
    const unsigned char* kind = mesh.face_kind[a].data();
    // Each cell writes its upper face; the cells of the first layer also write their lower face.
    parallel_for(mesh.parallel, mesh.rows, [&](std::size_t r) {
        const AxisRow ar = mesh.axis_row(a, r);
        const bool first_layer = a == 0 || (a == 1 ? r % grid.n[1] == 0 : r < static_cast<std::size_t>(grid.n[1]));
        for (int i = 0; i < static_cast<int>(nx); ++i) {
            const std::size_t c = nx * r + i, fl = ar.face0 + i, fu = fl + ar.face_step;
            const long lo = ar.lo_at(i), hi = ar.hi_at(i);
            psi_face[fu] = 0.5 * (psi[c] + (kind[fu] == kWallAbove && hi == 0 ? ghost(c, 1.0) : psi[c + hi]));
            if (first_layer && (a != 0 || i == 0))
                psi_face[fl] = 0.5 * ((kind[fl] == kWallBelow && lo == 0 ? ghost(c, -1.0) : psi[c + lo]) + psi[c]);
        }
    });
}

// Longer than most functions, for a reason: the cell kernel is a lambda over the raw pointers and
// the sweep direction set up here, inlined into the loops of both layouts below (along x inside
// rows, along y and z across rows in blocks of columns).
namespace {

/// Loads pass down chains of unsupported cells along axis a with the weight
/// w = max(0, |g_a| - max_(b != a) |g_b|)/|g|: fully along gravity when it is aligned with the
/// axis (a stack of loose cells, dust on a partly filled cell), not at all when gravity is
/// diagonal; along a row across gravity a chain would make loose surface cells a strut that
/// leans on the wall instead of sliding down the slope. w varies continuously with the
/// direction of gravity as it turns in the drum. `g_a`: gravity along a (0 on a periodic axis).
double chain_weight(const FlowMesh& mesh, const Vec3& g, double g_a, int a) {
    double g_other = 0.0, g_norm = 0.0;
    for (int b = 0; b < 3; ++b) {
        if (!mesh.active[b] || mesh.grid.periodic[b]) continue;
        g_norm += g[b] * g[b];
        if (b != a) g_other = std::max(g_other, std::fabs(g[b]));
    }
    return g_norm > 0.0 ? std::max(0.0, std::fabs(g_a) - g_other) / std::sqrt(g_norm) : 0.0;
}

}  // namespace

// Per cell: `load`, the weight its downhill face carries beyond p + Phi |d_psi| (flow/faces/hllc.hpp),
// and `carry`, the pressure an unsupported cell passes on at its uphill face. A cell is
// unsupported when p <= Phi rise (rise: potential rise to its uphill face); then its uphill
// face carries what rests on it (the downhill face pressure of the cell above, if that cell
// holds material) and its downhill face adds that to its own unsupported weight. Cells are
// visited in the direction of gravity along the axis so that loads pass down chains of
// unsupported cells (dust on a partly filled surface cell), scaled by chain_weight per link.
void unsupported_loads(const FlowMesh& mesh, const FlowSettings& settings, const Frame& frame, double t, int a,
                       const FlowState& state, const CellClosures& closures, const Potential& potential, AxisLoads& loads) {
    const Grid& grid = mesh.grid;
    const Vec3 g = frame.gravity_at(t);
    const double g_a = !grid.periodic[a] ? g[a] : 0.0;
    const double weight = chain_weight(mesh, g, g_a, a);
    const std::size_t nx = grid.n[0], ny = grid.n[1];
    double *load = loads.load.data(), *carry = loads.carry.data(), *downhill = loads.downhill.data();
    const double *Phi = state.Phi.data(), *p = closures.p.data(), *psi = potential.cell.data();
    const double *psi_face = potential.face[a].data(), *co = closures.Phi_co.data();
    const unsigned char *in = mesh.inside.data(), *kind = mesh.face_kind[a].data();
    const double Phi_vac = settings.Phi_vacuum;
    const int dir = weight == 0.0 ? 0 : g_a < 0.0 ? -1 : 1;  // sweep direction along the axis
    auto visit = [=](std::size_t c, std::size_t fl, std::size_t fu, long lo, long hi) __attribute__((always_inline)) {
        const double rise_lo = psi_face[fl] - psi[c], rise_hi = psi_face[fu] - psi[c];
        const bool up_hi = rise_hi > 0.0 && rise_lo <= 0.0, up_lo = rise_lo > 0.0 && rise_hi <= 0.0;
        const double rise = up_hi ? rise_hi : up_lo ? rise_lo : 0.0, fall = up_hi ? -rise_lo : up_lo ? -rise_hi : 0.0;
        const bool filled = in[c] && Phi[c] > Phi_vac;
        const bool unsupported = filled && (up_hi || up_lo) && p[c] <= Phi[c] * rise;
        // The cell above along the sweep is the uphill neighbour when it was visited just before.
        const bool from_hi = up_hi && dir < 0 && kind[fu] == kInterior, from_lo = up_lo && dir > 0 && kind[fl] == kInterior;
        const double arriving = from_hi ? downhill[c + hi] : from_lo ? downhill[c + lo] : 0.0;
        // It passes that on only while it and what rests on it would fit into the cell at the
        // loosest load-bearing packing Phi_co (arriving / (rise + fall) is the volume fraction the
        // material above would add): a partly filled surface cell with dust on it rests on the
        // cell below; loose material that fills the cell holds nothing up and compacts.
        const bool rests = (Phi[c] - co[c]) * (rise + fall) + arriving <= 0.0;
        carry[c] = unsupported && rests ? weight * arriving : 0.0;
        load[c] = filled ? unsupported_load(Phi[c], p[c], rise) + carry[c] : 0.0;
        downhill[c] = filled ? p[c] + Phi[c] * fall + load[c] : 0.0;
    };
    if (a == 0) {
        parallel_for(mesh.parallel, mesh.rows, [&](std::size_t r) {
            const AxisRow ar = mesh.axis_row(0, r);
            for (int q = 0; q < static_cast<int>(nx); ++q) {
                const int i = dir < 0 ? static_cast<int>(nx) - 1 - q : q;
                visit(nx * r + i, ar.face0 + i, ar.face0 + i + 1, ar.lo_at(i), ar.hi_at(i));
            }
        });
        return;
    }
    // y and z: layers in the sweep order, vectorised along x in blocks of columns.
    const int n_a = grid.n[a];
    const std::size_t others = a == 1 ? grid.n[2] : ny, blocks = (nx + 31) / 32;
    parallel_for_pairs(mesh.parallel, others, blocks, [&](std::size_t o, std::size_t blk) {
        for (int q = 0; q < n_a; ++q) {
            const int layer = dir < 0 ? n_a - 1 - q : q;
            const std::size_t r = a == 1 ? layer + ny * o : o + ny * layer;
            const AxisRow ar = mesh.axis_row(a, r);
            const std::size_t i1 = std::min(nx, 32 * blk + 32);
#pragma omp simd
            for (std::size_t i = 32 * blk; i < i1; ++i)
                visit(nx * r + i, ar.face0 + i, ar.face0 + i + ar.face_step, ar.lo, ar.hi);
        }
    });
}

}  // namespace granseg
