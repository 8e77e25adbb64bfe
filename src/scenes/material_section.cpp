#include "scenes/material_section.hpp"

#include <fstream>
#include <sstream>

namespace granseg {

Material read_material(const SceneFile& scene) {
    const std::string s = "material";
    Material m = Material::glass_substitute();
    m.eta0 = scene.number(s, "eta0", Range::above(0), m.eta0);
    m.lambda0 = scene.number(s, "lambda0", Range::above(0), m.lambda0);
    m.eps0 = scene.number(s, "eps0", Range::above(0), m.eps0);
    m.T0 = scene.number(s, "T0", Range::at_least(0), m.T0);
    m.rho_star = scene.number(s, "rho_star", Range::above(0), m.rho_star);
    m.g_law = parse_choice(kCompressibilityLaws, scene.choice(s, "g_law", choice_names(kCompressibilityLaws), "power"), "g_law");
    m.beta = scene.number(s, "beta", Range::left_open(0, 10), m.beta);
    if (m.g_law != CompressibilityLaw::power && scene.has(s, "beta"))
        scene.fail(s, "beta", "only used with g_law = \"power\"", "remove beta or set g_law = \"power\"");

    const std::string path = scene.text(s, "packing_table", "");
    const long degree = scene.integer(s, "packing_degree", 1, 8, kDefaultPackingDegree);
    if (!path.empty() || degree != kDefaultPackingDegree) {
        PackingTable table = builtin_packing_table();
        if (!path.empty()) {
            std::ifstream in(path);
            if (!in) scene.fail(s, "packing_table", "cannot open \"" + path + "\"", "path of a readable file");
            std::ostringstream text;
            text << in.rdbuf();
            try {
                table = parse_packing_table(text.str(), path);
            } catch (const InputError& e) {
                scene.fail(s, "packing_table", e.what(), "columns '# phi_hat Phi_rcp Phi_co'");
            }
        }
        try {
            m.packing = PackingFit(std::move(table), static_cast<int>(degree));
        } catch (const InputError& e) {
            scene.fail(s, path.empty() ? "packing_degree" : "packing_table", e.what(),
                       "a fit with 0 < Phi_co < Phi_rcp < 1 on [0, 1]");
        }
    }
    return m;
}

void require_yield_pressure(const SceneFile& scene, const Material& m) {
    if (m.T0 <= 0.0)
        scene.fail("material", "T0",
                   "0 leaves a bed under gravity only the kinetic pressure g Phi T (eq. 15), and at rest T falls to "
                   "T_floor: the bed compacts to Phi_rcp (a run stops there)",
                   "T0 > 0 in scenes with gravity, e.g. 1e-3; the default is 1");
}

}  // namespace granseg
