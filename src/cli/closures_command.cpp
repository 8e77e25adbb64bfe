// granseg closures --Phi X --phi-hat Y --T Z [--scene FILE]
// Prints the Sect. 2.1 closures at one state as `name = value` lines.
#include "cli/commands.hpp"
#include "cli/options.hpp"
#include "closures/closures.hpp"
#include "core/error.hpp"
#include "core/format.hpp"
#include "scenes/material_section.hpp"

#include <cmath>
#include <iostream>

namespace granseg::cli {

int closures_main(const std::vector<std::string>& args) {
    double Phi = 0, phi_hat = 0, T = 0;
    std::string scene_path;
    po::options_description desc("options (units per intrinsic density rho*: p, T in m^2/s^2)");
    desc.add_options()("Phi", po::value<double>(&Phi)->required(), "granular volume fraction, 0 <= Phi < Phi_rcp(phi_hat)")(
        "phi-hat", po::value<double>(&phi_hat)->required(), "small-particle share phi/Phi, 0 <= phi_hat <= 1")(
        "T", po::value<double>(&T)->required(), "granular temperature, T >= 0")(
        "scene", po::value<std::string>(&scene_path), "take the material from the [material] section of this scene file");
    po::variables_map vm;
    if (!parse_options("closures", "--Phi X --phi-hat Y --T Z [--scene FILE]", args, desc, {}, vm)) return 0;

    Material m = Material::glass_substitute();
    if (!scene_path.empty()) {
        const SceneFile scene = SceneFile::load(scene_path);
        m = read_material(scene);
    }
    checked("closures", "phi-hat", phi_hat, Range::closed(0, 1));
    checked("closures", "T", T, Range::at_least(0));
    const double rcp = m.packing.Phi_rcp(phi_hat);
    if (!Range::right_open(0, rcp).contains(Phi))
        throw InputError("granseg closures: --Phi: " + format_number(Phi) + " is out of range (allowed: 0 <= Phi < Phi_rcp(" +
                         format_number(phi_hat) + ") = " + format_number(rcp) + ")");

    const ClosureValues v = evaluate_closures(m, Phi, phi_hat, T);
    const TableRow lines = TableRow{{"Phi", Phi}, {"phi_hat", phi_hat}, {"T", T}}.add(closure_columns(v, &m));
    for (std::size_t k = 0; k < lines.size(); ++k)
        std::cout << lines.names()[k] << " = " << format_number(lines.values()[k], 10) << '\n';
    return 0;
}

}  // namespace granseg::cli
