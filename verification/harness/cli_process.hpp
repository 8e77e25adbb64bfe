// Running build/granseg from a verification program (verify_cli_errors, verify_resume): its exit
// status and what it printed, optionally stopped by a signal after some seconds.
#pragma once

#include <cmath>
#include <filesystem>
#include <functional>
#include <string>

namespace granseg::verify {

/// How a run of the CLI ended.
struct Outcome {
    int status = -1;       // exit status; 128 + the signal's number if a signal ended it
    std::string out, err;  // what it printed on stdout and stderr
};

/// Lines of a text (its newlines).
long line_count(const std::string& text);

class Cli {
public:
    /// `binary`: the CLI; `work`: a directory for its captured output.
    Cli(std::filesystem::path binary, std::filesystem::path work);
    /// The CLI of the build tree a program runs from (build/granseg beside build/verification/).
    static std::filesystem::path beside(const char* argv0);

    /// Runs `granseg ARGUMENTS` (words as a shell splits them), with the variables `environment`
    /// ("OMP_NUM_THREADS=2 ...") set, and waits for it; sends it `signal` once `seconds` have passed
    /// since it started, or since `since()` first held (polled every 2 ms).
    Outcome run(const std::string& arguments, const std::string& environment = "", double seconds = INFINITY, int signal = 0,
                const std::function<bool()>& since = {}) const;

private:
    std::filesystem::path binary_, work_;
};

}  // namespace granseg::verify
