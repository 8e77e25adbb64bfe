// The data files of a kinematic tumbler run (inertial frame, m, m/s), written by the
// tumbler-kinematic scene and by verify_tumbler_kinematic for figures/fig7{a,b,c}_*.gp.
#pragma once

#include "drum/drum_tables.hpp"
#include "kinematic/kinematic_run.hpp"
#include "kinematic/kinematic_tumbler.hpp"
#include "run/output.hpp"

#include <array>
#include <functional>
#include <vector>

namespace granseg {

/// Drum wall (index 0), free surface (index 1) and the bottom of the flowing layer (index 2).
DataTable drum_outline(const RollingDrumFlow& flow);

/// One row per bed cell: x z in_layer ux uz ds_x ds_z T a_x a_z (the steady fields of the run).
DataTable kinematic_flow_cells(const KinematicTumbler& tumbler);

/// t index core ring periphery mean core_deviation, one row per record.
DataTable kinematic_metrics(const KinematicRunResult& result, const PatternRegions& regions);

/// r phi_hat_initial phi_hat_final cells, one row per radial shell of the radius (empty shells left out).
DataTable kinematic_shells(const KinematicTumbler& tumbler, const KinematicRunResult& result, int shells);

}  // namespace granseg
