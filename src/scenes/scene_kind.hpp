// Scene kinds and the `granseg run` driver.
//
// Running a scene file has three phases, in this order:
//   1. prepare: the kind reads and validates every key it needs (SceneFile accessors) and any
//      cross-key condition (phi <= Phi on the grid, ...), computing nothing expensive;
//   2. the driver calls SceneFile::finish(), rejecting keys nobody asked for;
//   3. run: the job computes and returns its files; the driver writes them all at the end.
// So bad input never produces output, and a run that throws (InvariantError) leaves none either.
// A kind that steps in time also writes checkpoints while it runs (run/run_checkpoints.hpp) into
// its output directory, checkpoint.gsc, and resumes from them (docs/checkpoints.md).
// A new scene kind adds one row to scene_kinds() in registry.cpp and a section to docs/scenes.md.
#pragma once

#include "run/output.hpp"
#include "run/run_checkpoints.hpp"
#include "run/scene_file.hpp"

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace granseg {

/// A validated scene, ready to run.
class SceneJob {
public:
    virtual ~SceneJob() = default;
    /// Computes the scene; returns files with paths relative to the output directory.
    virtual OutputSet run() = 0;
    /// Where a kind that steps in time writes its checkpoints and resumes from (set by
    /// run_scene_file before run(); null: none).
    RunCheckpoints* checkpoints = nullptr;
};

struct SceneKind {
    std::string name;     // value of [scene] kind
    std::string summary;  // one line for `granseg run --help`
    std::function<std::unique_ptr<SceneJob>(const SceneFile&)> prepare;
    /// A kind that steps in time: the keys a resumed run may change (written "[section] key"; also
    /// [run] checkpoint_every and [output] dir, for every such kind); empty: no checkpoints.
    std::vector<std::string> resumable = {};
};

/// Default of [run] checkpoint_every: wall-clock minutes between checkpoints.
constexpr double kCheckpointMinutes = 5.0;

/// Every scene kind, in the order `granseg run --help` lists them.
const std::vector<SceneKind>& scene_kinds();

/// Loads, validates and runs the scene file at `path`, then writes its outputs below
/// `output_dir` if given, else below [output] dir of the file. Returns the files written.
/// Throws InputError (bad input) or InvariantError (broken invariant) before writing anything.
/// A kind that steps in time resumes from its checkpoint as `resume` says, and after a stop
/// signal throws Interrupted (its checkpoint written, no outputs).
std::vector<std::string> run_scene_file(const std::string& path, const std::string& output_dir = "", Resume resume = Resume::no);

}  // namespace granseg
