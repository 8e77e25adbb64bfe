#include "scenes/scene_kind.hpp"

#include "core/format.hpp"

namespace granseg {

namespace {

/// The checkpoints of a run of `kind` with outputs below `root`: [run] checkpoint_every, the keys a
/// resume may change, the command that resumes it. A kind that does not step in time has none.
CheckpointPlan checkpoint_plan(const SceneFile& scene, const SceneKind& kind, const std::string& root,
                               const std::string& output_dir, Resume resume) {
    CheckpointPlan plan;
    if (kind.resumable.empty()) return plan;
    const double minutes = scene.number("run", "checkpoint_every", Range::at_least(0), kCheckpointMinutes);
    if (minutes == 0.0) return plan;
    plan.path = root + "/checkpoint.gsc";
    plan.every = 60.0 * minutes;
    plan.resume = resume;
    plan.kind = kind.name;
    plan.changeable = comma_list(kind.resumable);
    plan.resume_command = "granseg run " + scene.name() + (output_dir.empty() ? "" : " --output-dir " + output_dir) + " --resume";
    return plan;
}

}  // namespace

std::vector<std::string> run_scene_file(const std::string& path, const std::string& output_dir, Resume resume) {
    const SceneFile scene = SceneFile::load(path);
    std::vector<std::string> names;
    for (const auto& kind : scene_kinds()) names.push_back(kind.name);
    const std::string kind_name = scene.choice("scene", "kind", names);
    const std::string dir = scene.text("output", "dir", "out/" + kind_name);
    if (dir.empty()) scene.fail("output", "dir", "empty path", "a directory path");
    const std::string root = output_dir.empty() ? dir : output_dir;

    std::unique_ptr<SceneJob> job;
    CheckpointPlan plan;
    for (const auto& kind : scene_kinds())
        if (kind.name == kind_name) {
            job = kind.prepare(scene);
            plan = checkpoint_plan(scene, kind, root, output_dir, resume);
            std::vector<std::string> ignored = kind.resumable;
            ignored.insert(ignored.end(), {"[run] checkpoint_every", "[output] dir"});
            plan.settings = scene.settings(ignored);
        }
    scene.finish();

    RunCheckpoints checkpoints(plan);
    job->checkpoints = &checkpoints;
    const OutputSet files = job->run();
    OutputSet placed;
    std::vector<std::string> written;
    for (const auto& [name, content] : files.files()) {
        placed.add(root + "/" + name, content);
        written.push_back(root + "/" + name);
    }
    placed.commit();
    return written;
}

}  // namespace granseg
