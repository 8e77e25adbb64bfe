// Running the flow solver in a scene and writing what it computed: progress and the mass
// invariant, gnuplot tables of fields and profiles, legacy VTK files for ParaView, and the
// diagnostics of a rotating drum (free-surface angle, flowing and resting material).
//
//   solves      nothing: runs a FlowSolver to t_end and measures its state
//   inputs      a FlowSolver after a step; the level, radius and speed of the drum diagnostics
//   outputs     DataTables (fields, profiles, counts), VTK text, DrumState
//   invariants  the total mass drifts by less than kMassDriftLimit (InvariantError otherwise)
#pragma once

#include "core/drum_shape.hpp"
#include "core/output.hpp"
#include "core/progress.hpp"
#include "core/run_checkpoints.hpp"
#include "flow/flow_solver.hpp"

#include <cmath>
#include <functional>
#include <string>

namespace granseg {

/// Relative change of the total mass that breaks the mass invariant: each step rounds every
/// cell's update once (relative error <= 2^-53 of Phi), so after n steps the drift is below
/// n * 2^-53 * (cells * max Phi / mass); runs of up to 10^7 steps stay far below 1e-8.
constexpr double kMassDriftLimit = 1e-8;

/// Steps `solver` to t_end, printing progress with an ETA on stderr for long runs, calling
/// `after_step` (if given) after every step, and throwing InvariantError if the mass drifts by
/// more than kMassDriftLimit. With `checkpoints`, writes checkpoints of `state` (the solver and
/// what the caller records, core/run_checkpoints.hpp; the caller has resumed it first, if at
/// all). Returns the run's wall and CPU seconds (with those before a resume) and its threads.
RunTime advance_flow(FlowSolver& solver, double t_end, const std::string& label, const std::function<void()>& after_step = {},
                     RunCheckpoints* checkpoints = nullptr, const RunState& state = {});

/// Cell fields of the slice j = 0, one gnuplot block per row of x (blank lines between rows):
/// x z Phi u_x u_y u_z T p inside, in the frame of the solver (lab = false) or with positions
/// and velocities turned back to the lab frame (lab = true, Frame::to_lab_*). Outside cells have
/// Phi = u = T = p = 0 and inside = 0.
DataTable flow_field_table(const FlowSolver& solver, bool lab);

/// Profiles along z of a column (nx = ny = 1): z Phi u_x u_z T p (the closures' pressure).
DataTable flow_column_table(const FlowSolver& solver);

/// Legacy VTK (ASCII STRUCTURED_GRID) of the slice j = 0 in the lab frame at the solver's time:
/// points are the cell corners turned by Frame::to_lab_position, cell data Phi, T, p, inside and
/// the lab-frame velocity.
std::string flow_vtk(const FlowSolver& solver);

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

/// Appends the solver's work to a summary row: steps_X, the steps whose dt the bound X set
/// (docs/flow_solver.md Sect. 2, step_size), the semi-implicit step's pressure_solves, newton and krylov
/// iterations (0 in the explicit step), the temperature solves' conjugate-gradient iterations,
/// and seconds_S, the wall-clock seconds of each stage S of the step (FlowStage).
void append_flow_work(const FlowSolver& solver, TableRow& row);

/// Appends a run's cost to a summary row: wall_seconds, cpu_seconds (every thread of the process:
/// CPU over wall says how many cores the run kept busy) and threads (core/threads.hpp).
void append_run_time(const RunTime& cost, TableRow& row);

/// Fits a line (total least squares) through the points where Phi crosses Phi_level between
/// neighbouring inside cells within the window, and compares it with the horizontal
/// (perpendicular to gravity at the solver's time). The window: points within `radius` of the
/// axis, or, given a drum `shape`, points whose gauge (DrumShape::gauge) is below `radius` (the
/// shape scaled by radius / R; for a circle the same points).
DrumState drum_state(const FlowSolver& solver, double Phi_level, double radius, double v_flow, const DrumShape* shape = nullptr);

}  // namespace granseg
