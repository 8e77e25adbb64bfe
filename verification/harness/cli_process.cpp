#include "harness/cli_process.hpp"

#include "harness/doc_blocks.hpp"

#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <thread>

namespace granseg::verify {

namespace fs = std::filesystem;

long line_count(const std::string& text) {
    long n = 0;
    for (char c : text) n += c == '\n';
    return n;
}

Cli::Cli(fs::path binary, fs::path work) : binary_(std::move(binary)), work_(std::move(work)) {}

fs::path Cli::beside(const char* argv0) { return fs::absolute(fs::path(argv0)).parent_path().parent_path() / "granseg"; }

Outcome Cli::run(const std::string& arguments, const std::string& environment, double seconds, int signal,
                 const std::function<bool()>& since) const {
    const fs::path out = work_ / "stdout.txt", err = work_ / "stderr.txt";
    // exec: the shell becomes env, env becomes granseg, so the signal reaches the CLI itself.
    const std::string command = "exec env " + environment + " '" + binary_.string() + "' " + arguments + " > '" + out.string() +
                                "' 2> '" + err.string() + "' < /dev/null";
    const pid_t child = fork();
    if (child == 0) {
        execl("/bin/sh", "sh", "-c", command.c_str(), static_cast<char*>(nullptr));
        _exit(127);
    }
    int raw = 0;
    const auto wait = std::chrono::duration<double>(std::isfinite(seconds) ? seconds : 1e9);
    auto deadline = std::chrono::steady_clock::now() + wait;
    bool started = !since, sent = false;
    while (waitpid(child, &raw, WNOHANG) == 0) {
        if (!started && since()) started = true, deadline = std::chrono::steady_clock::now() + wait;
        if (started && !sent && signal != 0 && std::chrono::steady_clock::now() >= deadline) kill(child, signal), sent = true;
        std::this_thread::sleep_for(std::chrono::milliseconds(2));
    }
    Outcome o;
    o.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : WIFSIGNALED(raw) ? 128 + WTERMSIG(raw) : -1;
    o.out = docs::read_text(out);
    o.err = docs::read_text(err);
    return o;
}

}  // namespace granseg::verify
