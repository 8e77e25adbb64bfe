#include "scenes/tumbler.hpp"

#include "core/error.hpp"
#include "core/format.hpp"
#include "scenes/drum_keys.hpp"
#include "scenes/flow_scenes.hpp"
#include "scenes/material_section.hpp"
#include "scenes/start_from.hpp"

#include <cmath>

namespace granseg {

namespace {

struct Tumbler : SceneJob {
    TumblerScene scene;

    OutputSet run() override {
        CoupledTumbler tumbler(scene.setup);
        start(tumbler, scene);
        return run_coupled_tumbler(tumbler, scene.run, {}, checkpoints);
    }
};

}  // namespace

void start(CoupledTumbler& tumbler, const TumblerScene& scene) {
    if (scene.flow_from.empty()) return;
    StateIO flow = flow_state_of(scene.flow_from);
    tumbler.start_from(flow);
}

int min_tumbler_cells() { return static_cast<int>(std::ceil(2.0 / kLayerShare)); }

TumblerScene read_tumbler(const SceneFile& scene) {
    TumblerScene t;
    CoupledTumblerSetup& s = t.setup;
    s.material = read_material(scene);
    s.flow = read_flow_settings(scene, false, s.flow);
    s.drum = read_drum(scene);
    require_yield_pressure(scene, s.material);
    if (s.drum.cells_per_diameter < min_tumbler_cells())
        scene.fail("drum", "cells_per_diameter",
                   std::to_string(s.drum.cells_per_diameter) + " cells leave the flowing layer (about " +
                       format_number(kLayerShare * s.drum.diameter) + " m thick) unresolved",
                   "cells_per_diameter >= " + std::to_string(min_tumbler_cells()));
    t.run.run = read_drum_run(scene);
    t.run.frames = static_cast<int>(scene.integer("run", "frames", 0, 1000, t.run.frames));
    t.flow_from = read_flow_source(scene, t.run.run.t_end);

    const std::string seg = "segregation";
    s.S = scene.number(seg, "S", Range::at_least(0), s.S);
    read_bounded_scheme(scene, s.segregation);
    s.segregation.cfl = scene.number(seg, "cfl", Range::left_open(0, 1), s.segregation.cfl);
    s.Phi_min = scene.number(seg, "Phi_min", Range::right_open(0, 1), s.Phi_min);
    s.diagnostic_min_shear_rate = scene.number(seg, "diagnostic_min_shear_rate", Range::at_least(0), s.diagnostic_min_shear_rate);
    s.packing_feedback = scene.flag("coupling", "packing_feedback", s.packing_feedback);
    if (scene.has("coupling", "mixture")) {
        if (s.packing_feedback)
            scene.fail("coupling", "mixture", "a fixed mixture with packing_feedback = true",
                       "only with packing_feedback = false (C3)");
        s.mixture = scene.number("coupling", "mixture", Range::closed(0, 1));
    }
    const Expression phi_hat = scene.expression("initial", "phi_hat", {"x", "z"}, "0.5");
    s.phi_hat0 = [phi_hat](double x, double z) { return phi_hat({x, z}); };
    if (scene.has("initial", "tracer")) {
        const Expression tracer = scene.expression("initial", "tracer", {"x", "z"});
        s.tracer0 = [tracer](double x, double z) { return tracer({x, z}); };
    }

    // Cross-key conditions on the initial bed: phi_hat0 in [0, 1] wherever the drum holds material,
    // and (packing feedback) the bed below Phi_rcp(phi_hat0) in every cell, which building the
    // drum checks (FlowSolver::set_state).
    const Grid grid = s.drum.grid();
    const std::vector<double> fill = drum_fill_fraction(s.drum, grid);
    require_share(scene, grid, "phi_hat", s.phi_hat0, "0 <= phi_hat <= 1 wherever the drum holds material",
                  [&](std::size_t c) { return fill[c] > 0.0; });
    if (s.tracer0) require_share(scene, grid, "tracer", s.tracer0, "0 <= tracer <= 1 in the drum");
    try {
        CoupledTumbler probe(s);
        t.run.regions = coupled_regions(s.drum, surface_level(s.material, probe.initial_mixture()));
        start(probe, t);
    } catch (const InvariantError& e) {
        scene.fail("initial", "phi_hat", e.what(), "a mixture whose Phi_rcp(phi_hat) lies above the initial bed's Phi");
    } catch (const InputError& e) {
        scene.fail("initial", "phi_hat", e.what(), "0 <= phi_hat <= 1 in every cell of the flow of [initial] flow");
    }
    return t;
}

std::unique_ptr<SceneJob> prepare_tumbler(const SceneFile& scene) {
    auto job = std::make_unique<Tumbler>();
    job->scene = read_tumbler(scene);
    return job;
}

}  // namespace granseg
