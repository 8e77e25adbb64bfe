#include "harness/program.hpp"

#include "core/error.hpp"
#include "harness/table_provenance.hpp"

#include <time.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <exception>
#include <fstream>
#include <iostream>
#include <sstream>

namespace granseg::verify {

namespace {

const char* program_name = "verification program";

/// The library's errors that escape a program end it like the CLI: the one-line message and
/// exit status 2 (InputError), 3 (InvariantError) or 128 + the signal (Interrupted); anything
/// else aborts as usual.
[[noreturn]] void on_uncaught_exception() {
    try {
        if (const std::exception_ptr error = std::current_exception()) std::rethrow_exception(error);
    } catch (const InputError& e) {
        std::cerr << program_name << ": " << e.what() << '\n';
        std::_Exit(kExitBadInput);
    } catch (const InvariantError& e) {
        std::cerr << program_name << ": stopped, invariant broken: " << e.what() << '\n';
        std::_Exit(kExitInvariant);
    } catch (const Interrupted& e) {
        std::cerr << program_name << ": " << e.what() << '\n';
        std::_Exit(128 + e.signal());
    } catch (...) {
    }
    std::abort();
}

}  // namespace

ProgramOptions parse_program_options(int argc, char** argv) {
    if (argc > 0) program_name = argv[0];
    std::set_terminate(on_uncaught_exception);
    remember_command_line(argc, argv);  // for the tables it writes (table_provenance.hpp)
    ProgramOptions options;
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        if (arg == "--data" && i + 1 < argc) {
            options.data_dir = argv[++i];
        } else {
            std::cerr << argv[0] << ": unknown argument \"" << arg << "\" (allowed: --data DIR)\n";
            std::exit(kExitBadInput);
        }
    }
    return options;
}

void write_data(const ProgramOptions& options, const std::string& name, const DataTable& table) {
    write_file_atomically(options.data_dir + "/" + name, table.str());
}

double median(std::vector<double> values) {
    std::sort(values.begin(), values.end());
    return values[values.size() / 2];
}

double cpu_seconds() {
    timespec ts{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
    return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

void add_timed(Timing& t, const std::function<void()>& work) {
    const double cpu = cpu_seconds();
    const auto wall = std::chrono::steady_clock::now();
    work();
    t.wall += std::chrono::duration<double>(std::chrono::steady_clock::now() - wall).count();
    t.cpu += cpu_seconds() - cpu;
}

std::string load_average() {
    std::ifstream in("/proc/loadavg");
    std::string one, five, fifteen;
    in >> one >> five >> fifteen;
    return one + " " + five + " " + fifteen;
}

std::map<std::string, double> last_row_of(const std::string& text) {
    std::istringstream in(text);
    std::string line, header, last;
    std::getline(in, header);
    while (std::getline(in, line))
        if (!line.empty() && line[0] != '#') last = line;
    std::istringstream names(header.substr(std::min<std::size_t>(1, header.size()))), values(last);
    std::map<std::string, double> row;
    std::string name, value;
    while (names >> name && values >> value) row[name] = std::strtod(value.c_str(), nullptr);  // reads nan and inf too
    return row;
}

std::map<std::string, double> last_row(const std::string& path) {
    std::ifstream in(path);
    std::ostringstream text;
    text << in.rdbuf();
    return last_row_of(text.str());
}

std::vector<std::vector<double>> read_rows(const std::string& path) {
    std::ifstream in(path);
    std::vector<std::vector<double>> out;
    for (std::string line; std::getline(in, line);) {
        if (line.empty() || line[0] == '#') continue;
        std::istringstream row(line);
        std::vector<double> v;
        for (double x; row >> x;) v.push_back(x);
        out.push_back(v);
    }
    return out;
}

}  // namespace granseg::verify
