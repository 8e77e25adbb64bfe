// A scoped timer: the wall-clock seconds of a scope added to an account, so that a stage of a step
// reads as its physics with one line that times it (the flow step's stages, FlowSolver; the
// coupled step's parts, CoupledTumbler).
#pragma once

#include <chrono>

namespace granseg {

/// Adds the wall-clock seconds from its construction to its end to `account`.
class Stopwatch {
public:
    explicit Stopwatch(double& account) : account_(account), start_(std::chrono::steady_clock::now()) {}
    ~Stopwatch() { account_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count(); }
    Stopwatch(const Stopwatch&) = delete;
    Stopwatch& operator=(const Stopwatch&) = delete;

private:
    double& account_;
    std::chrono::steady_clock::time_point start_;
};

/// Calls f() in a Stopwatch on `account` and returns what it returns.
template <class F>
auto timed(double& account, F&& f) {
    const Stopwatch watch(account);
    return f();
}

}  // namespace granseg
