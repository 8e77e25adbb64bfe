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
#include <vector>

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

/// True if a loop over a grid where threads pay (`parallel`, from threads_pay) is shared among
/// threads now, i.e. more than one is available. Otherwise the loop runs plainly, outside any
/// OpenMP region: a region costs a few microseconds even on one thread (libgomp ends each with a
/// futex system call), more than many of the step's loops; on a small grid those regions took
/// half of a one-thread run's time.
inline bool on_threads(bool parallel) { return parallel && omp_get_max_threads() > 1; }

/// Calls body(i) for i in [0, n): shared among the threads in a static schedule where
/// on_threads(parallel), else in order on this thread.
template <class Index, class Body>
void for_each_index(bool parallel, Index n, Body&& body) {
    if (on_threads(parallel)) {
#pragma omp parallel for schedule(static)
        for (Index i = 0; i < n; ++i) body(i);
    } else {
        for (Index i = 0; i < n; ++i) body(i);
    }
}

/// Calls body(i, j) for i in [0, n), j in [0, m): the pairs shared in one static schedule where
/// on_threads(parallel) (collapse(2)), else in order on this thread.
template <class Index, class Body>
void for_each_pair(bool parallel, Index n, Index m, Body&& body) {
    if (on_threads(parallel)) {
#pragma omp parallel for collapse(2) schedule(static)
        for (Index i = 0; i < n; ++i)
            for (Index j = 0; j < m; ++j) body(i, j);
    } else {
        for (Index i = 0; i < n; ++i)
            for (Index j = 0; j < m; ++j) body(i, j);
    }
}

/// A reduction over [0, n): each thread folds body(acc, i) over its share of the indices into its
/// own copy of `init`, and the copies are combined in thread order by combine(a, b). The result
/// does not depend on the thread count where combine is exact (max, min, integer sums, or).
template <class T, class Index, class Body, class Combine>
T fold_indices(bool parallel, Index n, const T& init, Body&& body, Combine&& combine) {
    if (!on_threads(parallel)) {
        T acc = init;
        for (Index i = 0; i < n; ++i) body(acc, i);
        return acc;
    }
    std::vector<T> part(static_cast<std::size_t>(omp_get_max_threads()), init);
#pragma omp parallel
    {
        T acc = init;
#pragma omp for schedule(static)
        for (Index i = 0; i < n; ++i) body(acc, i);
        part[static_cast<std::size_t>(omp_get_thread_num())] = acc;
    }
    T acc = init;
    for (const T& p : part) acc = combine(acc, p);
    return acc;
}

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
