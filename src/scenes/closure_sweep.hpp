// Scene kind "closure-sweep": tabulates the Sect. 2.1 closures of a material against Phi for
// several phi_hat, with T given as an expression of Phi and phi_hat. Keys: docs/scenes.md.
#pragma once

#include "scenes/scene_kind.hpp"

namespace granseg {

std::unique_ptr<SceneJob> prepare_closure_sweep(const SceneFile& scene);

}  // namespace granseg
