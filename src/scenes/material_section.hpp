// The [material] section of a scene file: the scene layer reads and validates it, the closures
// (src/closures/) only compute with the Material it returns.
#pragma once

#include "closures/material.hpp"
#include "core/scene_file.hpp"

namespace granseg {

/// Reads the optional [material] section of a scene (every key defaults to glass_substitute()).
/// Keys: eta0, lambda0, eps0, T0, rho_star, g_law (a name of kCompressibilityLaws), beta,
/// packing_table (path, default built-in), packing_degree. Bad values: scene.fail (InputError).
Material read_material(const SceneFile& scene);

}  // namespace granseg
