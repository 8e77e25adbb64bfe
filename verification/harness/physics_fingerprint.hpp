// What decides a generated table's numbers, as fingerprints (docs/checked_pages.md, "Where a
// table came from"): every table under docs/generated records the fingerprints of the parts of
// the code its numbers depend on, and verify_docs compares them with the build's own.
//
//   parts       flow       the flow step (verification/scenes/physics_flow.toml)
//               drum       the coupled drum: flow, bulk transport, segregation sub-step, packing
//                          feedback together (physics_drum.toml)
//               segregation the segregation flux and sub-step, in the Fig. 6 column and on a
//                          prescribed drum flow (physics_segregation1d.toml,
//                          physics_segregation_drum.toml)
//               closures   the Sect. 2.1 closures (physics_closures.toml)
//               study      the solution-verification procedure of the drum studies
//                          (grid_convergence.hpp, time_series.hpp) on fixed series
//   fingerprint a part's canonical runs (the scenes above, each in a scratch directory, about two
//               seconds in all) hashed by their output files' numbers at 9 significant digits
//               (number_fingerprint.hpp), leaving out wall-clock columns and the round-off
//               diagnostics (mass changes, clips), which are no physics
//   why         a run's outputs, not the source text: moving code between files keeps every
//               fingerprint, a changed constant or formula changes the fingerprint of each part
//               it acts in; the drum's fingerprint changes with any part it couples, the flow's
//               only with the flow, so a changed fingerprint also says where the code changed
#pragma once

#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace granseg::verify {

/// A part of the code whose fingerprint a table may record.
struct PhysicsPart {
    std::string name;   // as recorded: flow, drum, segregation, closures, study
    std::string title;  // for messages: "the flow step"
};

/// Every part, in the order records list them.
const std::vector<PhysicsPart>& physics_parts();

/// The title of part `name` ("the flow step"), or `name` itself if there is no such part.
std::string part_title(const std::string& name);

/// Part name -> fingerprint (16 hexadecimal digits).
using Fingerprints = std::map<std::string, std::string>;

/// The fingerprints of this build's parts, from the canonical runs of the scenes under
/// root/verification/scenes. InputError naming the scene if one cannot be read or run.
Fingerprints physics_fingerprints(const std::filesystem::path& root);

/// Whether a data file's column counts in a fingerprint: not the cost of a run (seconds, threads)
/// and not a round-off diagnostic (a mass change, a clip).
bool counts_in_fingerprint(const std::string& column);

}  // namespace granseg::verify
