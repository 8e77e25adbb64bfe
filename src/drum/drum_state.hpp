// The diagnostics of a rotating drum on the flow solver's state (docs/scenes.md, tumbler-flow and
// tumbler): the free surface's angle against the horizontal, the flowing and the resting
// material, and the flowing layer's thickness.
//
//   solves      nothing: measures a FlowSolver's state in the drum's (rotating) frame
//   inputs      a FlowSolver; the level, radius and speed of the diagnostics; the drum's shape
//   outputs     DrumState
#pragma once

#include "drum/drum_shape.hpp"
#include "flow/flow_solver.hpp"

namespace granseg {

/// Drum diagnostics in the solver's (rotating) frame.
struct DrumState {
    double surface_angle_deg;  // angle of the free surface against the horizontal, > 0 when it
                               // rises in the direction the drum turns (either sense); NaN with
                               // fewer than two surface points in the window
    int surface_points;        // crossings of Phi = Phi_level used for the fit
    double flowing_fraction;   // share of the granular mass moving faster than v_flow relative to the drum
    double max_speed;          // m/s, largest |u| relative to the drum over cells with Phi > Phi_level
    double kinetic_energy;     // sum of Phi |u|^2 / 2 times the cell volume (rho* = 1)
    double surface_distance;   // m, distance of the fitted surface line from the axis (NaN without a fit)
    double surface_offset;     // m, the same signed: the line is -sin(a) x + cos(a) z = offset about
    double surface_direction;  // the axis in the drum frame, a = surface_direction (rad; NaN without a fit)
    double flowing_area;       // m^2, area of the cells with Phi > Phi_level moving faster than v_flow
                               // relative to the drum, per unit length along y
                               // (flowing_fraction and flowing_area: NaN when v_flow = 0)
};

/// Mean thickness of the flowing layer: its area over the chord the fitted surface cuts from the
/// drum's cross-section (NaN without a fit).
inline double flowing_layer_thickness(const DrumState& d, const DrumShape& shape) {
    return d.flowing_area / shape.chord(d.surface_offset, d.surface_direction);
}

/// Fits a line (total least squares) through the points where Phi crosses Phi_level between
/// neighbouring inside cells within the window, and compares it with the horizontal
/// (perpendicular to gravity at the solver's time). The window: points within `radius` of the
/// axis, or, given a drum `shape`, points whose gauge (DrumShape::gauge) is below `radius` (the
/// shape scaled by radius / R; for a circle the same points).
DrumState drum_state(const FlowSolver& solver, double Phi_level, double radius, double v_flow, const DrumShape* shape = nullptr);

}  // namespace granseg
