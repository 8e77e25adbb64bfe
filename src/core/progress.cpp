#include "core/progress.hpp"

#include <cstdio>

namespace granseg {

Progress::Progress(std::string label, double total, double quiet_seconds, double every_seconds)
    : label_(std::move(label)), total_(total), quiet_(quiet_seconds), every_(every_seconds),
      start_(clock::now()), last_(start_) {}

void Progress::update(double done) {
    const auto now = clock::now();
    const double elapsed = std::chrono::duration<double>(now - start_).count();
    const double since = std::chrono::duration<double>(now - last_).count();
    if (elapsed < quiet_ || (printed_ && since < every_)) return;
    const double fraction = total_ > 0 ? done / total_ : 1.0;
    const double eta = fraction > 0 ? elapsed * (1.0 - fraction) / fraction : 0.0;
    std::fprintf(stderr, "%s: %3.0f%% (%.4g of %.4g) %.0f s elapsed, ETA %.0f s\n", label_.c_str(),
                 100.0 * fraction, done, total_, elapsed, eta);
    printed_ = true;
    last_ = now;
}

void Progress::finish() {
    if (!printed_) return;
    const double elapsed = std::chrono::duration<double>(clock::now() - start_).count();
    std::fprintf(stderr, "%s: done in %.1f s\n", label_.c_str(), elapsed);
}

}  // namespace granseg
