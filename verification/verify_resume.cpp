// Runs that survive (docs/checkpoints.md), checked as faults happen, on
// build/granseg: a coupled drum killed with SIGKILL at a random moment and resumed with --resume
// writes every file of the run that was never stopped, byte for byte but for the timing columns
// (the expected files are that run's: an independent computation of the same steps); SIGTERM
// writes a checkpoint,
// exits with 143 and one line saying how to continue; a finished run extended to a later t_end
// writes the files of the run made with that t_end; a full disk keeps the previous checkpoint and
// says so; a tumbler starts from a tumbler-flow's checkpoint at its time; and a checkpoint that
// cannot be continued (truncated, corrupted, of another kind, scene or build, past t_end, or a
// source of another drum) is refused with exit status 2 and one line naming the file.
//
// On two threads, a drum restored from a save continues to the bit: tests/run/checkpoint.cpp (the
// grid must be one whose loops run on threads, 92 cells per diameter: too long for this program).
// Run: build/verification/verify_resume [--data DIR]   (about two seconds of CPU: a drum of 26 cells
// per diameter runs for fractions of a second, a dozen times; the kill times are drawn at random)
#include "harness/check_table.hpp"
#include "harness/cli_process.hpp"
#include "harness/program.hpp"
#include "harness/same_outputs.hpp"
#include "run/checkpoint_file.hpp"

#include <signal.h>
#include <unistd.h>

#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <random>
#include <string>

namespace fs = std::filesystem;
using namespace granseg;
using namespace granseg::verify;

namespace {

/// A coupled drum: frames and VTK snapshots every 0.2 s, a checkpoint every 0.03 s of wall clock.
std::string drum(double t_end, int frames, const std::string& more = "") {
    return "[scene]\nkind = \"tumbler\"\n[drum]\ncells_per_diameter = 26\n" + more + "[run]\nt_end = " + std::to_string(t_end) +
           "\nangle_from = 0.2\nframes = " + std::to_string(frames) + "\nsnapshot_every = 0.2\ncheckpoint_every = 0.0005\n";
}

class Runs {
public:
    Runs(const char* argv0, fs::path work)
        : cli_(Cli::beside(argv0), work), work_(std::move(work)), random_(std::random_device{}()) {}

    std::string scene(const std::string& name, const std::string& text) const {
        const fs::path p = work_ / (name + ".toml");
        std::ofstream(p) << text;
        return p.string();
    }
    std::string dir(const std::string& name) const { return (work_ / name).string(); }
    Outcome run(const std::string& scene, const std::string& out, const std::string& more = "", const std::string& env = "",
                double seconds = INFINITY, int signal = 0, const std::function<bool()>& since = {}) const {
        return cli_.run("run '" + scene + "' --output-dir '" + out + "' " + more, env, seconds, signal, since);
    }
    double uniform(double a, double b) { return std::uniform_real_distribution<double>(a, b)(random_); }

private:
    Cli cli_;
    fs::path work_;
    std::mt19937 random_;
};

/// The time of the state in the checkpoint at `path` (its header's line "t ..."); -1 if there is none yet.
double checkpoint_time(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    char head[512] = {};
    in.read(head, sizeof head - 1);
    const char* line = std::strstr(head, "\nt ");
    return line ? std::strtod(line + 3, nullptr) : -1.0;
}

/// Files of `resumed` that differ from `whole`'s (timing columns aside); notes each.
long differing(CheckTable& t, const std::string& whole, const std::string& resumed) {
    long files = 0;
    const auto d = differing_outputs(whole, resumed, &files);
    for (const std::string& line : d) t.note("    " + line);
    t.note("  " + std::to_string(files) + " files compared with the uninterrupted run");
    return static_cast<long>(d.size());
}

/// A run killed with `signal` at a random moment of `seconds`, then resumed: its files against `whole`'s.
void killed_and_resumed(CheckTable& t, Runs& runs, const std::string& label, const std::string& scene, const std::string& whole,
                        double t_end, int signal) {
    const std::string out = runs.dir("killed_" + label);
    // At a random step: once a checkpoint (one every 0.03 s of wall clock) has reached a random
    // time of the run, after a random delay shorter than the time between two checkpoints, so that
    // the signal finds the run stepping or writing a checkpoint, whatever the machine's load.
    const double target = runs.uniform(0.05, 0.7) * t_end, delay = runs.uniform(0.0, 0.02);
    const auto reached = [&] { return checkpoint_time(out + "/checkpoint.gsc") >= target; };
    const Outcome o = runs.run(scene, out, "", "", delay, signal, reached);
    t.note(label + " " + format(delay) + " s after a checkpoint at t >= " + format(target) +
           " s: " + (o.err.empty() ? "no message" : o.err.substr(0, o.err.find('\n'))));
    t.count(label + ": killed run's exit status", o.status, 128 + signal);
    long left = 0;  // but the checkpoint and a temporary file of one being written
    for (const auto& e : fs::directory_iterator(out)) left += e.path().filename().string().rfind("checkpoint.gsc", 0) != 0;
    t.count(label + ": files it left but its checkpoint", left, 0);
    if (signal == SIGTERM) {
        t.count(label + ": stderr lines", line_count(o.err), 1);
        t.count(label + ": the line names the checkpoint and --resume",
                o.err.find(out + "/checkpoint.gsc") != std::string::npos && o.err.find("--resume") != std::string::npos, 1);
    }
    const Outcome r = runs.run(scene, out, "--resume");
    t.count(label + ": resumed run's exit status", r.status, 0);
    t.count(label + ": files differing from the uninterrupted run", differing(t, whole, out), 0);
}

/// A refused resume: exit 2, one line starting with `starts`, nothing written but what was there.
void refused(CheckTable& t, Runs& runs, const std::string& label, const std::string& scene, const std::string& out,
             const std::string& starts, const std::string& more = "--resume") {
    const long before = files_below(out);
    const Outcome o = runs.run(scene, out, more);
    t.note("  " + label + ": " + o.err.substr(0, o.err.find('\n')));
    t.count(label + ": exit status", o.status, 2);
    t.count(label + ": stderr and stdout lines", line_count(o.err) + line_count(o.out), 1);
    t.count(label + ": the line starts with " + starts, o.err.rfind(starts, 0) == 0, 1);
    t.count(label + ": files written", files_below(out) - before, 0);
}

/// A copy of the checkpoint of `from` into a new directory `name`, changed by `change`; its path.
std::string altered(Runs& runs, const std::string& from, const std::string& name,
                    const std::function<void(std::string&)>& change) {
    std::ifstream in(from + "/checkpoint.gsc", std::ios::binary);
    std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    change(bytes);
    fs::create_directories(runs.dir(name));
    std::ofstream(runs.dir(name) + "/checkpoint.gsc", std::ios::binary) << bytes;
    return runs.dir(name);
}

void check_refusals(CheckTable& t, Runs& runs, const std::string& scene, const std::string& whole, const std::string& flow_run) {
    t.note("Checkpoints that cannot be continued");
    const auto path = [](const std::string& d) { return d + "/checkpoint.gsc: "; };
    std::string d = altered(runs, whole, "truncated", [](std::string& b) { b.resize(b.size() / 2); });
    refused(t, runs, "truncated to half", scene, d, path(d) + "truncated");
    d = altered(runs, whole, "corrupted", [](std::string& b) { b[b.size() - 1000] ^= 1; });
    refused(t, runs, "one bit flipped", scene, d, path(d) + "corrupted");
    d = altered(runs, flow_run, "other_kind", [](std::string&) {});
    refused(t, runs, "a tumbler-flow's checkpoint", scene, d, path(d) + "a checkpoint of a tumbler-flow run");
    d = altered(runs, whole, "other_scene", [](std::string&) {});
    refused(t, runs, "another scene ([drum] rps)", runs.scene("rps", drum(0.6, 3, "rps = 0.2\n")), d,
            path(d) + "written for a scene with");
    d = altered(runs, whole, "other_build", [](std::string&) {});
    Checkpoint c = read_checkpoint(d + "/checkpoint.gsc");
    c.program = "0123456789abcdef";
    write_checkpoint(d + "/checkpoint.gsc", c);
    refused(t, runs, "another build", scene, d, path(d) + "written by another build");
    d = altered(runs, whole, "past_t_end", [](std::string&) {});
    refused(t, runs, "t_end before the checkpoint's time", runs.scene("earlier", drum(0.3, 3)), d,
            path(d) + "its state is at t = ");
    const std::string source = runs.scene("from_coarser",
                                          "[scene]\nkind = \"tumbler\"\n[drum]\ncells_per_diameter = 30\n[run]\nt_end = 0.6\n"
                                          "angle_from = 0.2\n[initial]\nflow = \"" +
                                              flow_run + "/checkpoint.gsc\"\n");
    refused(t, runs, "[initial] flow of another drum", source, runs.dir("from_coarser"), source + ": [initial] flow: ", "");
}

/// A full disk (a file size limit): the final checkpoint, the largest, fails; the previous one stays.
void check_full_disk(CheckTable& t, Runs& runs, const std::string& scene, const std::string& whole) {
    t.note("A full disk: the file size limit lets the checkpoints during the run through, not the final one");
    const long final_size = static_cast<long>(fs::file_size(whole + "/checkpoint.gsc"));
    const std::string out = runs.dir("full_disk");
    const long blocks = final_size * 3 / 4 / 512;  // ulimit -f counts blocks of 512 bytes in sh
    const Outcome o =
        runs.run(scene, out, "", "sh -c 'trap \"\" XFSZ; ulimit -f " + std::to_string(blocks) + "; exec \"$0\" \"$@\"'");
    t.note("  " + o.err.substr(0, o.err.find('\n')));
    t.count("full disk: exit status", o.status, 0);
    t.count("full disk: the message says the previous checkpoint is kept",
            o.err.find("File too large (the previous checkpoint there is kept)") != std::string::npos, 1);
    const Checkpoint kept = read_checkpoint(out + "/checkpoint.gsc");
    t.count("full disk: the checkpoint left is whole and from before the end (finished = 0)", kept.finished ? 1 : 0, 0);
    t.count("full disk: output files differing from the uninterrupted run", differing(t, whole, out), 0);
}

}  // namespace

int main(int argc, char** argv) {
    const auto options = parse_program_options(argc, argv);
    (void)options;
    const fs::path work = fs::temp_directory_path() / ("granseg_verify_resume_" + std::to_string(::getpid()));
    fs::create_directories(work);
    Runs runs(argv[0], work);
    CheckTable t("Checkpoints: killed, resumed, extended, started from another run, refused (granseg run --resume)");

    const std::string scene = runs.scene("drum", drum(0.6, 3)), whole = runs.dir("whole");
    runs.run(scene, whole);
    t.note("A coupled drum, 26 cells per diameter, 0.6 s, stopped and resumed");
    killed_and_resumed(t, runs, "SIGKILL", scene, whole, 0.6, SIGKILL);
    killed_and_resumed(t, runs, "SIGTERM", scene, whole, 0.6, SIGTERM);

    t.note("Extended: 0.4 s, then --resume with t_end = 0.6 s (frames every 0.2 s in both)");
    const std::string extended = runs.dir("extended");
    runs.run(runs.scene("short", drum(0.4, 2)), extended);
    const Outcome e = runs.run(scene, extended, "--resume");
    t.count("extended: exit status", e.status, 0);
    t.count("extended: files differing from the 0.6 s run", differing(t, whole, extended), 0);

    t.note("Started from another run: a tumbler on the flow of a tumbler-flow run at its t_end");
    const std::string flow_run = runs.dir("flow");
    runs.run(
        runs.scene("flow",
                   "[scene]\nkind = \"tumbler-flow\"\n[drum]\ncells_per_diameter = 26\n[run]\nt_end = 0.3\nangle_from = 0.1\n"),
        flow_run);
    const Checkpoint source = read_checkpoint(flow_run + "/checkpoint.gsc");
    const std::string from = runs.dir("from");
    const Outcome f =
        runs.run(runs.scene("from", drum(0.5, 0, "") + "[initial]\nflow = \"" + flow_run + "/checkpoint.gsc\"\n"), from);
    t.count("from a flow: exit status", f.status, 0);
    const auto first = read_rows(from + "/history.dat").front();
    // history.dat prints 12 significant digits.
    t.near("from a flow: first history row's t = the flow's t_end", first.at(0), source.t, 1e-12);
    t.near("from a flow: its steps = the flow's steps", first.at(1), static_cast<double>(source.steps), 0.0);

    check_refusals(t, runs, scene, whole, flow_run);
    check_full_disk(t, runs, scene, whole);
    fs::remove_all(work);
    return t.finish();
}
