// Scene kind "segregation1d": the 1-D column of Sect. 4.1, eq. (66), with profiles Phi(z), T(z)
// and an initial phi(z, Phi, T) given as expressions; writes profile.dat (# z Phi T phi).
// Keys: docs/scenes.md.
#pragma once

#include "scenes/scene_kind.hpp"

namespace granseg {

std::unique_ptr<SceneJob> prepare_segregation1d(const SceneFile& scene);

}  // namespace granseg
