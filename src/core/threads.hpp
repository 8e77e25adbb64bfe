// How the code runs on OpenMP threads: the one vocabulary every threaded loop uses
// (docs/flow_solver_choices.md, "Threads"; README.md).
//
//   decides     whether the loops over a grid run on the OpenMP threads (OMP_NUM_THREADS, by
//               default one per core) or on one thread: one rule (threads_pay) for the flow step,
//               the reconstruction, the bulk transport and the coupled drum's loops
//   offers      the only ways the code forks, each saying so in its name:
//                 parallel_for, parallel_for_pairs, parallel_fold, parallel_blocks: one parallel
//                   region per loop (FlowMesh's parallel_for_* loops are built on them);
//                 run_as_team and Team: one region for a whole algorithm whose loops are too
//                   short to open a region each; every member of Team ends with the barrier it
//                   needs, so a caller never writes one;
//                 parallel_lanes: a few independent tasks, one thread each, none forking again;
//                 ThreadScope, SerialScope: a scope that sets the thread count (SerialScope: one)
//                   and restores it on exit; max_threads and the team queries read it.
//               No other OpenMP directive or omp_ call appears in src/, tests/ or verification/
//               but `omp simd` (vectorisation).
//   invariants  the results do not depend on the thread count (every threaded loop writes
//               disjoint entries; reductions are max/min/sum of integers, or of doubles in a
//               fixed order) - tests/core/threads.cpp checks a drum bitwise on 1 and 2 threads
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <vector>

#include <omp.h>

namespace granseg {

/// Grids of fewer cells (all grid cells, inside or not) run on one thread: below this size a
/// second thread buys little wall time for nearly twice the CPU, since per step the threads meet
/// (fork, join, barrier) around each of many loops of a few microseconds (the crossover measured
/// on the coupled drum: docs/flow_solver_choices.md, "Threads").
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
void parallel_for(bool parallel, Index n, Body&& body) {
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
void parallel_for_pairs(bool parallel, Index n, Index m, Body&& body) {
    if (on_threads(parallel)) {
#pragma omp parallel for collapse(2) schedule(static)
        for (Index i = 0; i < n; ++i)
            for (Index j = 0; j < m; ++j) body(i, j);
    } else {
        for (Index i = 0; i < n; ++i)
            for (Index j = 0; j < m; ++j) body(i, j);
    }
}

/// Calls body(begin, end) on one contiguous block of [0, n) per thread, in thread order, where
/// on_threads(parallel), else body(0, n) on this thread.
template <class Body>
void parallel_blocks(bool parallel, long n, Body&& body) {
    if (on_threads(parallel)) {
#pragma omp parallel
        {
            const long t = omp_get_thread_num(), threads = omp_get_num_threads();
            body(n * t / threads, n * (t + 1) / threads);
        }
    } else {
        body(0L, n);
    }
}

/// A reduction over [0, n): each thread folds body(acc, i) over its share of the indices into its
/// own copy of `init`, and the copies are combined in thread order by combine(a, b). The result
/// does not depend on the thread count where combine is exact (max, min, integer sums, or).
template <class T, class Index, class Body, class Combine>
T parallel_fold(bool parallel, Index n, const T& init, Body&& body, Combine&& combine) {
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

/// The threads a parallel region opened now gets (OMP_NUM_THREADS, or what a ThreadScope set).
inline int max_threads() { return omp_get_max_threads(); }
/// The threads a parallel region opened here gets: it opens one and counts its team.
inline int region_threads() {
    int team = 1;
#pragma omp parallel
#pragma omp single
    team = omp_get_num_threads();
    return team;
}
/// This thread's number in its team and how deep the parallel regions around it nest (0 and 0
/// outside any region).
inline int thread_number() { return omp_get_thread_num(); }
inline int region_level() { return omp_get_level(); }

/// Within its scope every parallel region (the project's loops and Eigen's products alike) gets
/// `threads` threads (0: as before); the caller's thread count comes back on exit, an exception's
/// included. Tests, benchmarks and the verification harness set a thread count only this way.
class ThreadScope {
public:
    explicit ThreadScope(int threads) : before_(threads > 0 ? omp_get_max_threads() : 0) {
        if (threads > 0) omp_set_num_threads(threads);
    }
    ~ThreadScope() {
        if (before_ > 0) omp_set_num_threads(before_);
    }
    ThreadScope(const ThreadScope&) = delete;
    ThreadScope& operator=(const ThreadScope&) = delete;

private:
    int before_;
};

/// A ThreadScope of one thread where `serial` (else nothing changes).
class SerialScope : ThreadScope {
public:
    explicit SerialScope(bool serial) : ThreadScope(serial ? 1 : 0) {}
};

/// Calls body(l) for each of `lanes` independent lanes: each lane on a thread of its own where
/// on_threads(parallel) (threads beyond `lanes` wait), else the lanes in order on this thread.
/// Either way a lane runs in a SerialScope: nothing it calls (Eigen's products included) opens
/// threads of its own, so its arithmetic does not depend on the thread count.
template <class Body>
void parallel_lanes(bool parallel, int lanes, Body&& body) {
    if (on_threads(parallel)) {
#pragma omp parallel for schedule(static, 1)
        for (int l = 0; l < lanes; ++l) {
            const SerialScope alone(true);
            body(l);
        }
    } else {
        const SerialScope alone(true);
        for (int l = 0; l < lanes; ++l) body(l);
    }
}

/// The partial sums a team's dot products share: one set for each of two products in turn.
class TeamSums {
public:
    /// Rows per block of a dot product: the blocks' partial sums, added in block order, fix the
    /// rounding whatever the number of threads.
    static constexpr long kBlock = 512;
    /// Room for dot products of up to `rows` values.
    explicit TeamSums(long rows) {
        for (auto& p : partial_) p.resize(static_cast<std::size_t>((rows + kBlock - 1) / kBlock));
    }

private:
    friend class Team;
    std::array<std::vector<double>, 2> partial_;
};

/// One thread's handle on a team: the threads of one parallel region that all run the same code
/// (run_as_team). Every thread calls the same members in the same order; each member ends with a
/// barrier, so that what the team wrote in it is complete before any thread reads it.
class Team {
public:
    explicit Team(TeamSums& sums) : sums_(sums) {}
    Team(const Team&) = delete;
    Team& operator=(const Team&) = delete;

    /// body(begin, end) on this thread's block of [0, n) (contiguous, in thread order); then
    /// waits for the team.
    template <class Body>
    void share(long n, Body&& body) const {
        const long t = omp_get_thread_num(), threads = omp_get_num_threads();
        body(n * t / threads, n * (t + 1) / threads);
#pragma omp barrier
    }

    /// body() on one thread while the others wait for it.
    template <class Body>
    void single(Body&& body) const {
#pragma omp single
        body();
    }

    /// sum_r a_r b_r over [0, n), the same value on every thread and the same bits on any number
    /// of threads: blocks of TeamSums::kBlock rows shared among the threads, their partial sums
    /// added in block order. Successive products write the two sets of partial sums in turn, so a
    /// product never overwrites sums that a slower thread is still adding (the barrier of the
    /// product in between has passed only once every thread finished the one before).
    double dot(const double* a, const double* b, long n) {
        std::vector<double>& partial = sums_.partial_[turn_];
        turn_ = 1 - turn_;
        const long blocks = (n + TeamSums::kBlock - 1) / TeamSums::kBlock;
        share(blocks, [&](long first, long last) {
            for (long k = first; k < last; ++k) {
                double sum = 0.0;
                const long end = std::min(n, (k + 1) * TeamSums::kBlock);
                for (long r = k * TeamSums::kBlock; r < end; ++r) sum += a[r] * b[r];
                partial[static_cast<std::size_t>(k)] = sum;
            }
        });
        double sum = 0.0;
        for (long k = 0; k < blocks; ++k) sum += partial[static_cast<std::size_t>(k)];
        return sum;
    }

private:
    TeamSums& sums_;
    int turn_ = 0;  // which set of partial sums the next dot product writes
};

/// Calls body(team) on every thread of one parallel region where on_threads(parallel), else once
/// on this thread (a team of one, outside any region). `rows`: the longest dot product of the
/// team (Team::dot).
template <class Body>
void run_as_team(bool parallel, long rows, Body&& body) {
    TeamSums sums(rows);
    if (on_threads(parallel)) {
#pragma omp parallel
        {
            Team team(sums);
            body(team);
        }
    } else {
        Team team(sums);
        body(team);
    }
}

}  // namespace granseg
