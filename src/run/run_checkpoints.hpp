// The checkpoints of one run (docs/checkpoints.md): when a time loop
// writes its state, what it writes at its end, how a stop signal ends it, and how a run resumes
// from its checkpoint, extends to a later t_end, or refuses a checkpoint it cannot continue.
//
//   solves      nothing: schedules and writes checkpoints of the state a runner lists
//   inputs      CheckpointPlan (file, wall-clock interval, resume mode, the scene's identity); the
//               runner's state as a function listing its members (run/state_io.hpp)
//   outputs     the checkpoint file (run/checkpoint_file.hpp); on resuming, the restored state
//   invariants  writing a checkpoint changes nothing a later step reads, so a run with checkpoints
//               computes the same bits as one without; a resumed run continues from a state its
//               build, its scene kind and its scene's settings wrote, or is refused in one line
//
// The time loop, run_loop (run/run_loop.hpp), calls around each step from t:
//     if (checkpoints.resume(t_end, state)) ... else ... start at t = 0
//     while (t < t_end) { checkpoints.before_step(t, t_end, longest_step, state); step; ...;
//                         checkpoints.after_step(t, steps, state); }
//     checkpoints.finish(t, steps, state);
// after_step writes the state every plan.every seconds of wall clock, and when SIGINT or SIGTERM
// has come (the handler only sets a flag; the loop sees it between steps), writes it and throws
// Interrupted. The last step of a run is shortened to land on t_end, so the state at t_end is on
// no longer run's path: before a step that may end the run (t + longest_step >= t_end) the state
// is kept in memory, and finish() writes both, the state at t_end ("state": to start other runs
// from, or to write the outputs again) and the state before the last step ("resume": to extend
// the run to a later t_end along the path of a run made with that t_end from the start). The
// output files the states hold (StateIO::blob) go once into the block "files".
#pragma once

#include "run/checkpoint_file.hpp"
#include "run/progress.hpp"
#include "run/state_io.hpp"

#include <chrono>
#include <functional>
#include <string>
#include <vector>

namespace granseg {

/// How a run treats an existing checkpoint.
enum class Resume {
    no,            // start at t = 0 (a checkpoint there is overwritten)
    yes,           // continue from it (granseg run --resume); one that cannot be continued is refused
    if_compatible  // continue from it if it can be, else start at t = 0 (the studies: a finished run
                   // is only written out again, an interrupted one continues, a stale one reruns)
};

struct CheckpointPlan {
    std::string path;      // the checkpoint file; empty: no checkpoints
    double every = 600.0;  // wall-clock seconds between checkpoints
    Resume resume = Resume::no;
    std::string kind;            // the scene kind
    std::string settings;        // SceneFile::settings() without the keys a resume may change
    std::string changeable;      // those keys, for messages ("[run] t_end, [run] angle_from")
    std::string resume_command;  // the command that resumes the run, for the message on a stop signal
};

/// A runner's state: a function that lists its members to a StateIO (both directions).
using RunState = std::function<void(StateIO&)>;

class RunCheckpoints {
public:
    /// No checkpoints.
    RunCheckpoints() = default;
    /// Checkpoints by `plan`; watches SIGINT and SIGTERM while it exists.
    explicit RunCheckpoints(CheckpointPlan plan);
    RunCheckpoints(const RunCheckpoints&) = delete;
    RunCheckpoints& operator=(const RunCheckpoints&) = delete;
    ~RunCheckpoints();

    bool enabled() const { return !plan_.path.empty(); }
    /// The checkpoint file ("" without checkpoints).
    const std::string& path() const { return plan_.path; }

    /// Restores `state` from the plan's checkpoint as plan.resume says and returns true; false:
    /// the run starts at t = 0. InputError (one line naming the file) for a checkpoint that cannot
    /// be continued with Resume::yes: damaged, of another kind, build or scene, or past t_end.
    bool resume(double t_end, const RunState& state);
    /// Before a step from t: keeps the state if the step may end the run (t + longest_step >= t_end).
    void before_step(double t, double t_end, double longest_step, const RunState& state);
    /// After a step: writes a checkpoint when due; after a stop signal writes one and throws
    /// Interrupted. A failed write is reported on stderr and the run goes on.
    void after_step(double t, long steps, const RunState& state);
    /// At t_end: writes the final checkpoint (the state, and the state kept before the last step);
    /// a run of more than a few seconds says on stderr what its checkpoints cost.
    void finish(double t, long steps, const RunState& state);
    /// Wall and CPU seconds the run spent before this process resumed it (0 for a fresh run).
    RunTime earlier() const { return earlier_; }

private:
    /// A checkpoint of the state `bytes` at t (and `resume_bytes`, the state before the last step),
    /// with the output files `blobs` they name.
    Checkpoint make(double t, long steps, bool finished, const std::string& bytes, const std::string& resume_bytes,
                    BlobStore& blobs) const;
    /// The state as bytes, with the run's wall and CPU seconds so far; its output files go to `files`.
    std::string saved(const RunState& state, BlobStore& files) const;
    /// Refuses the checkpoint `c` (Resume::yes: InputError; if_compatible: a note on stderr) and returns false.
    bool refuse(const std::string& why) const;
    /// Why `c` cannot continue this run ("" if it can).
    std::string mismatch(const Checkpoint& c) const;
    /// Writes `c` to the plan's file and counts it.
    void write(const Checkpoint& c);

    CheckpointPlan plan_;
    std::string kept_;      // the state before a step that may end the run
    BlobStore kept_files_;  // the output files it names (StateIO::blob)
    std::chrono::steady_clock::time_point start_, last_;
    double cpu_start_ = 0.0;
    RunTime earlier_;
    int written_ = 0;
    double last_size_ = 0.0, spent_ = 0.0;  // bytes of the last checkpoint; seconds spent on them all
};

/// The signal (SIGINT, SIGTERM) that asked the running checkpointed runs to stop; 0 if none.
int stop_signal();

/// Block `block` ("state", "resume") of checkpoint `c` (read from `path`) as a StateIO at the
/// runner's first member, reading its output files from `files` (filled from the checkpoint; null:
/// a state read only as far as its solver); `clock` (if given) gets the run's wall and CPU seconds
/// saved before it.
StateIO runner_state(const Checkpoint& c, const std::string& block, const std::string& path, BlobStore* files = nullptr,
                     RunTime* clock = nullptr);

/// `checkpoints`, or if null a plan without checkpoints (shared: it changes nothing), so that a
/// time loop calls the same functions with and without.
RunCheckpoints& checkpoints_or_none(RunCheckpoints* checkpoints);

}  // namespace granseg
