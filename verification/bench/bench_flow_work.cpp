// Work against error of the flow solver's two time-stepping modes (docs/flow_solver.md Sect. 3): for each
// mode and resolution, the error against an independent reference and the cost of the solve: the
// CPU time (CLOCK_PROCESS_CPUTIME_ID) and the wall time (steady_clock) of the solver's time loop
// only, one thread, medians of kRepeats runs (the set-up, e.g. the manufactured sources, is not
// timed; on a shared machine the CPU time is the robust one). Two problems:
//   manufactured  the manufactured solution of verify_flow_order (harness/manufactured_flow.hpp),
//                 n x n cells, n = 16 .. 128: mean |error| of Phi, u, T at t_end. The explicit
//                 step is bound by the sound speed (c dt/h ~ 0.5); the semi-implicit step by
//                 dt_max = k h, k = 0.25, 1, 4 s/m (c dt/h ~ 2.3, 9, 36 at c = 9.1 m/s) or by
//                 its own bounds (docs/flow_solver.md Sect. 2, step_size), since its error against its
//                 cost depends on dt; its cfl on |u| does not bind (|u| <= 0.075 m/s);
//   incline       the layer on the inclined plane of verify_flow_incline (harness/incline_flow.hpp),
//                 nz = 16 .. 128 cells: the profiles after 2 s at the solver's own critical angle
//                 against the boundary-value solution (max |u - u_bvp|/u_bvp(depth), max |Phi -
//                 Phi_bvp(GSL)|, spread of T), timed; and the critical angle found by bisection
//                 (11 runs of 1.5 s) against atan(mu), its time the sum of the 11 runs (once, not
//                 a median). The semi-implicit step with the default dt_max = 1e-3 s and with 1e-4 s.
// Also the conjugate-gradient iterations of the pressure solves per step. It reports; it asserts
// nothing. The load average is written before and after. Writes bench_flow_work.dat (one gnuplot
// index per curve, see its header) for figures/bench_flow_work.gp, and prints the table.
//
// Run: build/bench/bench_flow_work [--data DIR]   (about 5 minutes of CPU time on one core)
#include "harness/flow_reference.hpp"
#include "harness/incline_flow.hpp"
#include "harness/manufactured_flow.hpp"
#include "harness/program.hpp"

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

using namespace granseg;

namespace {

constexpr int kRepeats = 3;
constexpr int kSizes[] = {16, 32, 64, 128};
constexpr double kStepPerLength[] = {0.25, 1.0, 4.0};  // s/m: semi-implicit dt_max = k h (manufactured)
constexpr double kInclineDtMax[] = {1e-3, 1e-4};       // s: semi-implicit dt_max (incline)
constexpr double kProfileTime = 2.0;                   // s, as verify_flow_incline

/// One curve: a mode and its time-step rule (0 for the explicit step's sound-speed bound).
struct Variant {
    TimeStepping mode;
    double rule;        // manufactured: k in dt_max = k h (s/m); incline: dt_max (s)
    int largest = 128;  // the finest resolution run
};

FlowSettings settings_for(const Variant& v, double dt_max) {
    FlowSettings s;
    s.time_stepping = v.mode;
    if (v.mode == TimeStepping::semi_implicit) s.dt_max = dt_max;
    return s;
}

std::string label(const Variant& v, const char* unit) {
    if (v.mode == TimeStepping::explicit_waves) return "explicit";
    char text[64];
    std::snprintf(text, sizeof text, "semi %g %s", v.rule, unit);
    return text;
}

void manufactured(const Material& m, DataTable& table) {
    std::vector<Variant> variants{{TimeStepping::explicit_waves, 0.0}};
    // k = 4 s/m: the step's own bounds hold dt near 1 ms, its error stalls; n = 128 would only add cost.
    for (double k : kStepPerLength) variants.push_back({TimeStepping::semi_implicit, k, k > 1.0 ? 64 : 128});
    std::vector<verify::ManufacturedFlow> problems;
    for (int n : kSizes) problems.emplace_back(m, n);
    std::printf("manufactured solution (t_end = %g s), mean |error| at t_end\n", verify::kManufacturedEnd);
    std::printf("%-18s %5s %7s %10s %7s %10s %10s %10s %10s %10s\n", "mode (dt_max/h)", "n", "steps", "dt (s)", "CG/step",
                "CPU (s)", "wall (s)", "Phi", "u (m/s)", "T (m2/s2)");
    for (const Variant& v : variants) {
        for (std::size_t i = 0; i < problems.size() && kSizes[i] <= v.largest; ++i) {
            const int n = kSizes[i];
            const FlowSettings s = settings_for(v, v.rule * verify::kManufacturedSide / n);
            std::vector<double> cpu, wall;
            verify::ManufacturedRun r;
            for (int k = 0; k < kRepeats; ++k) {
                r = problems[i].run(s);
                cpu.push_back(r.time.cpu), wall.push_back(r.time.wall);
            }
            const double dt = verify::kManufacturedEnd / r.steps;
            const double cg = static_cast<double>(r.work.krylov) / r.steps;
            table.row({{"problem", 0.0},
                       {"semi_implicit", static_cast<double>(v.mode == TimeStepping::semi_implicit)},
                       {"dt_rule", v.rule},
                       {"n", static_cast<double>(n)},
                       {"steps", static_cast<double>(r.steps)},
                       {"dt_mean", dt},
                       {"cg_per_step", cg},
                       {"cpu_seconds", verify::median(cpu)},
                       {"wall_seconds", verify::median(wall)},
                       {"error_Phi", r.error_Phi},
                       {"error_u", r.error_u},
                       {"error_T", r.error_T},
                       {"angle_cpu_seconds", 0.0},
                       {"angle_wall_seconds", 0.0},
                       {"angle_error_deg", 0.0}});
            std::printf("%-18s %5d %7ld %10.3g %7.1f %10.3g %10.3g %10.3g %10.3g %10.3g\n", label(v, "s/m").c_str(), n, r.steps,
                        dt, cg, verify::median(cpu), verify::median(wall), r.error_Phi, r.error_u, r.error_T);
            std::fflush(stdout);
        }
        table.blank();
        table.blank();
    }
}

void incline(const Material& m, DataTable& table) {
    const double theta_mu = std::atan(std::sqrt(2.0 * m.eta0 * m.eps0 / 3.0)) * 180.0 / M_PI;
    std::vector<Variant> variants{{TimeStepping::explicit_waves, 0.0}};
    for (double dt_max : kInclineDtMax) variants.push_back({TimeStepping::semi_implicit, dt_max});
    std::printf(
        "\ninclined plane: profiles after %g s at the solver's critical angle theta_c; theta_c - atan(mu) "
        "(atan(mu) = %.4f deg)\n",
        kProfileTime, theta_mu);
    std::printf("%-18s %5s %7s %10s %7s %10s %10s %10s %10s %10s %10s %10s\n", "mode (dt_max)", "nz", "steps", "dt (s)",
                "CG/step", "CPU (s)", "wall (s)", "u rel.", "Phi", "T spread", "angle CPU", "angle err");
    for (const Variant& v : variants) {
        const FlowSettings s = settings_for(v, v.rule);
        for (int nz : kSizes) {
            verify::Timing angle_time;
            const double theta_c = verify::critical_angle(m, s, nz, &angle_time);
            std::vector<double> cpu, wall;
            verify::InclineRun r;
            for (int k = 0; k < kRepeats; ++k) {
                r = verify::run_incline(m, s, theta_c, nz, kProfileTime);
                cpu.push_back(r.time.cpu), wall.push_back(r.time.wall);
            }
            const verify::InclineProfileErrors e = verify::incline_profile_errors(m, r, theta_c);
            const double dt = kProfileTime / r.steps, angle_error = std::fabs(theta_c - theta_mu);
            const double cg = static_cast<double>(r.work.krylov) / r.steps;
            table.row({{"problem", 1.0},
                       {"semi_implicit", static_cast<double>(v.mode == TimeStepping::semi_implicit)},
                       {"dt_rule", v.rule},
                       {"n", static_cast<double>(nz)},
                       {"steps", static_cast<double>(r.steps)},
                       {"dt_mean", dt},
                       {"cg_per_step", cg},
                       {"cpu_seconds", verify::median(cpu)},
                       {"wall_seconds", verify::median(wall)},
                       {"error_Phi", e.Phi},
                       {"error_u", e.u},
                       {"error_T", e.T_spread},
                       {"angle_cpu_seconds", angle_time.cpu},
                       {"angle_wall_seconds", angle_time.wall},
                       {"angle_error_deg", angle_error}});
            std::printf("%-18s %5d %7ld %10.3g %7.1f %10.3g %10.3g %10.3g %10.3g %10.3g %10.3g %10.3g\n", label(v, "s").c_str(),
                        nz, r.steps, dt, cg, verify::median(cpu), verify::median(wall), e.u, e.Phi, e.T_spread, angle_time.cpu,
                        angle_error);
            std::fflush(stdout);
        }
        table.blank();
        table.blank();
    }
}

}  // namespace

int main(int argc, char** argv) {
    const auto [options, m] = verify::flow_program(argc, argv);  // one OpenMP thread
    const std::string load_before = verify::load_average();
    DataTable table;
    table.comment(
        "problem 0 manufactured solution (n x n cells; errors: mean |error| of Phi, |u| in m/s, T in m^2/s^2 at "
        "t_end), 1 inclined plane (nz cells; errors after 2 s at the solver's critical angle: max |Phi - Phi_bvp|, "
        "max |u - u_bvp|/u_bvp(depth), relative spread of T; angle: |theta_c - atan(mu)| by bisection, its CPU "
        "time the sum of 11 runs)");
    table.comment(
        "dt_rule: 0 explicit (sound speed); semi-implicit: manufactured k in dt_max = k h (s/m), incline dt_max "
        "(s); dt_mean = simulated time / steps; cg_per_step: conjugate-gradient iterations of the pressure solves "
        "per step; cpu_seconds (CLOCK_PROCESS_CPUTIME_ID), wall_seconds (steady_clock): the solver's time "
        "loop, one thread, medians of " +
        std::to_string(kRepeats) +
        " runs; one gnuplot index per (problem, "
        "mode, dt_rule), in the order of the rows");
    table.comment("load average before: " + load_before);
    manufactured(m, table);
    incline(m, table);
    table.comment("load average after: " + verify::load_average());
    verify::write_data(options, "bench_flow_work.dat", table);
    std::printf("\nload average before: %s, after: %s\n", load_before.c_str(), verify::load_average().c_str());
    return 0;
}
