// What a flow run writes: gnuplot tables of fields and profiles, legacy VTK files for ParaView,
// and the solver's work and the run's cost as columns of a summary row.
//
//   solves      nothing: tabulates a FlowSolver's state
//   inputs      a FlowSolver after a step; a run's cost
//   outputs     DataTables (fields, profiles), VTK text, summary columns
#pragma once

#include "flow/flow_solver.hpp"
#include "run/output.hpp"
#include "run/progress.hpp"

#include <string>

namespace granseg {

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

/// Appends the solver's work to a summary row: steps_X, the steps whose dt the bound X set
/// (docs/flow_solver.md Sect. 2, step_size), the semi-implicit step's pressure_solves, newton and krylov
/// iterations (0 in the explicit step), the temperature solves' conjugate-gradient iterations,
/// and seconds_S, the wall-clock seconds of each stage S of the step (FlowStage).
void append_flow_work(const FlowSolver& solver, TableRow& row);

/// Appends a run's cost to a summary row: wall_seconds, cpu_seconds (every thread of the process:
/// CPU over wall says how many cores the run kept busy) and threads (core/threads.hpp).
void append_run_time(const RunTime& cost, TableRow& row);

}  // namespace granseg
