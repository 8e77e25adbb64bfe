// The runs of the Fig. 7 solution-verification study (bench_fig7_convergence): which variants of
// verification/scenes/tumbler.toml to run, running them (or reusing an earlier run of the same
// scene text), and reading the Fig. 7 quantities and their sampling errors from each run's files.
//
// Every run is the paper's coupled drum with some keys changed and written, with its outputs, under
// DIR/fig7_convergence/NAME.toml and NAME/ (so `granseg run NAME.toml` repeats it); no frames or VTK.
//   grid      the default time stepping at each --cells, the explicit one at each --explicit-cells
//   dt        the default time stepping at --dt-cells with dt_max halved and doubled
//   tracer    a passive tracer in the core (S = 0, packing feedback off, closures of the 0.5
//             mixture via [coupling] mixture, phi_hat = 1 within r_core, 0 elsewhere) at each --cells
//   floor     the full model and the tracer at the finest --cells with T_floor lowered to --T-floor-low
#pragma once

#include <array>
#include <string>
#include <vector>

namespace granseg::verify {

/// The study's settings (bench_fig7_convergence's command line; defaults: the real study).
struct Fig7Options {
    std::string data_dir = "build/bench-data";
    std::vector<int> cells{50, 71, 100};         // default time stepping, coarse to fine
    std::vector<int> explicit_cells{50, 71};     // explicit time stepping (none, two or more)
    int dt_cells = 0;                            // the dt study's grid (0: the finest of cells)
    bool dt_study = true, core_study = true;
    double t_end = 25.0, average_from = 10.0;    // s; the angle and layer are averaged over t >= average_from
    double jitter_window = 2.5;                  // s before t_end over which a value at t_end jitters
    double T_floor_low = 1e-14;                  // m^2/s^2, the floor run's T_floor
    int threads = 1;                             // OpenMP threads of every run
    int lanes = 0;                               // runs side by side (0: one per core; > 1 needs threads = 1)
    std::string transport;                       // [flow] transport of every run ("": the scene's)
    bool reuse = false;                          // reuse a run whose scene text is unchanged
};

enum class Fig7Kind { grid, dt, tracer, floor, tracer_floor };

struct Fig7Run {
    std::string name;           // also its directory under DIR/fig7_convergence
    Fig7Kind kind = Fig7Kind::grid;
    bool explicit_steps = false;
    int cells = 0;
    double dt_factor = 1.0;     // dt_max relative to the scene's
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
    double scale;  // summary and history values times scale = the value in `unit`
    double lower, upper;  // physical range (in `unit`): an extrapolation outside it is flagged
};
constexpr int kFig7Quantities = 8;
const std::array<Fig7Quantity, kFig7Quantities>& fig7_quantities();

/// What a run measured.
struct Fig7Result {
    Fig7Run run;
    double wall = 0, cpu = 0, steps = 0, dt_mean = 0, h = 0;  // s, s (all threads), -, s (t_end / steps), m
    std::array<double, kFig7Quantities> value{}, sampling{};  // sampling: the standard error of a time
                                                              // average, or the jitter of a value at t_end
    double initial_mixture = 0, packing_spread = 0;
};

/// A number of the study's scene (verification/scenes/tumbler.toml), or `fallback` where the scene
/// leaves the key to its default.
double fig7_scene_number(const char* section, const char* key, double fallback);

/// The runs the options ask for, in the order they are run: grid runs coarse to fine, then the dt,
/// tracer and floor runs.
std::vector<Fig7Run> plan_fig7_runs(const Fig7Options& options);

/// Runs `run` (or, with options.reuse, reuses an earlier run of the same scene text) and reads its
/// quantities. InputError or InvariantError from the run pass through.
Fig7Result run_fig7(const Fig7Run& run, const Fig7Options& options);

}  // namespace granseg::verify
