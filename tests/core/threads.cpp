// The thread count leaves the bits: the coupled drum on the smallest grid whose loops run on the
// OpenMP threads (core/threads.hpp), stepped on one thread and on two, gives the same Phi, phi,
// u and T to the last bit (every threaded loop writes disjoint entries; every reduction is a max,
// a min or a sum of integers; Eigen's threaded sparse products sum each row in one thread). And
// below that grid a run opens no second thread at all, whatever OMP_NUM_THREADS says.
#include "core/threads.hpp"
#include "coupled/coupled_tumbler.hpp"

#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <tuple>
#include <vector>

using namespace granseg;

namespace {

/// The smallest drum (cells per diameter) whose grid runs on threads.
int smallest_threaded_drum() {
    DrumSpec drum;
    for (drum.cells_per_diameter = 8; !threads_pay(drum.grid().cells()); ++drum.cells_per_diameter) {
    }
    return drum.cells_per_diameter;
}

/// Phi, phi, u_x, u_z and T of the drum after `steps` coupled steps on `threads` threads.
std::vector<std::vector<double>> drum_after(int cells_per_diameter, int steps, int threads) {
    const ThreadScope scope(threads);
    CoupledTumblerSetup setup;
    setup.drum.cells_per_diameter = cells_per_diameter;
    CoupledTumbler tumbler(setup);
    for (int n = 0; n < steps; ++n) tumbler.step();
    const FlowSolver& flow = tumbler.flow();
    return {flow.Phi(), tumbler.phi(), flow.u(0), flow.u(2), flow.T()};
}

/// Largest number of threads in any parallel region opened by `work` (a region reports its team).
template <class Work>
int largest_team(Work&& work) {
    int largest = 0;
    work([&] { largest = std::max(largest, region_threads()); });
    return largest;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(core_threads_tests)

BOOST_AUTO_TEST_CASE(one_and_two_threads_give_the_same_drum_to_the_bit) {
    const int n = smallest_threaded_drum();
    const auto one = drum_after(n, 12, 1), two = drum_after(n, 12, 2);
    for (std::size_t f = 0; f < one.size(); ++f) {
        long differ = 0;
        for (std::size_t c = 0; c < one[f].size(); ++c) differ += one[f][c] != two[f][c];
        BOOST_TEST(differ == 0, "field " << f << ": " << differ << " cells differ");
    }
}

BOOST_AUTO_TEST_CASE(below_the_crossover_a_run_opens_one_thread) {
    const ThreadScope two(2);
    // SerialScope is what a step below the crossover runs in: every region in it gets one thread
    // (Eigen's products read the same setting), and the caller's setting comes back after it.
    const int inside = largest_team([](auto region) {
        const SerialScope serial(true);
        region();
    });
    const int outside = largest_team([](auto region) {
        const SerialScope serial(false);
        region();
    });
    BOOST_TEST(inside == 1);
    BOOST_TEST(outside == 2);
    BOOST_TEST(max_threads() == 2);
    BOOST_TEST(run_threads(kParallelCells - 1) == 1);
    BOOST_TEST(run_threads(kParallelCells) == 2);
}

BOOST_AUTO_TEST_CASE(loops_run_on_threads_only_where_they_pay_and_more_than_one_is_there) {
    // The thread and the OpenMP nesting level each index ran at (level 0: outside any region,
    // not even a one-thread team), and a reduction (largest value, count) over the indices.
    auto run = [](bool parallel) {
        std::vector<int> thread(1000, -1), level(1000, -1);
        parallel_for(parallel, thread.size(), [&](std::size_t i) { thread[i] = thread_number(), level[i] = region_level(); });
        struct Fold {
            double largest = 0.0;
            long count = 0;
        };
        const Fold f = parallel_fold(
            parallel, 1000L, Fold{},
            [](Fold& acc, long i) {
                acc.largest = std::max(acc.largest, static_cast<double>((i * 7919) % 1000));
                acc.count += i % 3 == 0;
            },
            [](const Fold& x, const Fold& y) {
                return Fold{std::max(x.largest, y.largest), x.count + y.count};
            });
        return std::make_tuple(*std::max_element(thread.begin(), thread.end()), *std::max_element(level.begin(), level.end()),
                               f.largest, f.count);
    };
    const auto on_two = [&](bool parallel) {
        const ThreadScope two(2);
        return run(parallel);
    };
    const auto [threads_on, level_on, largest_on, count_on] = on_two(true);
    const auto [threads_off, level_off, largest_off, count_off] = on_two(false);
    const auto [threads_one, level_one, largest_one, count_one] = [&] {
        const ThreadScope one(1);
        return run(true);
    }();
    BOOST_TEST((threads_on == 1 && level_on == 1));    // the second thread took its share
    BOOST_TEST((threads_off == 0 && level_off == 0));  // a grid below the crossover: no region
    BOOST_TEST((threads_one == 0 && level_one == 0));  // one thread: no region either
    BOOST_TEST((largest_on == largest_off && largest_off == largest_one && largest_one == 999.0));
    BOOST_TEST((count_on == count_off && count_off == count_one && count_one == 334));
}

BOOST_AUTO_TEST_CASE(a_team_shares_its_loops_and_sums_to_the_same_bits_on_any_number_of_threads) {
    const long n = 5000;  // about ten blocks of a dot product
    std::vector<double> a(n), b(n);
    for (long i = 0; i < n; ++i) a[i] = 1.0 / (1.0 + i), b[i] = std::sin(0.37 * i);
    // Three dot products in a row on every thread (the partial sums are reused in turn), and a
    // shared loop whose rows must all be written before any thread reads them.
    auto run = [&](int threads) {
        const ThreadScope scope(threads);
        std::vector<std::array<double, 3>> seen(threads);
        std::vector<double> twice(n, 0.0);
        long wrong = 0;
        run_as_team(true, n, [&](Team& team) {
            std::array<double, 3>& mine = seen[thread_number()];
            mine = {team.dot(a.data(), b.data(), n), team.dot(b.data(), b.data(), n), team.dot(a.data(), a.data(), n)};
            team.share(n, [&](long begin, long end) {
                for (long i = begin; i < end; ++i) twice[i] = 2.0 * a[i];
            });
            long bad = 0;
            for (long i = 0; i < n; ++i) bad += twice[i] != 2.0 * a[i];
            team.single([&] { wrong = bad; });
        });
        for (const auto& s : seen) BOOST_TEST((s == seen[0]));  // every thread got the same sums
        BOOST_TEST(wrong == 0);
        return seen[0];
    };
    const auto one = run(1), two = run(2), three = run(3);
    BOOST_TEST((one == two && two == three));
}

BOOST_AUTO_TEST_CASE(lanes_run_once_each_on_threads_that_open_no_more) {
    const ThreadScope two(2);
    std::array<int, 2> runs{0, 0}, threads{0, 0}, team{0, 0};
    parallel_lanes(true, 2, [&](int l) {
        ++runs[l];
        threads[l] = thread_number();
        team[l] = region_threads();
    });
    BOOST_TEST((runs[0] == 1 && runs[1] == 1));
    BOOST_TEST(threads[0] != threads[1]);        // side by side
    BOOST_TEST((team[0] == 1 && team[1] == 1));  // a region inside a lane gets one thread
}

BOOST_AUTO_TEST_SUITE_END()
