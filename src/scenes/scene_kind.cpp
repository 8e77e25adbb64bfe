#include "scenes/scene_kind.hpp"

namespace granseg {

std::vector<std::string> run_scene_file(const std::string& path, const std::string& output_dir) {
    const SceneFile scene = SceneFile::load(path);
    std::vector<std::string> names;
    for (const auto& kind : scene_kinds()) names.push_back(kind.name);
    const std::string kind_name = scene.choice("scene", "kind", names);
    const std::string dir = scene.text("output", "dir", "out/" + kind_name);
    if (dir.empty()) scene.fail("output", "dir", "empty path", "a directory path");

    std::unique_ptr<SceneJob> job;
    for (const auto& kind : scene_kinds())
        if (kind.name == kind_name) job = kind.prepare(scene);
    scene.finish();

    const OutputSet files = job->run();
    OutputSet placed;
    std::vector<std::string> written;
    const std::string root = output_dir.empty() ? dir : output_dir;
    for (const auto& [name, content] : files.files()) {
        placed.add(root + "/" + name, content);
        written.push_back(root + "/" + name);
    }
    placed.commit();
    return written;
}

}  // namespace granseg
