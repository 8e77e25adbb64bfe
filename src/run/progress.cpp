#include "run/progress.hpp"

#include "core/threads.hpp"

#include <cstdio>
#include <ctime>

namespace granseg {

double run_cpu_seconds() {
    timespec t{};
    clock_gettime(max_threads() == 1 ? CLOCK_THREAD_CPUTIME_ID : CLOCK_PROCESS_CPUTIME_ID, &t);
    return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

Progress::Progress(std::string label, double total, double start, double quiet_seconds, double every_seconds)
    : label_(std::move(label)),
      total_(total),
      start_value_(start),
      quiet_(quiet_seconds),
      every_(every_seconds),
      start_(clock::now()),
      last_(start_),
      cpu_start_(run_cpu_seconds()) {}

void Progress::update(double done) {
    const auto now = clock::now();
    const double elapsed = std::chrono::duration<double>(now - start_).count();
    const double since = std::chrono::duration<double>(now - last_).count();
    if (elapsed < quiet_ || (printed_ && since < every_)) return;
    const double fraction = total_ > 0 ? done / total_ : 1.0;
    const double run = total_ > start_value_ ? (done - start_value_) / (total_ - start_value_) : 1.0;  // share of this run's part
    const double eta = run > 0 ? elapsed * (1.0 - run) / run : 0.0;
    std::fprintf(stderr, "%s: %3.0f%% (%.4g of %.4g) %.0f s elapsed, ETA %.0f s\n", label_.c_str(), 100.0 * fraction, done,
                 total_, elapsed, eta);
    printed_ = true;
    last_ = now;
}

RunTime Progress::finish(int threads) {
    const RunTime cost{wall_seconds(), cpu_seconds(), threads};
    if (printed_)
        std::fprintf(stderr, "%s: done in %.1f s wall, %.1f s CPU (%d thread%s)\n", label_.c_str(), cost.wall, cost.cpu, threads,
                     threads == 1 ? "" : "s");
    return cost;
}

double Progress::wall_seconds() const { return std::chrono::duration<double>(clock::now() - start_).count(); }

double Progress::cpu_seconds() const { return run_cpu_seconds() - cpu_start_; }

}  // namespace granseg
