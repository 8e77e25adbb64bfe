// The thread count leaves the bits: the coupled drum on the smallest grid whose loops run on the
// OpenMP threads (core/threads.hpp), stepped on one thread and on two, gives the same Phi, phi,
// u and T to the last bit (every threaded loop writes disjoint entries; every reduction is a max,
// a min or a sum of integers; Eigen's threaded sparse products sum each row in one thread). And
// below that grid a run opens no second thread at all, whatever OMP_NUM_THREADS says.
#include "core/threads.hpp"
#include "tumbler/coupled_tumbler.hpp"

#include <boost/test/unit_test.hpp>

#include <omp.h>

#include <array>
#include <vector>

using namespace granseg;

namespace {

/// The smallest drum (cells per diameter) whose grid runs on threads.
int smallest_threaded_drum() {
    DrumSpec drum;
    for (drum.cells_per_diameter = 8; !threads_pay(drum.grid().cells()); ++drum.cells_per_diameter) {}
    return drum.cells_per_diameter;
}

/// Phi, phi, u_x, u_z and T of the drum after `steps` coupled steps on `threads` threads.
std::vector<std::vector<double>> drum_after(int cells_per_diameter, int steps, int threads) {
    const int before = omp_get_max_threads();
    omp_set_num_threads(threads);
    CoupledTumblerSetup setup;
    setup.drum.cells_per_diameter = cells_per_diameter;
    CoupledTumbler tumbler(setup);
    for (int n = 0; n < steps; ++n) tumbler.step();
    omp_set_num_threads(before);
    const FlowSolver& flow = tumbler.flow();
    return {flow.Phi(), tumbler.phi(), flow.u(0), flow.u(2), flow.T()};
}

/// Largest number of threads in any parallel region opened by `work` (a region reports its team).
template <class Work>
int largest_team(Work&& work) {
    int largest = 0;
    work([&] {
#pragma omp parallel
        {
#pragma omp critical
            largest = std::max(largest, omp_get_num_threads());
        }
    });
    return largest;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(threads)

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
    const int before = omp_get_max_threads();
    omp_set_num_threads(2);
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
    BOOST_TEST(omp_get_max_threads() == 2);
    BOOST_TEST(run_threads(kParallelCells - 1) == 1);
    BOOST_TEST(run_threads(kParallelCells) == 2);
    omp_set_num_threads(before);
}

BOOST_AUTO_TEST_SUITE_END()
