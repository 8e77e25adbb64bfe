// The balance of a cell's face fluxes (flow/fields/face_balance.hpp) against sums over the faces that
// core/grid.hpp names for the cell, and the transport update of the semi-implicit step
// (flow/faces/convection.hpp) against the coupling identity Phi_new = Phi - dt div M.
#include "flow/fields/face_balance.hpp"
#include "flow/faces/convection.hpp"
#include "flow/faces/semi_implicit_faces.hpp"
#include "flow/fields/flow_mesh.hpp"

#include <boost/test/unit_test.hpp>

#include <array>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

using namespace granseg;
namespace tt = boost::test_tools;

namespace {

/// One random value in [-1, 1] per face of every axis.
std::array<std::vector<double>, 3> random_faces(const Grid& g, std::mt19937& rng) {
    std::uniform_real_distribution<double> value(-1.0, 1.0);
    std::array<std::vector<double>, 3> F;
    for (int a = 0; a < 3; ++a) {
        F[a].resize(g.faces(a));
        for (double& x : F[a]) x = value(rng);
    }
    return F;
}

/// The lower and upper face of cell (i, j, k) along `axis`, from the grid's own face numbering.
std::array<std::size_t, 2> cell_faces(const Grid& g, int axis, int i, int j, int k) {
    return {g.face_index(axis, i, j, k), g.face_index(axis, i + (axis == 0), j + (axis == 1), k + (axis == 2))};
}

/// Per inside cell (in index order) the three sums of flow/fields/face_balance.hpp with weights w.
struct Sums {
    std::vector<double> balance, outflow, after;
};
Sums helper_sums(const FlowMesh& mesh, const std::array<std::vector<double>, 3>& F, const AxisWeights& w) {
    const AxisFields f = {F[0].data(), F[1].data(), F[2].data()};
    const std::size_t cells = mesh.grid.cells();
    Sums s{std::vector<double>(cells), std::vector<double>(cells), std::vector<double>(cells)};
    mesh.parallel_for_inside_cells([&](std::size_t c, int i, const AxisRow* rows) {
        s.balance[c] = face_balance(f, w, i, rows);
        s.outflow[c] = face_outflow(f, w, i, rows);
        s.after[c] = mass_balance(1.0, 0.01, f, axis_weights(mesh), i, rows);
    });
    return s;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(flow_face_balance_tests)

BOOST_AUTO_TEST_CASE(face_balance_sums_the_faces_the_grid_names_for_a_cell) {
    // A 3-D grid (periodic along y) and an x-z plane whose inactive y faces hold NaN: the helpers
    // must take each cell's own faces, the axes in the order x, y, z, and leave inactive axes out.
    std::mt19937 rng(7);
    Grid box;
    box.n = {3, 2, 4}, box.h = {0.1, 0.2, 0.3}, box.periodic = {false, true, false};
    for (const Grid& g : {box, Grid::plane_xz(4, 3, 0.0, 0.0, 0.4, 0.6)}) {
        const FlowMesh mesh(g);
        std::array<std::vector<double>, 3> F = random_faces(g, rng);
        if (g.n[1] == 1) F[1].assign(g.faces(1), std::numeric_limits<double>::quiet_NaN());
        const AxisWeights w = axis_weights(mesh, 0.01);
        const Sums s = helper_sums(mesh, F, w);
        for (int k = 0; k < g.n[2]; ++k)
            for (int j = 0; j < g.n[1]; ++j)
                for (int i = 0; i < g.n[0]; ++i) {
                    double balance = 0.0, outflow = 0.0, divergence = 0.0;
                    for (int a = 0; a < 3; ++a) {
                        if (g.n[a] == 1) continue;
                        const auto [lo, hi] = cell_faces(g, a, i, j, k);
                        const double w_a = 0.01 / g.h[a];
                        balance += (F[a][hi] - F[a][lo]) * w_a;
                        outflow += (std::max(0.0, F[a][hi]) + std::max(0.0, -F[a][lo])) * w_a;
                        divergence += (F[a][hi] - F[a][lo]) * (1.0 / g.h[a]);
                    }
                    const std::size_t c = g.index(i, j, k);
                    BOOST_TEST(s.balance[c] == balance);  // the same operations in the same order: exact
                    BOOST_TEST(s.outflow[c] == outflow);
                    BOOST_TEST(s.after[c] == 1.0 - 0.01 * divergence);
                }
    }
}

BOOST_AUTO_TEST_CASE(transport_update_is_the_coupling_identity_and_conserves_mass) {
    // Walls all around a 5 x 4 plane (zero mass flux through them): the update's Phi is exactly
    // Phi - dt div M in every cell, the total changes only by round-off, u and T are the new
    // Phi u/Phi and Phi T/Phi; without fluxes nothing changes.
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> fill(0.1, 0.5), value(-1.0, 1.0);
    const Grid g = Grid::plane_xz(5, 4, 0.0, 0.0, 0.05, 0.04);
    const FlowMesh mesh(g);
    const std::size_t cells = g.cells();
    FlowState state;
    state.Phi.resize(cells), state.E.resize(cells), state.T.assign(cells, 0.0);
    for (int b = 0; b < 3; ++b) state.m[b].resize(cells), state.u[b].assign(cells, 0.0);
    for (std::size_t c = 0; c < cells; ++c) {
        state.Phi[c] = fill(rng), state.E[c] = 1e-3 * fill(rng);
        for (int b = 0; b < 3; ++b) state.m[b][c] = 0.01 * value(rng);
    }
    FlowFaces faces;
    for (int a = 0; a < 3; ++a) {
        AxisFaces& F = faces[a];
        const std::size_t n = g.faces(a);
        for (auto* f : {&F.mass, &F.energy, &F.mom_below, &F.p, &F.speed}) f->assign(n, 0.0);
        for (auto& f : F.mom) f.assign(n, 0.0);
        for (const MeshFace& face : mesh.faces[a]) {
            const double interior = face.kind == kInterior ? 1.0 : 0.0;
            F.mass[face.f] = 0.1 * interior * value(rng), F.energy[face.f] = 1e-4 * interior * value(rng);
            F.mom_below[face.f] = value(rng);
            for (auto& f : F.mom) f[face.f] = value(rng);
        }
    }
    FlowSettings settings;
    const double dt = 1e-3;

    const FlowState start = state;
    transport_update(mesh, settings, dt, faces, state);
    const AxisFields M = axis_fields(faces, &AxisFaces::mass);
    const AxisWeights inv_h = axis_weights(mesh);
    std::vector<double> expected(cells);
    mesh.parallel_for_inside_cells(
        [&](std::size_t c, int i, const AxisRow* rows) { expected[c] = start.Phi[c] - dt * face_balance(M, inv_h, i, rows); });
    double total_before = 0.0, total_after = 0.0;
    for (std::size_t c = 0; c < cells; ++c) {
        BOOST_TEST(state.Phi[c] == expected[c]);
        total_before += start.Phi[c], total_after += state.Phi[c];
        for (int b = 0; b < 3; ++b) BOOST_TEST(state.u[b][c] == state.m[b][c] / state.Phi[c], tt::tolerance(1e-14));
        BOOST_TEST(state.T[c] == state.E[c] / state.Phi[c], tt::tolerance(1e-14));
    }
    BOOST_TEST(total_after == total_before, tt::tolerance(1e-14));
    // The hand-over: a consumer's Phi - dt div M and the step's Phi after the fluxes are the
    // update's, bit for bit (one function rounds all three).
    std::vector<double> handed = start.Phi, after(cells, 0.0);
    apply_mass_fluxes(g, {faces[0].mass, faces[1].mass, faces[2].mass}, dt, handed);
    volume_fraction_after(mesh, dt, start.Phi, faces, after);
    for (std::size_t c = 0; c < cells; ++c) {
        BOOST_TEST(handed[c] == state.Phi[c]);
        BOOST_TEST(after[c] == state.Phi[c]);
    }

    FlowFaces none = faces;  // no fluxes at all: the state stays as it was
    for (AxisFaces& F : none) {
        for (auto* f : {&F.mass, &F.energy, &F.mom_below}) f->assign(f->size(), 0.0);
        for (auto& f : F.mom) f.assign(f.size(), 0.0);
    }
    FlowState still = start;
    transport_update(mesh, settings, dt, none, still);
    BOOST_TEST(still.Phi == start.Phi);
    BOOST_TEST(still.E == start.E);
    for (int b = 0; b < 3; ++b) BOOST_TEST(still.m[b] == start.m[b]);
}

BOOST_AUTO_TEST_SUITE_END()
