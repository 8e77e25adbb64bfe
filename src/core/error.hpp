// Error types shared by the library, the CLI and the verification programs.
//
// InputError:     a scene file or a command-line argument is wrong. The message is the single
//                 line the user sees, e.g. "scene.toml: [grid] cells: ... (allowed: ...)".
//                 The CLI prints it and exits with status 2 before writing any output.
// InvariantError: a running simulation broke one of its invariants (mass, bounds, finite
//                 fields), or the code broke its own consistency (a bug: a Riemann problem
//                 without a solution, a missing embedded file). The CLI prints it and exits
//                 with status 3; no output is written.
// Interrupted:    a run stopped by SIGINT or SIGTERM after writing its checkpoint
//                 (run/run_checkpoints.hpp). The CLI prints the message (where the checkpoint is,
//                 how to continue) and exits with status 128 + the signal's number (130, 143).
// The library throws nothing else: a bad value handed to any function is an InputError, so every
// entry point (granseg, the verification programs through harness/program.hpp) ends with the
// one line and exit status 2.
#pragma once

#include <stdexcept>
#include <string>

namespace granseg {

/// Bad user input (scene file, CLI argument); exit status 2.
class InputError : public std::runtime_error {
public:
    explicit InputError(const std::string& message) : std::runtime_error(message) {}
};

/// A simulation invariant failed while running; exit status 3.
class InvariantError : public std::runtime_error {
public:
    explicit InvariantError(const std::string& message) : std::runtime_error(message) {}
};

/// A run stopped by a signal after writing its checkpoint; exit status 128 + signal.
class Interrupted : public std::runtime_error {
public:
    Interrupted(const std::string& message, int signal) : std::runtime_error(message), signal_(signal) {}
    int signal() const { return signal_; }

private:
    int signal_;
};

/// Exit statuses used by every executable of the project.
enum ExitStatus : int { kExitOk = 0, kExitFailure = 1, kExitBadInput = 2, kExitInvariant = 3 };

}  // namespace granseg
