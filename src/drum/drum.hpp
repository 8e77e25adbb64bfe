// The drum of Sect. 4.2 as the flow solver sees it, shared by the scene kinds tumbler-flow (flow
// alone) and tumbler (flow and segregation coupled): the geometry and rotation (a circle, or a
// regular polygon: drum/drum_shape.hpp, docs/drum_shapes.md), the bed at rest it starts from
// (docs/assumptions.md F6, F8), and the dynamic angle of repose.
//
//   solves      nothing over time: the drum's geometry and the bed at rest it starts from
//   inputs      DrumSpec (shape, diameter, cells, fill height, rotation), the material, phi_hat
//   outputs     the grid, each cell's filled share and lithostatic Phi; the mean angle of repose
//   invariants  the bed at rest lies below its own Phi_rcp(phi_hat) in every cell (assumption C3)
#pragma once

#include "closures/material.hpp"
#include "core/grid.hpp"
#include "drum/drum_shape.hpp"
#include "flow/flow_solver.hpp"
#include "run/state_io.hpp"

#include <array>
#include <cmath>
#include <vector>

namespace granseg {

/// Geometry and rotation of the drum (keys of the [drum] section, docs/scenes.md).
struct DrumSpec {
    double diameter = 0.1;  // m, of the circle (a polygon: of the circle through its corners)
    int cells_per_diameter = 100;
    double fill_height = 0.075;  // m, flat initial surface above the drum's lowest point
    DrumShapeKind shape = DrumShapeKind::circle;
    int sides = 4;                // a polygon's sides (>= 3)
    double orientation = 0.0;     // degrees a polygon is turned counter-clockwise from a side at the bottom
    double rps = 0.1;             // revolutions per second, counter-clockwise as plotted
    int axial_cells = 1;          // 1: the x-z cross-section; more: a periodic slab along y
    double axial_length = 0.001;  // m
    double gravity = 9.81;        // |g|, m/s^2

    double radius() const { return 0.5 * diameter; }
    /// The cross-section in the drum frame at t = 0 (axis at the origin).
    DrumShape cross_section() const;
    /// The drum frame: gravity, rotation at 2 pi rps about the drum axis through the origin.
    Frame frame() const;
    /// The staircase drum on cells of side diameter/cells_per_diameter (drum/bed.hpp drum_grid).
    Grid grid() const;
    /// Height of the flat initial surface above the drum's centre.
    double surface_height() const { return cross_section().lowest() + fill_height; }
    /// Speed relative to the drum above which material counts as flowing: 5 % of the wall speed
    /// (0 for a drum at rest, whose flowing share and layer drum_state (drum/drum_state.hpp) then reports as NaN).
    double flowing_speed() const { return 0.05 * std::fabs(2.0 * M_PI * rps) * radius(); }
};

/// The smallest signed distance of the free surface from the axis (above it > 0) over a turn of
/// the drum: the flat surface over a bed of the area at rest (the shape below the fill height) at
/// each angle of the drum to gravity, sampled every half degree. A circle: surface_height() (the
/// same at every angle); a centrally symmetric shape half full: 0.
double closest_surface_distance(const DrumSpec& drum);

/// The free surface of the diagnostics is the level Phi = Phi_co(phi_hat)/2, half-way between
/// the empty drum and the loosest bed of the mixture (drum/drum_state.hpp).
inline double surface_level(const Material& material, double phi_hat) { return 0.5 * material.packing.Phi_co(phi_hat); }

/// How long a drum runs and what it writes on the way (the [run] keys, docs/scenes.md).
struct DrumRun {
    double t_end = 25.0;          // s
    double snapshot_every = 2.5;  // s between VTK files
    double angle_from = 10.0;     // s, start of the angle-of-repose average
    bool vtk = true;
};

/// Seconds between the rows of a drum's history.dat.
constexpr double kDrumHistoryInterval = 0.05;

/// Phi per cell of the bed at rest before the drum turns: the lithostatic balance under |g| along
/// -z with the flat surface at the fill height, T = T, for the uniform mixture phi_hat
/// (Phi_rcp(phi_hat), Phi_co(phi_hat); drum/bed.hpp lithostatic_bed).
std::vector<double> drum_bed_at_rest(const DrumSpec& drum, const Grid& grid, const Material& material, double phi_hat, double T);

/// The bed at rest of a mixture that varies from cell to cell, for packing feedback: the bed of
/// the uniform `mixture` (above) where phi_hat = mixture, and elsewhere, at the same pressure, the
/// Phi of the cell's own packing law Phi_rcp(phi_hat), Phi_co(phi_hat) (times its filled share),
/// so every cell lies below its own Phi_rcp (assumption C3).
std::vector<double> drum_bed_at_rest(const DrumSpec& drum, const Grid& grid, const Material& material,
                                     const std::vector<double>& phi_hat, double mixture, double T);

/// Share of each cell's volume below the flat initial surface (1 below, 0 above, the filled
/// fraction of its height for the cell holding the surface; 0 outside the drum).
std::vector<double> drum_fill_fraction(const DrumSpec& drum, const Grid& grid);

/// Mean and standard deviation of a drum diagnostic (the free-surface angle, the flowing layer's
/// thickness) over the samples taken at t >= from (NaN samples, without a surface fit, left out).
/// It keeps every sample, so that a run extended to a later t_end with another `from` (the
/// default angle_from depends on t_end) reports the average a run made with that t_end reports.
class TimeAverage {
public:
    explicit TimeAverage(double from) : from_(from) {}
    void add(double t, double value);
    double mean() const;
    double std_dev() const;  // 0 for one sample, NaN for none (as mean())
    long samples() const;
    /// Saves or restores (run/state_io.hpp) the samples; `from` stays the constructor's.
    void checkpoint(StateIO& io) { io("average.t", t_)("average.value", value_); }

private:
    /// Sum of the samples at t >= from_ and of their squares (in the order taken), and their count.
    std::array<double, 3> sums() const;
    double from_;
    std::vector<double> t_, value_;  // every finite sample
};

}  // namespace granseg
