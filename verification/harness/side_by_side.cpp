#include "harness/side_by_side.hpp"
#include "core/threads.hpp"

#include <time.h>

#include <algorithm>
#include <atomic>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

namespace granseg::verify {

int machine_cores() { return std::max(1u, std::thread::hardware_concurrency()); }

void run_side_by_side(int jobs, int lanes, const std::function<void(int)>& work) {
    if (lanes <= 1) {
        for (int j = 0; j < jobs; ++j) work(j);
        return;
    }
    std::atomic<int> next{0};
    std::atomic<bool> failed{false};
    std::exception_ptr first;
    std::mutex guard;
    auto lane = [&] {
        const ThreadScope one(1);  // this lane's parallel regions, and Eigen's, get one thread
        for (int j; !failed && (j = next++) < jobs;) {
            try {
                work(j);
            } catch (...) {
                const std::lock_guard<std::mutex> lock(guard);
                if (!first) first = std::current_exception();
                failed = true;
            }
        }
    };
    std::vector<std::thread> threads;
    for (int l = 0; l < std::min(lanes, jobs); ++l) threads.emplace_back(lane);
    for (std::thread& t : threads) t.join();
    if (first) std::rethrow_exception(first);
}

double thread_cpu_seconds() {
    timespec ts{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

}  // namespace granseg::verify
