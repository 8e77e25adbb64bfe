// How many OpenMP threads a run uses (docs/flow_solver_choices.md, "Threads"; README.md).
//
//   decides     whether the loops over a grid run on the OpenMP threads (OMP_NUM_THREADS, by
//               default one per core) or on one thread: one rule for the flow step, the
//               reconstruction, the bulk transport and the coupled drum's loops
//   invariants  the results do not depend on the thread count (every threaded loop writes
//               disjoint entries; reductions are max/min/sum of integers, or of doubles in a
//               fixed order) - tests/test_threads.cpp checks a drum bitwise on 1 and 2 threads
#pragma once

#include <cstddef>

#include <omp.h>

namespace granseg {

/// Grids of fewer cells (all grid cells, inside or not) run on one thread. The crossover measured
/// on the coupled drum, two threads against one, wall and CPU time (docs/flow_solver_choices.md,
/// "Threads"): 50 cells per diameter (2,500 grid cells) 0.99 / 1.92, 71 (5,041) 0.93 / 1.82,
/// 100 (10,000) 0.76 / 1.47: below about 8,000 cells a second thread buys a few per cent of wall
/// time for nearly twice the CPU, since per step the threads meet some 200 times (fork, join,
/// barrier) around loops of a few microseconds each.
constexpr std::size_t kParallelCells = 8192;

/// True if loops over a grid of `cells` cells run on the OpenMP threads.
inline bool threads_pay(std::size_t cells) { return cells >= kParallelCells; }

/// Threads a run uses: the OpenMP threads on a grid where threads pay (threads_pay), else one.
inline int run_threads(std::size_t cells) { return threads_pay(cells) ? omp_get_max_threads() : 1; }

/// Within its scope every parallel region (the project's loops and Eigen's products alike) gets
/// one thread where `serial`; the caller's thread count comes back on exit.
class SerialScope {
public:
    explicit SerialScope(bool serial) : threads_(serial ? omp_get_max_threads() : 0) {
        if (serial) omp_set_num_threads(1);
    }
    ~SerialScope() {
        if (threads_ > 0) omp_set_num_threads(threads_);
    }
    SerialScope(const SerialScope&) = delete;
    SerialScope& operator=(const SerialScope&) = delete;

private:
    int threads_;
};

}  // namespace granseg
