// granseg run SCENE.toml [--output-dir DIR] [--resume]
// Validates and runs a scene file; outputs go below [output] dir (or DIR). A scene that steps in
// time writes checkpoints there (checkpoint.gsc); --resume continues from the last one.
#include "cli/commands.hpp"
#include "cli/options.hpp"
#include "closures/material.hpp"
#include "flow/fields/flow_settings.hpp"
#include "scenes/scene_kind.hpp"
#include "segregation/column.hpp"
#include "segregation/scheme.hpp"

#include <iostream>

namespace granseg::cli {

int run_main(const std::vector<std::string>& args) {
    std::string scene, output_dir;
    bool resume = false;
    po::options_description desc("options");
    desc.add_options()("scene", po::value<std::string>(&scene)->required(), "the scene file (TOML), see docs/scenes.md")(
        "output-dir", po::value<std::string>(&output_dir), "write outputs here instead of [output] dir")(
        "resume", po::bool_switch(&resume),
        "continue from the checkpoint in the output directory (a finished run: "
        "to a later t_end, or its outputs written again); none: start at t = 0");
    po::positional_options_description positional;
    positional.add("scene", 1);
    std::string usage = "SCENE.toml [--output-dir DIR] [--resume]\n\nscene kinds ([scene] kind):\n";
    for (const auto& kind : scene_kinds()) usage += "  " + kind.name + ": " + kind.summary + "\n";
    usage += "\nchoices (docs/scenes.md lists which scene kinds read which key):\n";
    usage += "  [segregation] scheme:\n" + describe_choices(kSegregationSchemes);
    usage += "  [segregation] limiter (order-2 schemes):\n" + describe_choices(kLimiters);
    usage += "  [segregation] interface (schemes with interface values):\n" + describe_choices(kInterfaceRules);
    usage += "  [bulk] scheme:\n" + describe_choices(kBulkSchemes);
    usage += "  [material] g_law:\n" + describe_choices(kCompressibilityLaws);
    usage += "  [flow] time_stepping:\n" + describe_choices(kTimeSteppings);
    usage += "  [flow] viscosity:\n" + describe_choices(kViscositySolves);
    usage += "  [flow] factorisation:\n" + describe_choices(kFactorisations);
    po::variables_map vm;
    if (!parse_options("run", usage, args, desc, positional, vm)) return 0;
    for (const auto& file : run_scene_file(scene, output_dir, resume ? Resume::yes : Resume::no))
        std::cout << "wrote " << file << '\n';
    return 0;
}

}  // namespace granseg::cli
