// The runs of the Fig. 7 solution-verification study (bench_fig7_convergence): which variants of
// verification/scenes/tumbler.toml to run, running them (or reusing an earlier run of the same
// scene text), and reading the Fig. 7 quantities, their sampling errors and the steps' bounds from
// each run's files.
//
// The time step refines with the grid: every run takes dt_max = dt_ref (kDtRefCells / cells), so
// that dt is proportional to h (a constant Courant number of dt_max); dt_ref is chosen so that
// dt_max, not the CFL, outflow or compaction bound, sets the steps on every grid, which each run's
// step counts by bound show (summary.dat steps_dt_max against steps). A grid's error is then the
// grid's and its time step's together, both first order, shrinking with h at one rate.
//
// Every run is the paper's coupled drum with some keys changed and written, with its outputs, under
// DIR/fig7_convergence/NAME.toml and NAME/ (so `granseg run NAME.toml` repeats it); no frames or VTK.
// Each run keeps its checkpoint there: a study killed and started again skips the runs that
// finished and resumes those that were interrupted.
//   grid      each [flow] transport of --transports at each --cells; the explicit time stepping
//             at each --explicit-cells
//   dt        the first transport at the coarsest grid with dt_max times each --dt-coarse factor,
//             and at the finest with each --dt-fine factor (factors below 1: dt_max keeps binding)
//   tracer    the full model (S and packing feedback as in the paper's run) with a passive tracer
//             ([initial] tracer = 1 within the drum's own core r_core_layer of the reference
//             transport's grid run at that grid, 0 elsewhere; the tracer does not act on the flow,
//             so the run repeats that grid run) at each --cells
//   floor     the same at the second-finest --cells with T_floor lowered to --T-floor-low
#pragma once

#include <array>
#include <cmath>
#include <string>
#include <vector>

namespace granseg::verify {

/// The grid at which dt_max equals Fig7Options::dt_ref; dt_max scales as kDtRefCells / cells.
constexpr int kDtRefCells = 50;

/// The study's settings (bench_fig7_convergence's command line; defaults: the real study).
struct Fig7Options {
    std::string data_dir = "build/bench-data";
    std::string study_dir = "fig7_convergence";  // the runs go to data_dir/study_dir/NAME
    std::vector<int> cells{50, 70, 100, 140};    // coarse to fine (even counts keep the axis on a vertex)
    std::vector<std::string> transports{"muscl",
                                        "donor-cell"};  // [flow] transport of the grid series, the first is the reference
    std::vector<int> explicit_cells{};                  // explicit time stepping (none, two or more)
    double dt_ref = 2e-3;                               // s, dt_max at kDtRefCells cells per diameter
    std::vector<double> dt_coarse{0.5, 0.25};           // dt_max factors of the dt study at the coarsest grid
    std::vector<double> dt_fine{0.5};                   // and at the finest
    bool dt_study = true, core_study = true;
    double t_end = 25.0, average_from = 10.0;        // s; the angle and layer are averaged over t >= average_from
    double jitter_window = 2.5;                      // s before t_end over which a value at t_end jitters
    double T_floor_low = 1e-14;                      // m^2/s^2, the floor run's T_floor
    int threads = 1;                                 // OpenMP threads of every run
    int lanes = 0;                                   // runs side by side (0: one per core; > 1 needs threads = 1)
    bool reuse = false;                              // reuse a run whose scene text is unchanged
    std::string program = "bench_fig7_convergence";  // named in each run's scene file

    /// dt_max of a run at `cells` with the dt study's factor.
    double dt_max(int cells, double factor = 1.0) const { return factor * dt_ref * kDtRefCells / cells; }
};

enum class Fig7Kind { grid, dt, tracer, floor };

struct Fig7Run {
    std::string name;  // also its directory under DIR/fig7_convergence
    Fig7Kind kind = Fig7Kind::grid;
    bool explicit_steps = false;
    int cells = 0;
    double dt_factor = 1.0;             // dt_max relative to the grid's (Fig7Options::dt_max)
    std::string transport;              // [flow] transport ("" for the explicit time stepping)
    double dt_max = 0;                  // s
    bool packing_feedback = true;       // [coupling] packing_feedback
    double S = NAN;                     // [segregation] S; NaN: the scene's
    double min_shear_rate = 0;          // [segregation] diagnostic_min_shear_rate, 1/s (0: off, the scene's)
    double acoustic_courant_max = NAN;  // [flow] acoustic_courant_max; NaN: the scene's (the coupled drum's default)
};

/// The Fig. 7 quantities, in the order of every table: name, unit, whether it is a time average
/// over t >= average_from (else the value at t_end), and the summary.dat / history.dat column.
struct Fig7Quantity {
    const char* name;
    const char* label;
    const char* unit;
    bool time_average;
    const char* summary_column;
    const char* history_column;
    double scale;         // summary and history values times scale = the value in `unit`
    double lower, upper;  // physical range (in `unit`): an extrapolation outside it is flagged
};
constexpr int kFig7Quantities = 8;
/// Where each quantity sits in fig7_quantities() and in every array indexed like it.
enum Fig7QuantityIndex : int { kAngle, kLayer, kIndex, kRing, kPeriphery, kCore, kContrast, kAxis };
const std::array<Fig7Quantity, kFig7Quantities>& fig7_quantities();

/// What a run measured.
struct Fig7Result {
    Fig7Run run;
    double wall = 0, cpu = 0, steps = 0, dt_mean = 0, h = 0;  // s, s (all threads), -, s (t_end / steps), m
    double dt_max_share = 0;                                  // share of the steps whose dt dt_max set
    double acoustic_share = 0;                                // and the acoustic bound (src/flow/time_step.hpp)
    std::array<double, kFig7Quantities> value{}, sampling{};  // sampling: the standard error of a time
                                                              // average, or the jitter of a value at t_end
    double initial_mixture = 0, packing_spread = 0;
    double tracer = NAN, tracer_sampling = NAN;  // tracer and floor runs: the tracer's share of the core at t_end
    double points = NAN, points_sampling = NAN;  // and the material points' (no numerical diffusion)
};

/// A number of the study's scene (verification/scenes/tumbler.toml), or `fallback` where the scene
/// leaves the key to its default.
double fig7_scene_number(const char* section, const char* key, double fallback);

/// The runs the options ask for, in the order they are run: grid runs coarse to fine (each
/// transport), the explicit runs, then the dt, tracer and floor runs.
std::vector<Fig7Run> plan_fig7_runs(const Fig7Options& options);

/// Runs `run` (or, with options.reuse, reuses an earlier run of the same scene text) and reads its
/// quantities. A run whose checkpoint is of the same scene and build is only written out again if
/// it finished, or continued if it was interrupted (Resume::if_compatible). InputError or
/// InvariantError from the run pass through.
Fig7Result run_fig7(const Fig7Run& run, const Fig7Options& options);

}  // namespace granseg::verify
