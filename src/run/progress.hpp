// Progress on stderr for long runs: "label: 42% (t = 10.5 of 25) 12 s elapsed, ETA 16 s".
// Silent for the first few seconds, so short runs and verification programs stay quiet; then
// one line every few seconds (plain lines, readable in CI logs). The run's wall and CPU seconds
// (run_cpu_seconds: all its threads) and its threads go to the last line; wall_seconds() and
// cpu_seconds() feed the run summaries.
#pragma once

#include <chrono>
#include <string>

namespace granseg {

/// What a run cost: wall-clock seconds, CPU seconds of the whole process (every thread), threads.
struct RunTime {
    double wall = 0.0, cpu = 0.0;
    int threads = 1;
    /// This run's cost with the seconds of its earlier part (a resumed run, run/run_checkpoints.hpp).
    RunTime operator+(const RunTime& earlier) const { return {wall + earlier.wall, cpu + earlier.cpu, threads}; }
};

/// CPU seconds of the run going on in this thread, since the process started: this thread's own
/// where OpenMP gives it one thread (the run does all its work here, while other runs may share
/// the process: a study's runs side by side), else the whole process's (every thread).
double run_cpu_seconds();

class Progress {
public:
    /// `label` prefixes each line; `total` is the value of the progress variable at the end and
    /// `start` its value now (a resumed run's: the ETA follows the rate since then).
    Progress(std::string label, double total, double start = 0.0, double quiet_seconds = 3.0, double every_seconds = 5.0);
    /// Reports that the progress variable has reached `done` (prints only when due).
    void update(double done);
    /// The run's cost so far; prints it as a final line if anything was printed before.
    RunTime finish(int threads = 1);
    /// Wall-clock seconds since construction.
    double wall_seconds() const;
    /// CPU seconds of the run (run_cpu_seconds) since construction.
    double cpu_seconds() const;

private:
    using clock = std::chrono::steady_clock;
    std::string label_;
    double total_, start_value_;
    double quiet_, every_;
    clock::time_point start_, last_;
    double cpu_start_;
    bool printed_ = false;
};

}  // namespace granseg
