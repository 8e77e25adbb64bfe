#include "flow/flow_tables.hpp"

#include "closures/closures.hpp"
#include "core/error.hpp"
#include "core/format.hpp"
#include "core/threads.hpp"
#include "run/progress.hpp"

#include <cmath>
#include <cstdio>
#include <sstream>
#include <utility>
#include <vector>

namespace granseg {

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

}  // namespace granseg
