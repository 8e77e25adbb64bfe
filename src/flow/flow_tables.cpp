#include "flow_run/flow_output.hpp"

#include "closures/closures.hpp"
#include "core/error.hpp"
#include "core/format.hpp"
#include "core/progress.hpp"
#include "core/threads.hpp"

#include <cmath>
#include <cstdio>
#include <sstream>
#include <utility>
#include <vector>

namespace granseg {

RunTime advance_flow(FlowSolver& solver, double t_end, const std::string& label, const std::function<void()>& after_step,
                     RunCheckpoints* checkpoints, const RunState& state) {
    RunCheckpoints& saves = checkpoints_or_none(checkpoints);
    const double mass0 = solver.mass(), t0 = solver.time();
    Progress progress(label, t_end, t0);
    while (solver.time() < t_end) {
        saves.before_step(solver.time(), t_end, solver.settings().dt_max, state);
        solver.step(t_end);
        if (after_step) after_step();
        progress.update(solver.time());
        const double drift = std::fabs(solver.mass() - mass0) / mass0;
        if (!(drift <= kMassDriftLimit))
            throw InvariantError(label + ": mass changed by " + format_number(drift) +
                                 " (relative) between t = " + format_number(t0) + " and " + format_number(solver.time()) + " s");
        saves.after_step(solver.time(), solver.steps(), state);
    }
    saves.finish(solver.time(), solver.steps(), state);
    return progress.finish(run_threads(solver.grid().cells())) + saves.earlier();
}

namespace {

/// The pressure of a cell from the closures (0 outside).
double cell_pressure(const FlowSolver& s, std::size_t c) {
    if (!s.grid().is_inside(c)) return 0.0;
    const std::array<double, 2> lim = s.packing(c);
    return evaluate_closures_at(s.material(), s.Phi()[c], s.T()[c], lim[0], lim[1]).p;
}

}  // namespace

DataTable flow_field_table(const FlowSolver& s, bool lab) {
    const Grid& g = s.grid();
    DataTable table;
    table.comment(std::string(lab ? "lab" : "rotating") + " frame, t = " + format_number(s.time()) +
                  " s; slice j = 0; one block per row; units m, m/s, m^2/s^2");
    for (int k = 0; k < g.n[2]; ++k) {
        for (int i = 0; i < g.n[0]; ++i) {
            const std::size_t c = g.index(i, 0, k);
            const bool in = g.is_inside(c);
            double x = g.center(0, i), z = g.center(2, k), ux = s.u(0)[c], uz = s.u(2)[c];
            if (lab) {
                const auto xz = s.frame().to_lab_position(s.time(), x, z);
                const auto v = s.frame().to_lab_velocity(s.time(), x, z, ux, uz);
                x = xz[0], z = xz[1], ux = in ? v[0] : 0.0, uz = in ? v[1] : 0.0;
            }
            table.row({{"x", x},
                       {"z", z},
                       {"Phi", in ? s.Phi()[c] : 0.0},
                       {"u_x", ux},
                       {"u_y", s.u(1)[c]},
                       {"u_z", uz},
                       {"T", in ? s.T()[c] : 0.0},
                       {"p", cell_pressure(s, c)},
                       {"inside", in ? 1.0 : 0.0}});
        }
        table.blank();
    }
    return table;
}

DataTable flow_column_table(const FlowSolver& s) {
    const Grid& g = s.grid();
    DataTable table;
    table.comment("t = " + format_number(s.time()) + " s; units m, m/s, m^2/s^2");
    for (int k = 0; k < g.n[2]; ++k) {
        const std::size_t c = g.index(0, 0, k);
        table.row({{"z", g.center(2, k)},
                   {"Phi", s.Phi()[c]},
                   {"u_x", s.u(0)[c]},
                   {"u_z", s.u(2)[c]},
                   {"T", s.T()[c]},
                   {"p", cell_pressure(s, c)}});
    }
    return table;
}

std::string flow_vtk(const FlowSolver& s) {
    const Grid& g = s.grid();
    const int nx = g.n[0], nz = g.n[2];
    std::ostringstream out;
    out.precision(9);
    out << "# vtk DataFile Version 3.0\ngranseg flow, lab frame, t = " << s.time() << " s\nASCII\n"
        << "DATASET STRUCTURED_GRID\nDIMENSIONS " << nx + 1 << " " << nz + 1 << " 1\nPOINTS " << (nx + 1) * (nz + 1)
        << " double\n";
    for (int k = 0; k <= nz; ++k)
        for (int i = 0; i <= nx; ++i) {
            const auto xz = s.frame().to_lab_position(s.time(), g.origin[0] + i * g.h[0], g.origin[2] + k * g.h[2]);
            out << xz[0] << " " << xz[1] << " 0\n";
        }
    out << "CELL_DATA " << nx * nz << "\n";
    auto scalar = [&](const char* name, const std::function<double(std::size_t)>& f) {
        out << "SCALARS " << name << " double 1\nLOOKUP_TABLE default\n";
        for (int k = 0; k < nz; ++k)
            for (int i = 0; i < nx; ++i) out << f(g.index(i, 0, k)) << "\n";
    };
    scalar("Phi", [&](std::size_t c) { return g.is_inside(c) ? s.Phi()[c] : 0.0; });
    scalar("T", [&](std::size_t c) { return g.is_inside(c) ? s.T()[c] : 0.0; });
    scalar("p", [&](std::size_t c) { return cell_pressure(s, c); });
    scalar("inside", [&](std::size_t c) { return g.is_inside(c) ? 1.0 : 0.0; });
    out << "VECTORS velocity double\n";
    for (int k = 0; k < nz; ++k)
        for (int i = 0; i < nx; ++i) {
            const std::size_t c = g.index(i, 0, k);
            const auto v = s.frame().to_lab_velocity(s.time(), g.center(0, i), g.center(2, k), s.u(0)[c], s.u(2)[c]);
            const bool in = g.is_inside(c);
            out << (in ? v[0] : 0.0) << " " << (in ? s.u(1)[c] : 0.0) << " " << (in ? v[1] : 0.0) << "\n";
        }
    return out.str();
}

void append_flow_work(const FlowSolver& solver, TableRow& work) {
    const FlowCounters& counts = solver.counters();
    for (int b = 0; b < kStepBounds; ++b)
        work.add(std::string("steps_") + step_bound_name(static_cast<StepBound>(b)), static_cast<double>(counts.set_by[b]));
    work.add({{"pressure_solves", static_cast<double>(counts.pressure_solves)},
              {"newton", static_cast<double>(counts.newton)},
              {"krylov", static_cast<double>(counts.krylov)},
              {"temperature_iterations", static_cast<double>(counts.temperature_iterations)}});
    for (int k = 0; k < kFlowStages; ++k)
        work.add(std::string("seconds_") + flow_stage_name(static_cast<FlowStage>(k)), solver.timers().seconds[k]);
}

void append_run_time(const RunTime& cost, TableRow& row) {
    row.add({{"wall_seconds", cost.wall}, {"cpu_seconds", cost.cpu}, {"threads", static_cast<double>(cost.threads)}});
}

DrumState drum_state(const FlowSolver& s, double Phi_level, double radius, double v_flow, const DrumShape* shape) {
    const Grid& g = s.grid();
    const Frame& f = s.frame();
    DrumState d{};
    // Crossings of Phi = Phi_level along x and z between neighbouring inside cells (slice j = 0).
    std::vector<std::array<double, 2>> points;
    for (int k = 0; k < g.n[2]; ++k)
        for (int i = 0; i < g.n[0]; ++i) {
            const std::size_t c = g.index(i, 0, k);
            if (!g.is_inside(c)) continue;
            for (int a : {0, 2}) {
                const int ni = a == 0 ? i + 1 : i, nk = a == 2 ? k + 1 : k;
                if (ni >= g.n[0] || nk >= g.n[2] || !g.is_inside(g.index(ni, 0, nk))) continue;
                const double p0 = s.Phi()[c], p1 = s.Phi()[g.index(ni, 0, nk)];
                if ((p0 - Phi_level) * (p1 - Phi_level) >= 0.0 || p0 == p1) continue;
                const double w = (Phi_level - p0) / (p1 - p0);
                const double x = g.center(0, i) + (a == 0 ? w * g.h[0] : 0.0), z = g.center(2, k) + (a == 2 ? w * g.h[2] : 0.0);
                const double r = shape ? shape->gauge(x - f.x_c, z - f.z_c) : std::hypot(x - f.x_c, z - f.z_c);
                if (r < radius) points.push_back({x, z});
            }
        }
    d.surface_points = static_cast<int>(points.size());
    d.surface_angle_deg = NAN;
    d.surface_distance = d.surface_offset = d.surface_direction = NAN;
    if (points.size() >= 2) {
        double mx = 0, mz = 0;
        for (const auto& p : points) mx += p[0], mz += p[1];
        mx /= points.size(), mz /= points.size();
        double sxx = 0, sxz = 0, szz = 0;
        for (const auto& p : points)
            sxx += (p[0] - mx) * (p[0] - mx), sxz += (p[0] - mx) * (p[1] - mz), szz += (p[1] - mz) * (p[1] - mz);
        const double theta = 0.5 * std::atan2(2 * sxz, sxx - szz);  // principal direction of the points
        d.surface_offset = -(mx - f.x_c) * std::sin(theta) + (mz - f.z_c) * std::cos(theta);
        d.surface_distance = std::fabs(d.surface_offset);
        d.surface_direction = theta;
        const Vec3 gv = f.gravity_at(s.time());
        const double horizontal = std::atan2(gv[0], -gv[2]);  // direction of g rotated by +90 degrees
        double angle = theta - horizontal;
        while (angle > M_PI / 2) angle -= M_PI;
        while (angle <= -M_PI / 2) angle += M_PI;
        // Measured counter-clockwise; a drum turning clockwise lifts the surface the other way.
        d.surface_angle_deg = (f.omega < 0.0 ? -1.0 : 1.0) * angle * 180.0 / M_PI;
    }
    double mass = 0.0, flowing = 0.0;
    const double cell_area = g.cell_volume() / (g.n[1] * g.h[1]);
    for (std::size_t c = 0; c < g.cells(); ++c) {
        if (!g.is_inside(c)) continue;
        const double speed = std::sqrt(s.u(0)[c] * s.u(0)[c] + s.u(1)[c] * s.u(1)[c] + s.u(2)[c] * s.u(2)[c]);
        mass += s.Phi()[c];
        if (speed > v_flow) flowing += s.Phi()[c];
        if (s.Phi()[c] > Phi_level) d.max_speed = std::max(d.max_speed, speed);
        if (s.Phi()[c] > Phi_level && speed > v_flow) d.flowing_area += cell_area;
        d.kinetic_energy += 0.5 * s.Phi()[c] * speed * speed * g.cell_volume();
    }
    d.flowing_fraction = mass > 0.0 ? flowing / mass : 0.0;
    if (!(v_flow > 0.0)) d.flowing_fraction = d.flowing_area = NAN;  // a drum at rest: no wall speed to measure by
    return d;
}

}  // namespace granseg
