// Independent runs of a study side by side, one OpenMP thread each (docs/flow_solver_choices.md,
// "Threads"): on the drum a second thread buys a run little wall time, so a study of many runs
// finishes sooner with one run per core than with its runs one after another on all cores.
#pragma once

#include <functional>

namespace granseg::verify {

/// The machine's cores, whatever OMP_NUM_THREADS says (std::thread::hardware_concurrency, >= 1).
int machine_cores();

/// Runs work(0), ..., work(jobs - 1) on `lanes` threads side by side (each job whole on one lane,
/// the next free lane taking the next job), every job on one OpenMP thread; lanes = 1 runs them
/// in order on the caller's thread with its OpenMP threads. The first exception a job throws is
/// rethrown once every lane has stopped (the jobs not yet started do not start).
void run_side_by_side(int jobs, int lanes, const std::function<void(int)>& work);

/// CPU seconds of the calling thread: a run's CPU time when it runs on one thread beside others
/// (cpu_seconds() would count the whole process).
double thread_cpu_seconds();

}  // namespace granseg::verify
