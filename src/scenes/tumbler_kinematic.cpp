#include "scenes/tumbler_kinematic.hpp"

#include "core/format.hpp"
#include "kinematic/kinematic_tables.hpp"
#include "scenes/drum_keys.hpp"
#include "scenes/material_section.hpp"

#include <cmath>
#include <cstdio>

namespace granseg {

namespace {

struct TumblerKinematic : SceneJob {
    TumblerKinematicScene scene;

    OutputSet run() override {
        KinematicTumbler tumbler(scene.setup);
        const KinematicRunResult result = run_kinematic_tumbler(tumbler, scene.run, {}, checkpoints);
        return tumbler_kinematic_outputs(tumbler, result, scene.run);
    }
};

}  // namespace

TumblerKinematicScene read_tumbler_kinematic(const SceneFile& scene) {
    TumblerKinematicScene s;
    KinematicTumblerSetup& k = s.setup;
    RollingDrumParameters& drum = k.drum;
    drum.diameter = scene.number("drum", "diameter", Range::above(0), drum.diameter);
    k.cells_per_diameter = static_cast<int>(scene.integer("drum", "cells_per_diameter", 4, 2000, k.cells_per_diameter));
    // The coupled drum's names are accepted too: fill_height (m) and rps (drum_keys.hpp).
    const double D = drum.diameter;
    drum.fill_fraction = read_drum_key_or_other(scene, "fill_fraction", Range::open(0, 1), drum.fill_fraction, "fill_height",
                                                Range::open(0, D), [D](double height) { return height / D; });
    drum.rotation_rate = read_drum_key_or_other(scene, "rotation_rate", Range::any(), drum.rotation_rate, "rps", Range::any(),
                                                [](double rps) { return rps; });
    if (drum.rotation_rate == 0.0)
        scene.fail("drum", scene.has("drum", "rps") ? "rps" : "rotation_rate", "0 (no flow)", "a number != 0, rev/s");
    drum.repose_angle = scene.number("drum", "repose_angle", Range::right_open(0, 90), drum.repose_angle);
    drum.layer_thickness = scene.number("drum", "layer_thickness", Range::above(0), drum.layer_thickness);
    {
        const double R = drum.diameter / 2, d = (2 * drum.fill_fraction - 1) * R,
                     limit = std::min(std::sqrt(R * R - d * d), R + d);
        if (!(drum.layer_thickness < limit))
            scene.fail("drum", "layer_thickness",
                       format_number(drum.layer_thickness) +
                           " m is not below min(half chord, bed depth) = " + format_number(limit) + " m",
                       "0 < layer_thickness < " + format_number(limit));
        if (R / k.cells_per_diameter * 2 > drum.layer_thickness)
            scene.fail("drum", "cells_per_diameter",
                       std::to_string(k.cells_per_diameter) + " cells leave the flowing layer unresolved (cell size " +
                           format_number(drum.diameter / k.cells_per_diameter) + " m > layer_thickness)",
                       "cells_per_diameter >= diameter/layer_thickness = " +
                           format_number(std::ceil(drum.diameter / drum.layer_thickness)));
    }
    k.Phi = scene.number("drum", "Phi", Range::open(0, 1), k.Phi);
    s.run.t_end = scene.number("time", "end", Range::above(0));
    const double cfl = scene.number("time", "cfl", Range::left_open(0, 1), 0.9);
    k.bulk_cfl = cfl, k.segregation.cfl = cfl;
    k.S = scene.number("segregation", "S", Range::at_least(0), k.S);
    k.gravity = scene.number("segregation", "gravity", Range::above(0), k.gravity);
    read_bounded_scheme(scene, k.segregation);
    k.bulk = parse_bulk_scheme(scene.choice("bulk", "scheme", bulk_scheme_names(), "fct"));
    const Expression phi_hat = scene.expression("initial", "phi_hat", {"x", "z"}, "0.5");
    k.phi_hat0 = [phi_hat](double x, double z) { return phi_hat({x, z}); };
    k.material = read_material(scene);
    s.run.samples = static_cast<int>(scene.integer("output", "samples", 1, 100000, 100));
    s.run.frames = static_cast<int>(scene.integer("output", "frames", 0, 1000, 0));

    // The drum the keys describe; RollingDrumFlow rejects what the checks above do not cover.
    RollingDrumFields fields;
    try {
        fields = discretize(RollingDrumFlow(drum), k.cells_per_diameter, k.Phi);
        s.run.regions = default_regions(RollingDrumFlow(drum));
    } catch (const InputError& e) {
        scene.fail("drum", "diameter", e.what(), "a drum of docs/scenes.md");
    }
    // Cross-key conditions on the grid: phi_hat0 in [0, 1] at every bed-cell centre.
    require_share(scene, fields.grid, "phi_hat", k.phi_hat0, "0 <= phi_hat <= 1 at every bed cell");
    return s;
}

OutputSet tumbler_kinematic_outputs(const KinematicTumbler& tumbler, const KinematicRunResult& result,
                                    const KinematicRunOptions& run) {
    OutputSet out;
    const Grid& g = tumbler.grid();
    out.add("tumbler_initial.dat", composition_cells(g, result.phi_hat_initial, "phi_hat at t = 0"));
    out.add("tumbler_final.dat", composition_cells(g, composition_field(g, tumbler.phi(), tumbler.Phi()),
                                                   "phi_hat at t = " + format_number(tumbler.time()) + " s"));
    out.add("tumbler_flow.dat", kinematic_flow_cells(tumbler));
    out.add("tumbler_outline.dat", drum_outline(tumbler.flow()));
    DataTable metrics = kinematic_metrics(result, run.regions);
    metrics.comment(std::to_string(tumbler.steps()) + " steps (dt = " + format_number(tumbler.time_step()) + " s), " +
                    std::to_string(tumbler.cell_updates()) + " cell updates; relative change of sum(phi): " +
                    format_number((result.mass_end - result.mass_start) / result.mass_start, 3));
    out.add("tumbler_metrics.dat", metrics);
    out.add("tumbler_shells.dat", kinematic_shells(tumbler, result, kTumblerShells));
    for (std::size_t n = 0; n < result.frames.size(); ++n) {
        char name[32];
        std::snprintf(name, sizeof name, "frame_%03zu.dat", n + 1);
        out.add(name,
                composition_cells(g, result.frames[n].phi_hat, "phi_hat at t = " + format_number(result.frames[n].t) + " s"));
    }
    return out;
}

std::unique_ptr<SceneJob> prepare_tumbler_kinematic(const SceneFile& scene) {
    auto job = std::make_unique<TumblerKinematic>();
    job->scene = read_tumbler_kinematic(scene);
    return job;
}

}  // namespace granseg
