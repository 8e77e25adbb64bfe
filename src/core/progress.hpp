// Progress on stderr for long runs: "label: 42% (t = 10.5 of 25) 12 s elapsed, ETA 16 s".
// Silent for the first few seconds, so short runs and verification programs stay quiet; then
// one line every few seconds (plain lines, readable in CI logs).
#pragma once

#include <chrono>
#include <string>

namespace granseg {

class Progress {
public:
    /// `label` prefixes each line; `total` is the value of the progress variable at the end.
    Progress(std::string label, double total, double quiet_seconds = 3.0, double every_seconds = 5.0);
    /// Reports that the progress variable has reached `done` (prints only when due).
    void update(double done);
    /// Prints a final line if anything was printed before.
    void finish();

private:
    using clock = std::chrono::steady_clock;
    std::string label_;
    double total_;
    double quiet_, every_;
    clock::time_point start_, last_;
    bool printed_ = false;
};

}  // namespace granseg
