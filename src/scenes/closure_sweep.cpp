#include "scenes/closure_sweep.hpp"

#include "closures/closures.hpp"
#include "core/format.hpp"
#include "scenes/material_section.hpp"

#include <cmath>

namespace granseg {

namespace {

struct ClosureSweep : SceneJob {
    Material material;
    std::vector<double> phi_hats, Phis;
    std::vector<double> T;  // T at (phi_hat index, Phi index), row-major

    explicit ClosureSweep(Material m) : material(std::move(m)) {}

    OutputSet run() override {
        DataTable table;
        table.comment("closure-sweep: one block per phi_hat (gnuplot index); units m^2/s^2, m^2/s, 1/s, m/s");
        for (std::size_t a = 0; a < phi_hats.size(); ++a) {
            for (std::size_t b = 0; b < Phis.size(); ++b) {
                const double t = T[a * Phis.size() + b];
                const ClosureValues v = evaluate_closures(material, Phis[b], phi_hats[a], t);
                table.row(TableRow{{"phi_hat", phi_hats[a]}, {"Phi", Phis[b]}, {"T", t}}.add(closure_columns(v)));
            }
            table.blank();
            table.blank();
        }
        OutputSet out;
        out.add("closures.dat", table);
        return out;
    }
};

}  // namespace

std::unique_ptr<SceneJob> prepare_closure_sweep(const SceneFile& scene) {
    auto job = std::make_unique<ClosureSweep>(read_material(scene));
    const std::string s = "sweep";
    job->phi_hats = scene.numbers(s, "phi_hat", Range::closed(0, 1), {0.0, 0.4, 1.0});
    const double Phi_min = scene.number(s, "Phi_min", Range::right_open(0, 1), 0.01);
    const double Phi_max = scene.number(s, "Phi_max", Range::open(0, 1));
    const long points = scene.integer(s, "points", 2, 100000, 200);
    const Expression T = scene.expression(s, "T", {"Phi", "phi_hat"}, "1e-4");

    double lowest_rcp = 1.0, at = 0.0;
    for (double x : job->phi_hats)
        if (job->material.packing.Phi_rcp(x) < lowest_rcp) lowest_rcp = job->material.packing.Phi_rcp(x), at = x;
    if (!(Phi_max > Phi_min))
        scene.fail(s, "Phi_max", format_number(Phi_max) + " <= Phi_min = " + format_number(Phi_min),
                   "Phi_min < Phi_max < Phi_rcp");
    if (!(Phi_max < lowest_rcp))
        scene.fail(s, "Phi_max",
                   format_number(Phi_max) + " >= Phi_rcp(phi_hat = " + format_number(at) + ") = " + format_number(lowest_rcp),
                   "Phi_min < Phi_max < Phi_rcp for every phi_hat");

    for (long i = 0; i < points; ++i) job->Phis.push_back(Phi_min + (Phi_max - Phi_min) * i / (points - 1));
    for (double x : job->phi_hats) {
        for (double Phi : job->Phis) {
            const double t = T({Phi, x});
            if (!(t >= 0.0) || !std::isfinite(t))
                scene.fail(s, "T",
                           "T = " + format_number(t) + " at Phi = " + format_number(Phi) + ", phi_hat = " + format_number(x),
                           "finite T >= 0 at every point");
            job->T.push_back(t);
        }
    }
    return job;
}

}  // namespace granseg
