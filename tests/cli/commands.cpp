// The command line (src/cli/) as a user meets it: build/granseg run as a process. `granseg
// closures` prints the state and then the closures' columns as the closure-sweep writes them
// (closure_columns, listed once); a bad command or option is one line and exit status 2; a run
// that cannot get its memory says so in one line, with what it needed.
#include "closures/closures.hpp"
#include "core/error.hpp"
#include "harness/cli_process.hpp"

#include <boost/test/unit_test.hpp>

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

using namespace granseg;
namespace fs = std::filesystem;

namespace {

// The sanitizer builds (mk/sanitizers.mk) map terabytes of shadow memory: no run fits a limit.
#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
constexpr bool kSanitized = true;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer) || __has_feature(thread_sanitizer)
constexpr bool kSanitized = true;
#else
constexpr bool kSanitized = false;
#endif
#else
constexpr bool kSanitized = false;
#endif

fs::path scratch() {
    const fs::path dir = fs::temp_directory_path() / ("granseg_cli_tests_" + std::to_string(::getpid()));
    fs::create_directories(dir);
    return dir;
}

fs::path granseg_binary() { return verify::Cli::beside(boost::unit_test::framework::master_test_suite().argv[0]); }

verify::Outcome run(const std::string& arguments) { return verify::Cli(granseg_binary(), scratch()).run(arguments); }

}  // namespace

BOOST_AUTO_TEST_SUITE(cli_commands_tests)

BOOST_AUTO_TEST_CASE(closures_prints_the_state_then_the_columns_of_the_closure_sweep) {
    const verify::Outcome o = run("closures --Phi 0.5 --phi-hat 0.4 --T 1e-4");
    BOOST_TEST(o.status == kExitOk);
    std::vector<std::string> names;
    std::istringstream lines(o.out);
    for (std::string name, equals, value; lines >> name >> equals >> value;) names.push_back(name);
    const Material m = Material::glass_substitute();
    const TableRow expected =
        TableRow{{"Phi", 0.5}, {"phi_hat", 0.4}, {"T", 1e-4}}.add(closure_columns(evaluate_closures(m, 0.5, 0.4, 1e-4), &m));
    BOOST_TEST(names == expected.names(), boost::test_tools::per_element());
}

BOOST_AUTO_TEST_CASE(a_bad_command_or_option_is_one_line_and_exit_status_2) {
    for (const char* arguments : {"no-such-command", "closures --Phi 0.5 --phi-hat 1.5 --T 1e-4", "run --no-such-option"}) {
        const verify::Outcome o = run(arguments);
        BOOST_TEST(o.status == kExitBadInput, arguments);
        BOOST_TEST(verify::line_count(o.err) == 1, arguments << ": " << o.err);
    }
}

// A drum of 2000 cells across under a limit of 1 GB of address space: the run stops in one line
// that says it is out of memory and what it needed, instead of "std::bad_alloc".
BOOST_AUTO_TEST_CASE(a_run_out_of_memory_says_so_in_one_line_with_what_it_needed) {
    if (kSanitized) return;  // the sanitizers reserve far more address space than the limit
    const fs::path dir = scratch(), scene = dir / "big_drum.toml", err = dir / "big_drum.err";
    std::ofstream(scene) << "[scene]\nkind = \"tumbler-flow\"\n[drum]\ncells_per_diameter = 2000\n[run]\nt_end = 1.0\n";
    const pid_t child = fork();
    if (child == 0) {
        const rlimit limit{1000000000, 1000000000};
        setrlimit(RLIMIT_AS, &limit);
        if (!std::freopen(err.c_str(), "w", stderr) || !std::freopen("/dev/null", "w", stdout)) _exit(99);
        execl(granseg_binary().c_str(), "granseg", "run", scene.c_str(), "--output-dir", (dir / "out").c_str(),
              static_cast<char*>(nullptr));
        _exit(98);
    }
    int status = 0;
    waitpid(child, &status, 0);
    std::ifstream in(err);
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    BOOST_TEST(WIFEXITED(status));
    BOOST_TEST(WEXITSTATUS(status) == kExitFailure);
    BOOST_TEST(verify::line_count(text) == 1, text);
    BOOST_TEST(text.rfind("granseg: out of memory: the run needed more than the ", 0) == 0, text);
    BOOST_TEST(text.find("beyond the 1.00 GB this process may use (ulimit -v)") != std::string::npos, text);
    fs::remove_all(dir);
}

BOOST_AUTO_TEST_SUITE_END()
