// Scene kind "tumbler-flow": the rotating drum of Sect. 4.2 without segregation (keys:
// docs/scenes.md). The drum is at rest in the rotating frame; the bed starts at rest in the
// lithostatic balance with a flat surface at the fill height and T at its floor
// (docs/assumptions.md F8), and the drum starts turning at t = 0.
#include "scenes/flow_scenes.hpp"

#include "core/format.hpp"
#include "flow/bed.hpp"
#include "flow/flow_output.hpp"
#include "scenes/material_section.hpp"

#include <cmath>
#include <cstdio>
#include <vector>

namespace granseg {

namespace {

struct TumblerFlow : SceneJob {
    Material material;
    FlowSettings settings;
    Frame frame;
    double R = 0.05, fill_height = 0.075, t_end = 25.0, snapshot_every = 2.5, angle_from = 10.0;
    int cells = 100, axial_cells = 1;
    double axial_length = 0.01;
    bool vtk = true;

    explicit TumblerFlow(Material m) : material(std::move(m)) {}

    OutputSet run() override {
        const Grid grid = drum_grid(cells, R, axial_cells, axial_length);
        FlowSolver solver(grid, material, settings, frame);
        const double z_surface = -R + fill_height;
        const std::vector<double> Phi = lithostatic_bed(grid, material, z_surface, frame.gravity, settings.T_floor,
                                                        material.packing.Phi_rcp(settings.phi_hat),
                                                        material.packing.Phi_co(settings.phi_hat));
        const std::vector<double> zero(grid.cells(), 0.0), T(grid.cells(), settings.T_floor);
        solver.set_state(Phi, {zero, zero, zero}, T);

        // Diagnostics: the surface is the level half-way to the bed's Phi_co; "flowing" means
        // faster than 5% of the wall speed relative to the drum; the fit avoids the wall region.
        const double Phi_level = 0.5 * material.packing.Phi_co(settings.phi_hat);
        const double v_flow = 0.05 * std::fabs(frame.omega) * R;
        DataTable history({"t", "steps", "surface_angle_deg", "surface_points", "flowing_fraction", "max_speed",
                           "kinetic_energy", "mass", "mass_change", "dt"});
        history.comment("tumbler-flow: rotating-frame diagnostics; surface = Phi " + format_number(Phi_level) +
                        " contour within 0.8 R; flowing = |u| > " + format_number(v_flow) + " m/s");
        OutputSet out;
        std::vector<double> late_angles;  // surface angles sampled at t >= angle_from
        const double mass0 = solver.mass();  // before the first sample
        int snapshot = 0;
        double next_history = 0.0, next_snapshot = 0.0;
        auto sample = [&] {
            if (solver.time() >= next_history - 1e-12 || solver.time() >= t_end) {
                next_history += 0.05;
                const DrumState d = drum_state(solver, Phi_level, 0.8 * R, v_flow);
                if (solver.time() >= angle_from && std::isfinite(d.surface_angle_deg)) late_angles.push_back(d.surface_angle_deg);
                history.row({solver.time(), static_cast<double>(solver.steps()), d.surface_angle_deg,
                             static_cast<double>(d.surface_points), d.flowing_fraction, d.max_speed, d.kinetic_energy,
                             solver.mass(), solver.mass() / mass0 - 1.0, solver.last_dt()});
            }
            if (vtk && (solver.time() >= next_snapshot - 1e-12 || solver.time() >= t_end)) {
                next_snapshot += snapshot_every;
                char name[64];
                std::snprintf(name, sizeof name, "vtk/tumbler_%04d.vtk", snapshot++);
                out.add(name, flow_vtk(solver));
            }
        };
        sample();
        advance_flow(solver, t_end, "tumbler-flow", sample);

        // Dynamic angle of repose: mean and spread of the surface angle over t >= angle_from.
        double sum = 0, sum2 = 0;
        for (double a : late_angles) sum += a, sum2 += a * a;
        const double n = static_cast<double>(late_angles.size()), mean = n > 0 ? sum / n : NAN;
        DataTable summary({"t_end", "steps", "angle_mean_deg", "angle_std_deg", "samples", "mass_change"});
        summary.comment("dynamic angle of repose: mean of the surface angle over t >= " + format_number(angle_from) +
                        " s; mass_change relative");
        summary.row({solver.time(), static_cast<double>(solver.steps()), mean,
                     n > 1 ? std::sqrt(std::max(0.0, sum2 / n - mean * mean)) : 0.0, n, solver.mass() / mass0 - 1.0});
        out.add("history.dat", history);
        out.add("summary.dat", summary);
        out.add("fields_lab.dat", flow_field_table(solver, true));
        out.add("fields_drum.dat", flow_field_table(solver, false));
        return out;
    }
};

}  // namespace

std::unique_ptr<SceneJob> prepare_tumbler_flow(const SceneFile& scene) {
    auto job = std::make_unique<TumblerFlow>(read_material(scene));
    job->settings = read_flow_settings(scene);
    const std::string s = "drum";
    const double D = scene.number(s, "diameter", Range::above(0), 0.1);
    job->R = 0.5 * D;
    job->cells = static_cast<int>(scene.integer(s, "cells_per_diameter", 8, 2000, 100));
    job->fill_height = scene.number(s, "fill_height", Range::open(0, D), 0.75 * D);
    const double rps = scene.number(s, "rps", Range::closed(-100, 100), 0.1);
    job->axial_cells = static_cast<int>(scene.integer(s, "axial_cells", 1, 1000, 1));
    job->axial_length = scene.number(s, "axial_length", Range::above(0), job->axial_cells * D / job->cells);
    job->frame.gravity = scene.number(s, "gravity", Range::at_least(0), 9.81);
    job->frame.omega = 2.0 * M_PI * rps;
    job->t_end = scene.number("run", "t_end", Range::above(0), 25.0);
    job->snapshot_every = scene.number("run", "snapshot_every", Range::above(0), 2.5);
    job->angle_from = scene.number("run", "angle_from", Range::at_least(0), 10.0);
    job->vtk = scene.flag("run", "vtk", true);
    if (!(job->angle_from < job->t_end))
        scene.fail("run", "angle_from", format_number(job->angle_from) + " >= t_end", "angle_from < t_end");
    return job;
}

}  // namespace granseg
