// The data files of a kinematic tumbler run (inertial frame, m, m/s), written by the
// tumbler-kinematic scene and by verify_tumbler_kinematic for figures/fig7{a,b,c}_*.gp.
#pragma once

#include "core/output.hpp"
#include "tumbler/kinematic_tumbler.hpp"
#include "tumbler/tumbler_run.hpp"

#include <array>
#include <functional>
#include <vector>

namespace granseg {

/// Drum wall (index 0), free surface (index 1) and the bottom of the flowing layer (index 2).
DataTable drum_outline(const RollingDrumFlow& flow);

/// Where a cell of the slice j = 0 is drawn: its centre (x, z) mapped to the inertial frame (the
/// coupled drum's grid turns with the drum; the kinematic drum's grid is inertial: no mapping).
using InertialPosition = std::function<std::array<double, 2>(double x, double z)>;

/// One row per bed cell: x z phi_hat (from phi_hat, a cell field). Bed cells: the inside cells,
/// or those `bed` accepts if given; positions mapped by `where` if given.
DataTable composition_cells(const Grid& grid, const std::vector<double>& phi_hat, const std::string& what,
                            const std::function<bool(std::size_t)>& bed = {}, const InertialPosition& where = {});

/// One row per bed cell: x z in_layer ux uz ds_x ds_z T a_x a_z (the steady fields of the run).
DataTable tumbler_flow_cells(const KinematicTumbler& tumbler);

/// t index core ring periphery mean core_deviation, one row per record.
DataTable tumbler_metrics(const TumblerRunResult& result, const PatternRegions& regions);

/// r phi_hat_initial phi_hat_final cells, one row per radial shell of the radius (empty shells left out).
DataTable tumbler_shells(const KinematicTumbler& tumbler, const TumblerRunResult& result, int shells);

}  // namespace granseg
