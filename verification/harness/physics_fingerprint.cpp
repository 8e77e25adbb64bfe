#include "harness/physics_fingerprint.hpp"

#include "core/error.hpp"
#include "harness/doc_blocks.hpp"
#include "harness/grid_convergence.hpp"
#include "harness/number_fingerprint.hpp"
#include "harness/time_series.hpp"
#include "scenes/scene_kind.hpp"

#include <unistd.h>

#include <cmath>
#include <cstdio>

namespace fs = std::filesystem;

namespace granseg::verify {

namespace {

// Significant digits of a canonical run's numbers in its fingerprint: the outputs carry 12, and
// round-off that differs between machines stays far below 9, while a changed constant of the
// scheme moves the drum's sums at the first few digits.
constexpr int kPhysicsDigits = 9;

/// A canonical run: a scene file under verification/scenes and the output files hashed.
struct CanonicalRun {
    std::string scene;
    std::vector<std::string> files;
};

const std::map<std::string, std::vector<CanonicalRun>>& canonical_runs() {
    static const std::map<std::string, std::vector<CanonicalRun>> runs = {
        {"flow", {{"physics_flow.toml", {"history.dat", "summary.dat"}}}},
        {"drum", {{"physics_drum.toml", {"history.dat", "summary.dat"}}}},
        {"segregation",
         {{"physics_segregation1d.toml", {"profile.dat"}}, {"physics_segregation_drum.toml", {"tumbler_metrics.dat"}}}},
        {"closures", {{"physics_closures.toml", {"closures.dat"}}}},
    };
    return runs;
}

std::string number_text(double x) {
    char buf[40];
    std::snprintf(buf, sizeof buf, "%.*g", kPhysicsDigits, x);
    return buf;
}

/// The study's procedure on fixed series: one of each condition, and the sampling errors of a
/// fixed noisy series.
std::string study_fingerprint() {
    const std::vector<double> h = {1.0, 1.4, 2.0, 2.8};
    const std::vector<std::vector<double>> series = {
        {1.02, 1.05, 1.11, 1.19},   // monotone
        {1.02, 1.07, 1.01, 1.09},   // oscillatory
        {1.00, 1.001, 0.999, 1.0},  // within noise
        {0.01, 0.02, 0.05, 0.11},   // monotone towards a limit below 0
    };
    const std::vector<double> se = {0.002, 0.002, 0.003, 0.003};
    Fnv1a hash;
    for (const auto& f : series)
        for (const std::vector<double>& grid : {h, std::vector<double>(h.begin(), h.begin() + 2)}) {
            const std::vector<double> values(f.begin(), f.begin() + static_cast<long>(grid.size()));
            const std::vector<double> errors(se.begin(), se.begin() + static_cast<long>(grid.size()));
            const GridConvergence c = grid_convergence(grid, values, errors, 1.0, {0.0, 1.5});
            std::string line = convergence_name(c.condition);
            for (double x : {c.chi2, c.chi2_limit, c.p, c.f0, c.p_u, c.fs, c.eps, c.sigma, c.uncertainty, c.e_a, c.e_ext})
                line += " " + number_text(x);
            hash.add(line + (c.outside_bounds ? " outside" : ""));
        }
    std::vector<double> t, v;
    for (int i = 0; i < 200; ++i) {
        t.push_back(0.05 * i);
        v.push_back(0.3 + 0.001 * i + 0.01 * std::sin(1.7 * i) + 0.004 * std::cos(5.3 * i));
    }
    hash.add(number_text(batch_mean_error(v)) + " " + number_text(detrended_spread(t, v)));
    return hash.hex();
}

}  // namespace

const std::vector<PhysicsPart>& physics_parts() {
    static const std::vector<PhysicsPart> parts = {{"flow", "the flow step"},
                                                   {"drum", "the coupled drum"},
                                                   {"segregation", "the segregation"},
                                                   {"closures", "the closures"},
                                                   {"study", "the studies' uncertainty procedure"}};
    return parts;
}

std::string part_title(const std::string& name) {
    for (const PhysicsPart& p : physics_parts())
        if (p.name == name) return p.title;
    return name;
}

bool counts_in_fingerprint(const std::string& column) {
    const auto has = [&](const char* s) { return column.find(s) != std::string::npos; };
    return !has("seconds") && column != "threads" && !has("_change") && !has("clip");
}

Fingerprints physics_fingerprints(const fs::path& root) {
    Fingerprints out;
    const fs::path scratch = fs::temp_directory_path() / ("granseg_physics_" + std::to_string(::getpid()));
    try {
        for (const auto& [part, runs] : canonical_runs()) {
            Fnv1a hash;
            for (const CanonicalRun& run : runs) {
                const fs::path scene = root / "verification" / "scenes" / run.scene, dir = scratch / run.scene;
                if (!fs::exists(scene)) throw InputError("no scene " + scene.string() + " for the fingerprint of " + part);
                run_scene_file(scene.string(), dir.string());
                for (const std::string& file : run.files) {
                    bool found = false;
                    const std::string text = docs::read_text(dir / file, &found);
                    if (!found) throw InputError(run.scene + " wrote no " + file + " (the fingerprint of " + part + ")");
                    hash.add(run.scene + "/" + file);
                    hash.add(numbers_fingerprint(text, kPhysicsDigits, counts_in_fingerprint));
                }
            }
            out[part] = hash.hex();
        }
    } catch (...) {
        fs::remove_all(scratch);
        throw;
    }
    fs::remove_all(scratch);
    out["study"] = study_fingerprint();
    return out;
}

}  // namespace granseg::verify
