// The drums of other cross-sections at the resolution their page shows (docs/drum_shapes.md): the
// half-filled square drum and the triangular drum (verification/scenes/drum_square.toml,
// drum_triangle.toml; the whole model, three turns, 60 cells across the circle through the
// corners), each run once with the threads the run's own rule gives it (core/threads.hpp: one
// thread on grids below the crossover), with its wall time, CPU time, steps, inside cells and the
// pattern's measures at t_end.
// Writes DIR/drum_square and DIR/drum_triangle (the scenes' files: history, summary, frames for
// figures/bench_drum_shapes.gp and bench_drum_shapes_animation.gp) and drum_shapes.md, the table
// docs/drum_shapes.md shows (docs/checked_pages.md, generated tables). A few minutes:
// `make bench BENCH=bench_drum_shapes`.
//
// Run: build/bench/bench_drum_shapes [--data DIR]
#include "harness/program.hpp"
#include "harness/table_provenance.hpp"
#include "run/output.hpp"
#include "scenes/scene_kind.hpp"

#include <cstdio>
#include <string>

using namespace granseg;

namespace {

struct Scene {
    const char* name;   // below DIR and in the table
    const char* label;  // the drum, for the table
};
constexpr Scene kScenes[] = {{"drum_square", "square, half full"}, {"drum_triangle", "triangle, half its height"}};

}  // namespace

int main(int argc, char** argv) {
    const auto options = verify::parse_program_options(argc, argv);
    const std::string load_before = verify::load_average();
    std::string md =
        "| drum | inside cells | flow steps | wall time | angle of repose | segregation index | periphery | axis |\n"
        "|---|---|---|---|---|---|---|---|\n";
    for (const Scene& s : kScenes) {
        const std::string dir = options.data_dir + "/" + s.name;
        // A run that finished is only written out again, an interrupted one resumes; its wall time
        // covers all its parts.
        run_scene_file(std::string("verification/scenes/") + s.name + ".toml", dir, Resume::if_compatible);
        const auto r = verify::last_row(dir + "/summary.dat");
        const double wall = r.at("wall_seconds");
        char line[300];
        std::snprintf(line, sizeof line, "| %s | %.0f | %.0f | %.0f s | %.1f deg | %.2f | %.2f | %.2f |\n", s.label,
                      r.at("inside_cells"), r.at("steps"), wall, r.at("angle_mean_deg"), r.at("segregation_index"),
                      r.at("periphery"), r.at("axis"));
        md += line;
        std::printf("%s: %.1f s wall, %.1f s CPU on %.0f thread(s), %.0f steps, %.0f inside cells\n", s.name, wall,
                    r.at("cpu_seconds"), r.at("threads"), r.at("steps"), r.at("inside_cells"));
        std::fflush(stdout);
    }
    verify::write_generated_table(options.data_dir + "/drum_shapes.md", md, verify::kDrumParts);
    std::printf("%s\nload average before: %s, after: %s\n", md.c_str(), load_before.c_str(), verify::load_average().c_str());
    return 0;
}
