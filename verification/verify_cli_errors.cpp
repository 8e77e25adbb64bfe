// End-to-end check of bad input handling: runs build/granseg on bad scene files and bad
// arguments and checks, for each, exit status 2, exactly one line on stderr, nothing on stdout
// and no output file; then checks that good input works.
//
// Run: build/verification/verify_cli_errors [--data DIR]   (about a second; finds the CLI next
// to its own directory, build/granseg)
#include "harness/check_table.hpp"
#include "harness/program.hpp"

#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace fs = std::filesystem;
using granseg::verify::CheckTable;

namespace {

struct Outcome {
    int status = -1;
    std::string out, err;
};

std::string read(const fs::path& p) {
    std::ifstream in(p);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

long lines(const std::string& s) {
    long n = 0;
    for (char c : s) n += c == '\n';
    return n;
}

long files_below(const fs::path& dir) {
    if (!fs::exists(dir)) return 0;
    long n = 0;
    for (const auto& e : fs::recursive_directory_iterator(dir)) n += e.is_regular_file();
    return n;
}

class Cli {
public:
    Cli(fs::path binary, fs::path work) : binary_(std::move(binary)), work_(std::move(work)) {}

    Outcome run(const std::string& arguments) const {
        const fs::path out = work_ / "stdout.txt", err = work_ / "stderr.txt";
        const std::string command = "'" + binary_.string() + "' " + arguments + " > '" + out.string() +
                                    "' 2> '" + err.string() + "' < /dev/null";
        const int raw = std::system(command.c_str());
        Outcome o;
        o.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
        o.out = read(out);
        o.err = read(err);
        return o;
    }

private:
    fs::path binary_, work_;
};

/// A bad input must give exit status 2, one stderr line, empty stdout, and write no file.
void expect_rejected(CheckTable& t, const Cli& cli, const std::string& label, const std::string& arguments,
                     const fs::path& output_dir) {
    const Outcome o = cli.run(arguments);
    t.count(label + ": exit status", o.status, 2);
    t.count(label + ": stderr lines + stdout lines", lines(o.err) + lines(o.out), 1);
    t.count(label + ": files written", files_below(output_dir), 0);
    t.note("  stderr: " + o.err.substr(0, o.err.find('\n')));
}

}  // namespace

int main(int argc, char** argv) {
    const auto options = granseg::verify::parse_program_options(argc, argv);
    (void)options;
    const fs::path cli_path = fs::absolute(fs::path(argv[0])).parent_path().parent_path() / "granseg";
    const fs::path work = fs::temp_directory_path() / ("granseg_verify_cli_" + std::to_string(::getpid()));
    fs::create_directories(work);
    const fs::path out = work / "out";
    const Cli cli(cli_path, work);
    CheckTable t("CLI input validation (granseg run, granseg closures, granseg direction)");

    const std::string head = "[scene]\nkind = \"closure-sweep\"\n[output]\ndir = \"" + out.string() + "\"\n";
    const std::vector<std::pair<std::string, std::string>> scenes = {
        {"unknown key", head + "[sweep]\nPhi_max = 0.6\npionts = 10\n"},
        {"string where a number belongs", head + "[sweep]\nPhi_max = \"0.6\"\n"},
        {"unknown scene kind", "[scene]\nkind = \"tumbler-magic\"\n[output]\ndir = \"" + out.string() + "\"\n"},
        {"out-of-range value (Phi_max >= Phi_rcp)", head + "[sweep]\nPhi_max = 0.7\n"},
        {"negative T from an expression", head + "[sweep]\nPhi_max = 0.6\nT = \"0.3 - Phi\"\n"},
        {"malformed expression", head + "[sweep]\nPhi_max = 0.6\nT = \"1e-4 * (Phi\"\n"},
        {"unknown section", head + "[sweep]\nPhi_max = 0.6\n[materail]\neta0 = 1e-4\n"},
        {"TOML syntax error", head + "[sweep]\nPhi_max = 0.6 0.7\n"},
    };
    for (const auto& [label, text] : scenes) {
        const fs::path file = work / "scene.toml";
        std::ofstream(file) << text;
        expect_rejected(t, cli, "run, " + label, "run '" + file.string() + "'", out);
    }
    expect_rejected(t, cli, "run, missing scene file", "run '" + (work / "absent.toml").string() + "'", out);
    expect_rejected(t, cli, "closures, non-numeric --Phi", "closures --Phi abc --phi-hat 0.4 --T 1e-4", out);
    expect_rejected(t, cli, "closures, --Phi >= Phi_rcp", "closures --Phi 0.7 --phi-hat 0.4 --T 1e-4", out);
    expect_rejected(t, cli, "closures, negative --T", "closures --Phi 0.5 --phi-hat 0.4 --T -1", out);
    expect_rejected(t, cli, "closures, missing --T", "closures --Phi 0.5 --phi-hat 0.4", out);
    expect_rejected(t, cli, "unknown command", "segregate", out);
    const std::string shear = "--grad '0 0 2.385 0 0 0 0 0 0'";
    expect_rejected(t, cli, "direction, non-numeric --grad", "direction --grad '0 0 x 0 0 0 0 0 0' --u '1 0 0'", out);
    expect_rejected(t, cli, "direction, 8 numbers in --grad", "direction --grad '0 0 1 0 0 0 0 0' --u '1 0 0'", out);
    expect_rejected(t, cli, "direction, 10 numbers in --grad", "direction --grad '0 0 1 0 0 0 0 0 0 0' --u '1 0 0'", out);
    expect_rejected(t, cli, "direction, 2 numbers in --u", "direction " + shear + " --u '1 0'", out);
    expect_rejected(t, cli, "direction, nan in --u", "direction " + shear + " --u '1 nan 0'", out);
    expect_rejected(t, cli, "direction, missing --u", "direction " + shear, out);

    // Good input: the scene writes its table, closures prints every quantity of the issue.
    const fs::path good = work / "good.toml";
    std::ofstream(good) << head << "[sweep]\nPhi_max = 0.6\npoints = 5\n";
    const Outcome ran = cli.run("run '" + good.string() + "'");
    t.count("run, valid scene: exit status", ran.status, 0);
    t.count("run, valid scene: files written", files_below(out), 1);
    const Outcome closures = cli.run("closures --Phi 0.59 --phi-hat 0.4 --T 1e-4");
    t.count("closures, valid state: exit status", closures.status, 0);
    long missing = 0;
    for (const char* name : {"g", "Phi_rcp", "Phi_co", "p_k", "p_y", "p", "eta", "lambda", "eps"})
        if (closures.out.find("\n" + std::string(name) + " = ") == std::string::npos) ++missing;
    t.count("closures, valid state: required quantities missing", missing, 0);
    const Outcome direction = cli.run("direction " + shear + " --u '-1.3 0 0'");
    t.count("direction, simple shear: exit status", direction.status, 0);
    t.count("direction, simple shear: 'status = ok' and 'd_s = 0 0 1' lines",
            (direction.out.find("status = ok\n") != std::string::npos) + (direction.out.find("\nd_s = 0 0 1\n") != std::string::npos), 2);
    t.count("direction, simple shear: 'gamma_dot = 2.385' line", direction.out.find("\ngamma_dot = 2.385\n") != std::string::npos, 1);
    const Outcome rigid = cli.run("direction --grad '0 -1 0 1 0 0 0 0 0' --u '1 0 0'");
    t.count("direction, rigid rotation: exit status", rigid.status, 0);
    t.count("direction, rigid rotation: 'status = no_shear' line", rigid.out.find("status = no_shear\n") == 0, 1);

    fs::remove_all(work);
    return t.finish();
}
