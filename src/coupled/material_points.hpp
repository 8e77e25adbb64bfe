// Material points carried through the coupled drum's velocity relative to the drum (the flow
// solver's frame, F5): a reference for the passive tracer without numerical diffusion. A point
// moves only where the bed moves relative to the drum (the flowing layer and the creep below it);
// in solid-body rotation u_rel = 0 and it stays. What the tracer loses beyond what the points lose
// is the grid's smearing; what the points lose is what the flow moves (docs/sect4.2_tumbler.md,
// "The core").
//
//   solves      dx/dt = u_rel(x, t) for each point: the midpoint rule (RK2) per flow step with the
//               step's end velocity, bilinear interpolation of the cell-centre velocity, u = 0 in
//               wall cells and beyond the grid
//   inputs      the grid (x-z plane; a slab: its slice j = 0), Phi at t = 0, a marking function
//   outputs     the share of the points within a radius of the axis that started marked
//   invariants  the number of points is fixed; radial regions about the axis are the same in the
//               drum and the lab frame, so no frame change is needed to test them
#pragma once

#include "core/grid.hpp"
#include "run/state_io.hpp"

#include <functional>
#include <vector>

namespace granseg {

class MaterialPoints {
public:
    /// Four points in every bed cell (inside, Phi > bed_level), at the centres of its quarters, at
    /// t = 0 (drum and lab frame agree then), each marked where mark(x, z) >= 1/2.
    MaterialPoints(const Grid& grid, const std::vector<double>& Phi, double bed_level,
                   const std::function<double(double x, double z)>& mark);

    /// Moves every point by dt: x* = x + dt/2 u(x), x_new = x + dt u(x*), with u = (u_x, u_z)
    /// per cell (the velocity relative to the drum at the end of the step).
    void advance(const std::vector<double>& ux, const std::vector<double>& uz, double dt);

    /// Of the points within radius r of the axis, the share that started marked (NaN if none).
    double marked_share_within(double r) const;

    std::size_t size() const { return x_.size(); }

private:
    /// Bilinear interpolation of the cell-centre field f at (x, z) (0 in wall cells and outside).
    double interpolate(const std::vector<double>& f, double x, double z) const;

    Grid grid_;
    std::vector<double> x_, z_;
    std::vector<unsigned char> marked_;

public:
    /// Saves or restores (run/state_io.hpp) the points.
    void checkpoint(StateIO& io) { io("points.x", x_)("points.z", z_)("points.marked", marked_); }
};

}  // namespace granseg
