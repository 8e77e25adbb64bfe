// The table of scene kinds known to `granseg run` (one row per kind).
#include "scenes/closure_sweep.hpp"
#include "scenes/flow_scenes.hpp"
#include "scenes/scene_kind.hpp"
#include "scenes/segregation1d.hpp"
#include "scenes/tumbler.hpp"
#include "scenes/tumbler_kinematic.hpp"

namespace granseg {

const std::vector<SceneKind>& scene_kinds() {
    static const std::vector<SceneKind> kinds = {
        {"closure-sweep", "tabulate the Sect. 2.1 closures against Phi for a material", prepare_closure_sweep},
        {"segregation1d", "the 1-D segregation column of Sect. 4.1, eq. (66), Fig. 6", prepare_segregation1d},
        {"bed-at-rest",
         "a granular bed settling under gravity in a box or column (Sect. 2.1 flow)",
         prepare_bed_at_rest,
         {"[run] t_end"}},
        {"simple-shear",
         "homogeneous simple shear between moving walls (Sect. 2.1 flow, eq. 45)",
         prepare_simple_shear,
         {"[run] t_end"}},
        {"inclined-plane",
         "a granular layer on a rough inclined plane, periodic along the slope",
         prepare_inclined_plane,
         {"[run] t_end"}},
        {"tumbler-flow",
         "the rotating drum of Sect. 4.2 without segregation (rotating frame)",
         prepare_tumbler_flow,
         {"[run] t_end", "[run] angle_from"}},
        {"tumbler-kinematic",
         "segregation in the drum of Sect. 4.2 on a prescribed rolling flow, Fig. 7a-c",
         prepare_tumbler_kinematic,
         {"[time] end", "[output] samples", "[output] frames"}},
        {"tumbler",
         "the whole model of Sect. 4.2: flow and segregation coupled in the drum, Fig. 7a-d",
         prepare_tumbler,
         {"[run] t_end", "[run] angle_from", "[run] frames"}},
    };
    return kinds;
}

}  // namespace granseg
