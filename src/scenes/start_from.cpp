#include "scenes/start_from.hpp"

#include "core/error.hpp"
#include "core/format.hpp"
#include "run/checkpoint_file.hpp"
#include "run/run_checkpoints.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <map>
#include <sstream>

namespace granseg {

namespace {

/// Relative difference below which two numbers of a [drum] key are the same drum.
constexpr double kSameDrum = 1e-12;

/// The [drum] keys of `settings` (SceneFile::settings) and their values as text.
std::map<std::string, std::string> drum_keys(const std::string& settings) {
    std::istringstream in(settings);
    std::map<std::string, std::string> keys;
    for (std::string line; std::getline(in, line);) {
        const std::size_t eq = line.find(" = ");
        if (line.rfind("[drum] ", 0) == 0 && eq != std::string::npos) keys[line.substr(0, eq)] = line.substr(eq + 3);
    }
    return keys;
}

/// Two values of a key alike: equal text, or numbers within kSameDrum relative (a default computed
/// as 0.75 of the height and the same length written out differ in the last bit).
bool alike(const std::string& a, const std::string& b) {
    char *end_a = nullptr, *end_b = nullptr;
    const double x = std::strtod(a.c_str(), &end_a), y = std::strtod(b.c_str(), &end_b);
    const bool numbers = *end_a == '\0' && *end_b == '\0' && !a.empty() && !b.empty();
    return a == b || (numbers && std::fabs(x - y) <= kSameDrum * std::max(std::fabs(x), std::fabs(y)));
}

}  // namespace

std::string read_flow_source(const SceneFile& scene, double t_end) {
    if (!scene.has("initial", "flow")) return "";
    const std::string path = scene.text("initial", "flow", "");
    const std::string allowed = "a checkpoint of a tumbler-flow or tumbler run of the same [drum]";
    Checkpoint c;
    try {
        c = read_checkpoint(path);
    } catch (const InputError& e) {
        throw InputError(scene.name() + ": [initial] flow: " + e.what());  // names the checkpoint and what it must be
    }
    if (c.kind != "tumbler-flow" && c.kind != "tumbler")
        scene.fail("initial", "flow", path + " is a checkpoint of a " + c.kind + " run", allowed);
    const auto theirs = drum_keys(c.block("scene", path)), ours = drum_keys(scene.settings());
    for (const bool given : {true, false})  // the keys the file gives first: a default may follow from one of them
        for (const auto& [key, value] : ours) {
            const auto it = theirs.find(key);
            const std::string other = it == theirs.end() ? "none" : it->second;
            if (scene.has("drum", key.substr(7)) == given && !alike(value, other))
                scene.fail("initial", "flow", path + " is a drum with " + key + " = " + other + ", this scene's has " + value,
                           allowed);
        }
    if (!(t_end > c.t))
        scene.fail("run", "t_end",
                   format_exact(t_end) + " s is not after the time of [initial] flow, " + format_exact(c.t) + " s",
                   "t_end > " + format_exact(c.t) + " (the run continues the flow's clock)");
    return path;
}

StateIO flow_state_of(const std::string& path) {
    return runner_state(read_checkpoint(path), "state", path);  // the source run's clock is not this run's
}

}  // namespace granseg
