// What the segregation sub-step reads and never changes: eq. (52b) freezes Phi (and T) while
// phi segregates. The flow solver (or a test) fills it once per step.
//
//   solves      nothing: the fields eq. (52b) freezes during the segregation sub-step
//   inputs      filled by the flow solver, a scene or a test
//   outputs     read by SegregationSolver and segregation_face_fluxes
//   invariants  one value per cell (face), 0 <= Phi < 1, finite a, D >= 0 (check_frozen_fields)
//
// Per axis k the segregation flux is f_k(phi) = a_k phi (phi - Phi)/Phi (eq. 47 with the flux on
// the left-hand side), a_k = (S^sl)_k = -S0 sqrt(T) (d_s . g)(d_s)_k (eq. 46) per cell. a_k may
// have either sign and change sign between neighbouring cells (docs/assumptions.md S1); in 1-D
// with z up and gravity down, a_z = S sqrt(T) >= 0 (eq. 66).
#pragma once

#include "core/grid.hpp"
#include "run/state_io.hpp"
#include "segregation/flux_difference.hpp"

#include <array>
#include <vector>

namespace granseg {

struct FrozenFields {
    std::vector<double> Phi;               // granular volume fraction per cell, 0 <= Phi < 1
    std::array<std::vector<double>, 3> a;  // a_k per cell; an empty vector: no segregation along k
    // Classic schemes only: Phi and a at the faces (docs/assumptions.md G2). An empty face field
    // means the arithmetic mean of the two neighbouring cells.
    FaceFields Phi_face, a_face;
    // Diffusive remixing (Gray & Chugunov; beyond the paper) along every axis that has a:
    // flux -D min(Phi_L, Phi_R) d(phi_hat)/dx_k, which is -D d(phi)/dx_k for constant Phi
    // (docs/assumptions.md G3). D = 0 switches it off.
    double D = 0.0;
    /// Saves or restores (run/state_io.hpp) the cell fields (the faces and D are set-up).
    void checkpoint(StateIO& io) { io("Phi", Phi)("a", a); }
};

/// Throws InputError with a one-line reason if a field has the wrong size or holds
/// a value outside its range (Phi in [0, 1), finite a, D >= 0).
void check_frozen_fields(const Grid& grid, const FrozenFields& fields);

}  // namespace granseg
