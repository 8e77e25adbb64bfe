#include "scenes/segregation1d.hpp"

#include "core/format.hpp"
#include "run/run_loop.hpp"
#include "segregation/column.hpp"
#include "segregation/invariants.hpp"
#include "segregation/segregation_solver.hpp"

#include <algorithm>
#include <cmath>

namespace granseg {

namespace {

// Invariants are checked every this many steps (and after the last one).
constexpr long kCheckEvery = 1000;

struct Segregation1d : SceneJob {
    Column column;
    std::vector<double> phi;
    SegregationOptions options;
    double t_end = 0.0;

    OutputSet run() override {
        SegregationSolver solver(column.grid, options);
        const bool bounded = preserves_bounds(options.scheme);
        const double Phi_max = *std::max_element(column.fields.Phi.begin(), column.fields.Phi.end());
        const double mass0 = total_amount(column.grid, phi);
        BoundsMonitor bounds;
        const auto check = [&] {
            check_segregation_invariants("segregation1d", bounds, solver.largest_correction(), mass0,
                                         total_amount(column.grid, phi), mass0, kAmountTolerance, bounded, Phi_max);
        };
        const double dt_max = solver.time_step(column.fields);
        double t = 0.0;
        long steps = 0;
        RunLoop loop;
        loop.label = "segregation1d", loop.t_end = t_end;
        loop.time = [&] { return t; };
        loop.steps = [&] { return steps; };
        loop.step = [&] { solver.step_towards(column.fields, dt_max, t_end, t, phi), ++steps; };
        loop.observers.push_back([&] {
            bounds.observe(column.grid, phi, column.fields.Phi);
            if (steps % kCheckEvery == 0) check();
        });
        run_loop(loop);
        check();

        DataTable table;
        table.comment("segregation1d: scheme " + scheme_name(options.scheme) + ", t = " + format_number(t_end) +
                      ", cfl = " + format_number(options.cfl) + ", " + std::to_string(steps) + " steps, " +
                      std::to_string(solver.cell_updates()) + " cell updates");
        table.comment("max over the run of phi - Phi: " + format_number(bounds.max_excess, 4) + "; min of phi: " +
                      format_number(bounds.min_phi, 4) + "; round-off clip: " + format_number(solver.largest_correction(), 3) +
                      "; relative change of sum(phi): " + format_number((total_amount(column.grid, phi) - mass0) / mass0, 3));
        for (std::size_t k = 0; k < phi.size(); ++k)
            table.row({{"z", column.z[k]}, {"Phi", column.fields.Phi[k]}, {"T", column.T[k]}, {"phi", phi[k]}});
        OutputSet out;
        out.add("profile.dat", table);
        return out;
    }
};

/// Evaluates `f` at every point, failing with "[initial] KEY: ... at z = ..." at the first bad one.
void require_at_points(const SceneFile& scene, const std::string& key, const std::vector<double>& z,
                       const std::function<double(double)>& f, const std::function<bool(double)>& ok, const std::string& allowed,
                       const char* where) {
    for (double p : z) {
        const double v = f(p);
        if (!ok(v))
            scene.fail("initial", key, key + " = " + format_number(v) + " at z = " + format_number(p) + " (" + where + ")",
                       allowed);
    }
}

}  // namespace

std::unique_ptr<SceneJob> prepare_segregation1d(const SceneFile& scene) {
    auto job = std::make_unique<Segregation1d>();
    ColumnSetup setup;
    setup.cells = static_cast<int>(scene.integer("grid", "cells", 1, 10000000));
    setup.length = scene.number("grid", "length", Range::above(0), 1.0);
    job->t_end = scene.number("time", "end", Range::above(0));
    job->options.cfl = scene.number("time", "cfl", Range::above(0), 0.9);
    if (job->options.cfl > 1.0)
        scene.fail("time", "cfl",
                   format_number(job->options.cfl) + " > 1: the step would exceed the largest one that keeps 0 <= phi <= Phi",
                   "0 < cfl <= 1");
    setup.S = scene.number("segregation", "S", Range::at_least(0), 1.0);
    setup.D = scene.number("segregation", "D", Range::at_least(0), 0.0);
    job->options.scheme = parse_scheme(scene.choice("segregation", "scheme", scheme_names(), "modified-godunov"));
    job->options.limiter = parse_limiter(scene.choice("segregation", "limiter", limiter_names(), "mc"));
    setup.interface = parse_interface_rule(scene.choice("segregation", "interface", interface_rule_names(), "exact"));
    const Expression Phi = scene.expression("initial", "Phi", {"z"});
    const Expression T = scene.expression("initial", "T", {"z"});
    const Expression phi = scene.expression("initial", "phi", {"z", "Phi", "T"});
    setup.Phi = [Phi](double z) { return Phi({z}); };
    setup.T = [T](double z) { return T({z}); };

    // Every value the run reads must be in range: Phi and T at the centres, and at the faces too
    // where a classic scheme evaluates them there.
    const double h = setup.length / setup.cells;
    std::vector<double> centres, faces;
    for (int k = 0; k < setup.cells; ++k) centres.push_back((k + 0.5) * h);
    for (int k = 0; k <= setup.cells; ++k) faces.push_back(k * h);
    const auto Phi_ok = [](double v) { return v > 0.0 && v < 1.0; };
    const auto T_ok = [](double v) { return v >= 0.0 && std::isfinite(v); };
    require_at_points(scene, "Phi", centres, setup.Phi, Phi_ok, "0 < Phi < 1 everywhere on the grid", "cell centre");
    require_at_points(scene, "T", centres, setup.T, T_ok, "finite T >= 0 everywhere on the grid", "cell centre");
    if (!uses_interface_values(job->options.scheme)) {
        setup.interface = InterfaceRule::mean;  // not read; built from the centre values checked above
    } else if (setup.interface == InterfaceRule::exact) {
        require_at_points(scene, "Phi", faces, setup.Phi, Phi_ok, "0 < Phi < 1 everywhere on the grid", "cell face");
        require_at_points(scene, "T", faces, setup.T, T_ok, "finite T >= 0 everywhere on the grid", "cell face");
    }
    job->column = make_column(setup);
    for (std::size_t k = 0; k < centres.size(); ++k) {
        const double Phi_k = job->column.fields.Phi[k], T_k = job->column.T[k];
        const double v = phi({centres[k], Phi_k, T_k});
        if (!(v >= 0.0 && v <= Phi_k))
            scene.fail("initial", "phi",
                       "phi = " + format_number(v) + " outside [0, Phi = " + format_number(Phi_k) +
                           "] at z = " + format_number(centres[k]) + " (cell centre)",
                       "0 <= phi <= Phi everywhere on the grid");
        job->phi.push_back(v);
    }
    return job;
}

}  // namespace granseg
