#include "scenes/drum_keys.hpp"

#include "core/format.hpp"

namespace granseg {

void read_bounded_scheme(const SceneFile& scene, SegregationOptions& options) {
    options.scheme = parse_scheme(scene.choice("segregation", "scheme", scheme_names(), "modified-godunov"));
    options.limiter = parse_limiter(scene.choice("segregation", "limiter", limiter_names(), "mc"));
    if (!preserves_bounds(options.scheme))
        scene.fail("segregation", "scheme",
                   "\"" + scheme_name(options.scheme) + "\" does not keep 0 <= phi <= Phi, which the run checks",
                   bounded_scheme_names());
}

double read_drum_key_or_other(const SceneFile& scene, const std::string& key, const Range& range, double fallback,
                              const std::string& other, const Range& other_range, const std::function<double(double)>& to_key) {
    if (!scene.has("drum", other)) return scene.number("drum", key, range, fallback);
    if (scene.has("drum", key))
        scene.fail("drum", other, "given together with " + key + ", its other name", "one of " + key + " and " + other);
    return to_key(scene.number("drum", other, other_range));
}

void require_share(const SceneFile& scene, const Grid& grid, const char* key, const std::function<double(double, double)>& share,
                   const std::string& allowed, const std::function<bool(std::size_t cell)>& where) {
    for_each_bed_cell(grid, [&](const BedCell& b) {
        if (where && !where(b.c)) return;
        const double v = share(b.x, b.z);
        if (!(v >= 0.0 && v <= 1.0))
            scene.fail(
                "initial", key,
                std::string(key) + " = " + format_number(v) + " at x = " + format_number(b.x) + ", z = " + format_number(b.z),
                allowed);
    });
}

}  // namespace granseg
