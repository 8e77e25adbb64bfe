// The data files of a coupled drum run (docs/scenes.md, kind "tumbler"), in the lab (inertial)
// frame: the solver's drum-frame positions, velocities and d_s turned by Frame::to_lab_*.
#pragma once

#include "coupled/coupled_tumbler.hpp"
#include "run/output.hpp"

#include <string>

namespace granseg {

/// Cells of the slice j = 0, one gnuplot block per row, lab frame:
///   x z Phi phi_hat u_x u_z T ds_x ds_z inside urel_x urel_z a_x a_z
/// u: lab velocity; urel: velocity relative to the drum (lab components); d_s and a = S^sl of the
/// last segregation sub-step (0 where there is none). Outside cells: zeros and inside = 0.
DataTable coupled_field_table(const CoupledTumbler& tumbler);

/// x z phi_hat of the bed cells (Phi > bed_level), lab frame: a frame of the animation.
DataTable coupled_composition(const CoupledTumbler& tumbler, double bed_level);

/// The flow's legacy VTK file (flow/flow_tables.hpp flow_vtk: Phi, T, p, inside, velocity, lab frame)
/// with the cell data phi_hat and d_s (lab frame) appended, for ParaView.
std::string coupled_vtk(const CoupledTumbler& tumbler);

}  // namespace granseg
