// Runs that are stopped and resumed (run/run_checkpoints.hpp) through run_scene_file: a coupled
// drum killed (SIGKILL, in a child process) at a random moment and resumed writes the files of the
// run that was never stopped, byte for byte but for the timing columns; a finished run extended
// to a later t_end writes those of a run made with that t_end; a study (Resume::if_compatible)
// starts a run over whose checkpoint belongs to another scene, where --resume (Resume::yes) refuses.
#include "core/error.hpp"
#include "core/threads.hpp"
#include "harness/same_outputs.hpp"
#include "scenes/scene_kind.hpp"

#include <boost/test/unit_test.hpp>

#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <random>
#include <thread>

using namespace granseg;
namespace fs = std::filesystem;

BOOST_AUTO_TEST_SUITE(run_checkpoints_tests)

namespace {

/// A small coupled drum with frames and VTK snapshots, a checkpoint every 0.03 s of wall clock.
std::string drum_scene(double t_end, int frames, const std::string& drum = "") {
    return "[scene]\nkind = \"tumbler\"\n[drum]\ncells_per_diameter = 26\n" + drum + "[run]\nt_end = " + std::to_string(t_end) +
           "\nangle_from = 0.2\nframes = " + std::to_string(frames) + "\nsnapshot_every = 0.25\ncheckpoint_every = 0.0005\n";
}

fs::path scratch() {
    const fs::path dir = fs::temp_directory_path() / ("granseg_test_run_checkpoints_" + std::to_string(::getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir);
    return dir;
}

std::string write_scene(const fs::path& dir, const std::string& name, const std::string& text) {
    const fs::path p = dir / name;
    std::ofstream(p) << text;
    return p.string();
}

double seconds_of(const std::function<void()>& f) {
    const auto t0 = std::chrono::steady_clock::now();
    f();
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

long differences(const fs::path& a, const fs::path& b) {
    long files = 0;
    const auto d = verify::differing_outputs(a.string(), b.string(), &files);
    for (const auto& line : d) BOOST_TEST_MESSAGE(line);
    BOOST_TEST(files >= 5);
    return static_cast<long>(d.size());
}

}  // namespace

BOOST_AUTO_TEST_CASE(killed_at_a_random_moment_and_resumed_writes_the_same_files) {
    const fs::path dir = scratch();
    const std::string scene = write_scene(dir, "drum.toml", drum_scene(1.0, 4));
    const double seconds = seconds_of([&] { run_scene_file(scene, (dir / "whole").string()); });
    const unsigned seed = std::random_device{}();
    std::mt19937 random(seed);
    const double kill_after = std::uniform_real_distribution<double>(0.1, 0.9)(random) * seconds;
    BOOST_TEST_MESSAGE("seed " << seed << ": killed after " << kill_after << " of " << seconds << " s");
    const pid_t child = fork();
    if (child == 0) {  // a small grid: no OpenMP region is opened in the child
        const ThreadScope one(1);
        try {
            run_scene_file(scene, (dir / "killed").string());
        } catch (...) {
            _exit(1);
        }
        _exit(0);
    }
    BOOST_REQUIRE(child > 0);
    std::this_thread::sleep_for(std::chrono::duration<double>(kill_after));
    kill(child, SIGKILL);
    int status = 0;
    waitpid(child, &status, 0);
    BOOST_TEST(fs::exists(dir / "killed" / "checkpoint.gsc"));
    run_scene_file(scene, (dir / "killed").string(), Resume::yes);
    BOOST_TEST(differences(dir / "whole", dir / "killed") == 0);
    fs::remove_all(dir);
}

BOOST_AUTO_TEST_CASE(a_finished_run_extends_to_the_run_made_with_the_later_t_end) {
    const fs::path dir = scratch();
    // The same frame spacing (0.25 s) in both: frames are spaced t_end/frames.
    const std::string longer = write_scene(dir, "long.toml", drum_scene(1.0, 4)),
                      shorter = write_scene(dir, "short.toml", drum_scene(0.5, 2));
    run_scene_file(longer, (dir / "long").string());
    run_scene_file(shorter, (dir / "extended").string());
    run_scene_file(longer, (dir / "extended").string(), Resume::yes);
    BOOST_TEST(differences(dir / "long", dir / "extended") == 0);
    // Once more: written out again from its final state.
    run_scene_file(longer, (dir / "extended").string(), Resume::yes);
    BOOST_TEST(differences(dir / "long", dir / "extended") == 0);
    fs::remove_all(dir);
}

BOOST_AUTO_TEST_CASE(a_checkpoint_of_another_scene_is_refused_or_run_again) {
    const fs::path dir = scratch();
    const std::string scene = write_scene(dir, "drum.toml", drum_scene(0.3, 0));
    const std::string other = write_scene(dir, "other.toml", drum_scene(0.3, 0, "rps = 0.2\n"));
    run_scene_file(scene, (dir / "a").string());
    std::string message;
    try {
        run_scene_file(other, (dir / "a").string(), Resume::yes);
    } catch (const InputError& e) {
        message = e.what();
    }
    BOOST_TEST(message.find("written for a scene with [drum] rps = 0.1") != std::string::npos);
    BOOST_TEST(message.find("this scene has [drum] rps = 0.2") != std::string::npos);
    run_scene_file(other, (dir / "a").string(), Resume::if_compatible);  // a study: runs it again
    run_scene_file(other, (dir / "b").string());
    BOOST_TEST(differences(dir / "b", dir / "a") == 0);
    fs::remove_all(dir);
}

BOOST_AUTO_TEST_SUITE_END()
