#include "run/run_checkpoints.hpp"

#include "core/error.hpp"
#include "core/format.hpp"
#include "run/build_identity.hpp"
#include "run/scene_file.hpp"

#include <atomic>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <mutex>

namespace granseg {

namespace {

/// Seconds of wall clock a run stays quiet about its checkpoints' cost (as run/progress.hpp).
constexpr double kQuietSeconds = 3.0;

// SIGINT and SIGTERM while checkpointed runs are under way: the handler only records the signal
// (a lock-free atomic, safe in a handler); the runs see it between steps. A second signal
// ends the process at once, as without a handler.
std::atomic<int> requested{0};
std::mutex watch_mutex;
int watchers = 0;
struct sigaction old_int, old_term;

extern "C" void on_stop_signal(int signal) {
    if (requested.exchange(signal) != 0) {
        std::signal(signal, SIG_DFL);
        std::raise(signal);
    }
}

void watch_signals() {
    const std::lock_guard<std::mutex> lock(watch_mutex);
    if (watchers++ > 0) return;
    requested = 0;
    struct sigaction action {};
    action.sa_handler = on_stop_signal;
    sigemptyset(&action.sa_mask);
    sigaction(SIGINT, &action, &old_int);
    sigaction(SIGTERM, &action, &old_term);
}

void unwatch_signals() {
    const std::lock_guard<std::mutex> lock(watch_mutex);
    if (--watchers > 0) return;
    sigaction(SIGINT, &old_int, nullptr);
    sigaction(SIGTERM, &old_term, nullptr);
}

}  // namespace

int stop_signal() { return requested.load(); }

StateIO runner_state(const Checkpoint& c, const std::string& block, const std::string& path, BlobStore* files, RunTime* clock) {
    if (files && c.has("files")) {
        StateIO in(c.block("files", path), path);
        std::uint64_t n = 0;
        in("files", n);
        for (std::uint64_t i = 0; i < n; ++i) {
            std::string key, text;
            in("file.key", key)("file.text", text);
            (*files)[key] = std::move(text);
        }
        in.expect_end();
    }
    StateIO io(c.block(block, path), path, files);
    RunTime spent;
    io("run.wall_seconds", spent.wall)("run.cpu_seconds", spent.cpu);
    if (clock) *clock = spent;
    return io;
}

RunCheckpoints& checkpoints_or_none(RunCheckpoints* checkpoints) {
    static RunCheckpoints none;
    return checkpoints ? *checkpoints : none;
}

RunCheckpoints::RunCheckpoints(CheckpointPlan plan)
    : plan_(std::move(plan)), start_(std::chrono::steady_clock::now()), last_(start_), cpu_start_(run_cpu_seconds()) {
    if (!enabled()) return;
    watch_signals();
    // A run killed while writing left its temporary file (the checkpoint itself is whole): remove it.
    namespace fs = std::filesystem;
    const fs::path file(plan_.path);
    std::error_code ec;
    const fs::path dir = file.has_parent_path() ? file.parent_path() : fs::path(".");
    for (const auto& e : fs::directory_iterator(dir, ec))
        if (e.path().filename().string().rfind(file.filename().string() + ".tmp.", 0) == 0) fs::remove(e.path(), ec);
}

RunCheckpoints::~RunCheckpoints() {
    if (enabled()) unwatch_signals();
}

std::string RunCheckpoints::saved(const RunState& state, BlobStore& files) const {
    StateIO io(&files);
    double wall = earlier_.wall + std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    double cpu = earlier_.cpu + run_cpu_seconds() - cpu_start_;
    io("run.wall_seconds", wall)("run.cpu_seconds", cpu);
    state(io);
    return io.bytes();
}

Checkpoint RunCheckpoints::make(double t, long steps, bool finished, const std::string& bytes, const std::string& resume_bytes,
                                BlobStore& blobs) const {
    Checkpoint c;
    c.kind = plan_.kind, c.program = build_identity(), c.scene = hash_text(plan_.settings);
    c.t = t, c.steps = steps, c.finished = finished;
    c.blocks = {{"scene", plan_.settings}, {"state", bytes}};
    if (!resume_bytes.empty()) c.blocks.emplace_back("resume", resume_bytes);
    // The output files the states name, once.
    StateIO files;
    std::uint64_t n = blobs.size();
    files("files", n);
    for (auto& [key, text] : blobs) {
        std::string k = key;
        files("file.key", k)("file.text", text);
    }
    c.blocks.emplace_back("files", files.bytes());
    return c;
}

bool RunCheckpoints::refuse(const std::string& why) const {
    const std::string allowed = " (allowed: a checkpoint of this scene by this build; a change of " + plan_.changeable +
                                " only; or run without --resume to start at t = 0)";
    if (plan_.resume == Resume::yes) throw InputError(plan_.path + ": " + why + allowed);
    std::fprintf(stderr, "%s: %s: starting at t = 0\n", plan_.path.c_str(), why.c_str());
    return false;
}

std::string RunCheckpoints::mismatch(const Checkpoint& c) const {
    if (c.kind != plan_.kind) return "a checkpoint of a " + c.kind + " run, this scene is a " + plan_.kind + " run";
    if (c.program != build_identity())
        return std::string("written by another build of granseg (") + c.program + ", this one " + build_identity() +
               "), which need not compute the same bits";
    const std::string& settings = c.block("scene", plan_.path);
    if (c.scene != hash_text(settings)) return "corrupted: its scene does not match its fingerprint";
    if (settings != plan_.settings) {
        const std::string theirs = first_setting_missing(settings, plan_.settings),
                          ours = first_setting_missing(plan_.settings, settings);
        return "written for a scene with " + (theirs.empty() ? "no " + ours : theirs) + ", this scene has " +
               (ours.empty() ? "no such key" : ours);
    }
    return "";
}

bool RunCheckpoints::resume(double t_end, const RunState& state) {
    if (!enabled() || plan_.resume == Resume::no) return false;
    if (!std::filesystem::exists(plan_.path)) {
        if (plan_.resume == Resume::yes) std::fprintf(stderr, "%s: no checkpoint yet: starting at t = 0\n", plan_.path.c_str());
        return false;
    }
    Checkpoint c;
    try {
        c = read_checkpoint(plan_.path);
        const std::string why = mismatch(c);
        if (!why.empty()) return refuse(why);
    } catch (const InputError& e) {
        if (plan_.resume == Resume::yes) throw;
        std::fprintf(stderr, "%s: starting at t = 0\n", e.what());
        return false;
    }
    // A finished run extended to a later t_end continues from the state before its last step
    // (written out again, it keeps that state for a later extension).
    const bool extend = c.finished && t_end > c.t && c.has("resume");
    if (!extend && t_end < c.t)
        return refuse("its state is at t = " + format_exact(c.t) + " s, after this scene's t_end = " + format_exact(t_end) +
                      " s");
    BlobStore files;
    StateIO io = runner_state(c, extend ? "resume" : "state", plan_.path, &files, &earlier_);
    if (c.finished && !extend && c.has("resume")) kept_ = c.block("resume", plan_.path), kept_files_ = files;
    state(io);
    io.expect_end();
    return true;
}

void RunCheckpoints::before_step(double t, double t_end, double longest_step, const RunState& state) {
    if (!enabled() || t + longest_step < t_end) return;
    const auto t0 = std::chrono::steady_clock::now();
    kept_files_.clear();
    kept_ = saved(state, kept_files_);
    spent_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

void RunCheckpoints::after_step(double t, long steps, const RunState& state) {
    if (!enabled()) return;
    const int signal = stop_signal();
    const auto now = std::chrono::steady_clock::now();
    if (!signal && std::chrono::duration<double>(now - last_).count() < plan_.every) return;
    std::string written = plan_.path;
    const struct Account {  // the time of this checkpoint, however it ends
        double& spent;
        std::chrono::steady_clock::time_point from;
        ~Account() { spent += std::chrono::duration<double>(std::chrono::steady_clock::now() - from).count(); }
    } account{spent_, now};
    try {
        BlobStore files;
        const std::string bytes = saved(state, files);
        write(make(t, steps, false, bytes, "", files));
    } catch (const InputError& e) {
        if (!signal) {
            std::fprintf(stderr, "granseg: %s; the run goes on\n", e.what());
            last_ = now;
            return;
        }
        written.clear();
        throw Interrupted(std::string("granseg: stopped by ") + (signal == SIGINT ? "SIGINT" : "SIGTERM") +
                              " at t = " + format_number(t) + " s without a new checkpoint: " + e.what(),
                          signal);
    }
    last_ = std::chrono::steady_clock::now();
    if (signal)
        throw Interrupted(std::string("granseg: stopped by ") + (signal == SIGINT ? "SIGINT" : "SIGTERM") +
                              " at t = " + format_number(t) + " s after " + std::to_string(steps) + " steps; checkpoint " +
                              written + "; continue with: " + plan_.resume_command,
                          signal);
}

void RunCheckpoints::finish(double t, long steps, const RunState& state) {
    if (!enabled()) return;
    const auto t0 = std::chrono::steady_clock::now();
    try {
        BlobStore files = kept_files_;
        const std::string bytes = saved(state, files);
        write(make(t, steps, true, bytes, kept_, files));
    } catch (const InputError& e) {
        std::fprintf(stderr, "granseg: %s; the outputs are written all the same\n", e.what());
    }
    spent_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    // Their cost, for long runs only (as the progress lines: quiet for the first seconds).
    const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    if (wall >= kQuietSeconds)
        std::fprintf(stderr,
                     "%s: %d checkpoints written, the last %.1f MB; %.2f s with the states kept before the last steps, "
                     "%.2f %% of this run's %.0f s\n",
                     plan_.path.c_str(), written_, last_size_ / 1e6, spent_, 100.0 * spent_ / wall, wall);
}

void RunCheckpoints::write(const Checkpoint& c) {
    write_checkpoint(plan_.path, c);
    ++written_;
    last_size_ = static_cast<double>(std::filesystem::file_size(plan_.path));
}

}  // namespace granseg
