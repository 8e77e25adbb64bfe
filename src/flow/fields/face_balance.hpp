// The balance of a cell's face fluxes, written once for every kernel that needs it: the updates
// and the hand-over's mass balance (flow/faces/convection.hpp), the bounds of the time step
// (flow/time_step.hpp) and the semi-implicit step's explicit mass change, dust cap and Phi after
// the step (flow/faces/semi_implicit_faces.hpp).
//
//   solves      nothing over time: per cell, sums over its faces
//   inputs      a face field per axis (one value per face, flow/fields/flow_mesh.hpp order), a weight
//               per axis (1/h for a rate, dt/h for a change; 0 leaves an inactive axis out), and
//               the cell (its index i in the row and the AxisRow of each axis)
//   outputs     face_balance    sum_axis (F[upper face] - F[lower face]) w_axis  (w = 1/h: div F)
//               face_outflow    sum_axis (max(0, F[upper]) + max(0, -F[lower])) w_axis  (what leaves)
//               mass_balance    Phi - dt face_balance(M, 1/h): the mass balance of a step
//   invariants  the axes are taken in the order x, y, z and each term is (difference) times w: a
//               result is the same to the last bit wherever it is computed (the coupling identity
//               of flow/flow_solver.hpp relies on the update and the hand-over rounding alike)
#pragma once

#include "flow/fields/flow_mesh.hpp"

#include <algorithm>
#include <array>
#include <cstddef>

namespace granseg {

/// One face field per axis (the data of a face vector; unused for an axis whose weight is 0).
using AxisFields = std::array<const double*, 3>;
/// One weight per axis; 0 leaves the axis out.
using AxisWeights = std::array<double, 3>;

/// The weights scale/h_axis of the active axes of `mesh` (0 for inactive ones): scale = 1 gives
/// rates (1/s), scale = dt the change over a step.
inline AxisWeights axis_weights(const FlowMesh& mesh, double scale = 1.0) {
    AxisWeights w{};
    for (int a = 0; a < 3; ++a) w[a] = mesh.active[a] ? scale / mesh.grid.h[a] : 0.0;
    return w;
}

/// sum over the axes with w != 0 (x, y, z in turn) of term(axis, lower face, upper face) * w_axis
/// for cell i of a row whose AxisRow along each axis is rows[axis].
template <class Term>
inline __attribute__((always_inline)) double sum_over_axes(const AxisWeights& w, int i, const AxisRow* rows, Term&& term) {
    double sum = 0.0;
    for (int a = 0; a < 3; ++a) {
        if (w[a] == 0.0) continue;
        const std::size_t fl = rows[a].face0 + i, fu = fl + rows[a].face_step;
        sum += term(a, fl, fu) * w[a];
    }
    return sum;
}

/// sum_axis (upper[axis][upper face] - lower[axis][lower face]) w_axis: the balance of the cell's
/// face fluxes (the normal momentum flux differs as seen from below and above a face).
inline __attribute__((always_inline)) double face_balance(const AxisFields& upper, const AxisFields& lower, const AxisWeights& w,
                                                          int i, const AxisRow* rows) {
    return sum_over_axes(w, i, rows, [&](int a, std::size_t fl, std::size_t fu) { return upper[a][fu] - lower[a][fl]; });
}

/// sum_axis (F[upper face] - F[lower face]) w_axis; with w = 1/h the divergence of F.
inline __attribute__((always_inline)) double face_balance(const AxisFields& F, const AxisWeights& w, int i, const AxisRow* rows) {
    return face_balance(F, F, w, i, rows);
}

/// sum_axis (max(0, F[upper face]) + max(0, -F[lower face])) w_axis: what leaves the cell.
inline __attribute__((always_inline)) double face_outflow(const AxisFields& F, const AxisWeights& w, int i, const AxisRow* rows) {
    return sum_over_axes(
        w, i, rows, [&](int a, std::size_t fl, std::size_t fu) { return std::max(0.0, F[a][fu]) + std::max(0.0, -F[a][fl]); });
}

/// Phi - dt sum_axis (M[upper] - M[lower])/h for one cell, with inv_h = axis_weights(mesh): the
/// mass balance of a step, computed by this one function wherever it is needed (the flow's update,
/// Phi after the step within it, the hand-over's apply_mass_fluxes), so all round it alike.
inline __attribute__((always_inline)) double mass_balance(double Phi, double dt, const AxisFields& M, const AxisWeights& inv_h,
                                                          int i, const AxisRow* rows) {
    return Phi - dt * face_balance(M, inv_h, i, rows);
}

/// The data of one face field of every axis, e.g. axis_fields(faces, &AxisFaces::mass).
template <class Faces, class Field>
inline AxisFields axis_fields(const Faces& faces, Field field) {
    return {(faces[0].*field).data(), (faces[1].*field).data(), (faces[2].*field).data()};
}

}  // namespace granseg
