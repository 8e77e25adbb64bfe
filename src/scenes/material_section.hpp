// The [material] section of a scene file: the scene layer reads and validates it, the closures
// (src/closures/) only compute with the Material it returns.
#pragma once

#include "closures/material.hpp"
#include "run/scene_file.hpp"

namespace granseg {

/// Reads the optional [material] section of a scene (every key defaults to glass_substitute()).
/// Keys: eta0, lambda0, eps0, T0, rho_star, g_law (a name of kCompressibilityLaws), beta,
/// packing_table (path, default built-in), packing_degree. Bad values: scene.fail (InputError).
Material read_material(const SceneFile& scene);

/// Fails on [material] T0 = 0 in a scene whose bed rests under gravity: without the yield pressure
/// (eq. 19) only the kinetic pressure g Phi T holds it, and T -> T_floor compacts it to Phi_rcp.
void require_yield_pressure(const SceneFile& scene, const Material& m);

}  // namespace granseg
