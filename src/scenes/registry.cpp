// The table of scene kinds known to `granseg run` (one row per kind).
#include "scenes/closure_sweep.hpp"
#include "scenes/scene_kind.hpp"

namespace granseg {

const std::vector<SceneKind>& scene_kinds() {
    static const std::vector<SceneKind> kinds = {
        {"closure-sweep", "tabulate the Sect. 2.1 closures against Phi for a material", prepare_closure_sweep},
    };
    return kinds;
}

}  // namespace granseg
