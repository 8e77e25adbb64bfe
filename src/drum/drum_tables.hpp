// The composition of a drum's bed as a data file, one row per bed cell, shared by the kinematic
// and the coupled drum (tumbler_initial.dat, frames/frame_NNN.dat, ...): positions in the
// inertial frame.
#pragma once

#include "core/grid.hpp"
#include "run/output.hpp"

#include <array>
#include <functional>
#include <string>
#include <vector>

namespace granseg {

/// Where a cell of the slice j = 0 is drawn: its centre (x, z) mapped to the inertial frame (the
/// coupled drum's grid turns with the drum; the kinematic drum's grid is inertial: no mapping).
using InertialPosition = std::function<std::array<double, 2>(double x, double z)>;

/// One row per bed cell: x z phi_hat (from phi_hat, a cell field). Bed cells: the inside cells,
/// or those `bed` accepts if given; positions mapped by `where` if given.
DataTable composition_cells(const Grid& grid, const std::vector<double>& phi_hat, const std::string& what,
                            const std::function<bool(std::size_t)>& bed = {}, const InertialPosition& where = {});

}  // namespace granseg
