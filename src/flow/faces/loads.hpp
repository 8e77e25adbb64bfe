// The potential psi and the loads of the hydrostatic reconstruction (docs/flow_solver.md Sect. 2, forces;
// the reconstruction itself is hydrostatic_reconstruction() in flow/faces/hllc.hpp).
//
//   solves      nothing over time: psi and the unsupported loads at t^n
//   inputs      FlowMesh, FlowSettings, Frame, t; Phi, p, Phi_co
//   outputs     psi per cell and face; per axis and cell load, carry and downhill (AxisLoads)
//   invariants  load, carry, downhill >= 0, and 0 in empty cells
//
// psi = -g . x - omega^2 |r|^2/2 (gravity along the bounded active axes and the centrifugal
// potential of the rotating frame, flow/fields/frame.hpp) is piecewise constant per cell; a face takes
// the mean of its two cells (a wall's ghost is the mirror cell). A cell whose own pressure cannot
// carry its weight up to its uphill face (p <= Phi rise: the partly filled surface cell, dust) is
// "unsupported": its downhill face carries the missing weight (`load`), and the load resting on
// it (`carry`) is passed on down chains of unsupported cells along axes close to gravity, but
// only while the cell and that load fit into the cell at Phi_co, so loose material compacts
// (assumption F7).
#pragma once

#include "flow/fields/flow_mesh.hpp"
#include "flow/fields/flow_settings.hpp"
#include "flow/fields/flow_state.hpp"
#include "flow/fields/frame.hpp"

#include <vector>

namespace granseg {

/// psi at every cell centre at time t (all cells, inside or not).
void cell_potential(const FlowMesh& mesh, const Frame& frame, double t, std::vector<double>& psi);

/// psi on every face of `axis`: the mean of the two cells' potentials (the mirror cell's on a wall
/// of the domain boundary).
void face_potential(const FlowMesh& mesh, const Frame& frame, double t, int axis, const std::vector<double>& psi,
                    std::vector<double>& psi_face);

/// `load`, `carry` and `downhill` of every cell along `axis` from Phi, p, Phi_co and the potentials.
void unsupported_loads(const FlowMesh& mesh, const FlowSettings& settings, const Frame& frame, double t, int axis,
                       const FlowState& state, const CellClosures& closures, const Potential& psi, AxisLoads& loads);

}  // namespace granseg
