// End-to-end check of bad input handling: runs build/granseg on bad scene files and bad
// arguments and checks, for each, exit status 2, exactly one line on stderr, nothing on stdout
// and no output file; then checks that good input works, and that `granseg riemann` prints the
// case, region, flux, waves and samples of the library's exact solution (one state per Table 1
// case and coefficient family, verification/table1/table1_states.hpp).
//
// Run: build/verification/verify_cli_errors [--data DIR]   (about a second; finds the CLI next
// to its own directory, build/granseg)
#include "harness/check_table.hpp"
#include "harness/program.hpp"
#include "riemann/riemann_sample.hpp"
#include "table1/table1_states.hpp"

#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace fs = std::filesystem;
using granseg::verify::CheckTable;
using namespace granseg;

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

/// The values of the `name = value` lines called `name`, in order.
std::vector<std::string> values_of(const std::string& out, const std::string& name) {
    std::vector<std::string> v;
    std::istringstream in(out);
    for (std::string line; std::getline(in, line);)
        if (line.rfind(name + " = ", 0) == 0) v.push_back(line.substr(name.size() + 3));
    return v;
}

std::string arg(double v) {
    char buf[40];
    std::snprintf(buf, sizeof buf, "%.17g", v);
    return buf;
}

/// `granseg riemann` against the library, one state per case (sign class) and family.
void check_riemann_agreement(CheckTable& t, const Cli& cli) {
    // The CLI prints 12 significant digits: values of size <= 2 agree to 2e-12; 1e-11 leaves room.
    constexpr double kPrintTol = 1e-11;
    constexpr int kSamples = 9;
    verify::StateSampler sampler(20200048);
    long runs = 0, failed_runs = 0, wrong_case = 0, wrong_waves = 0;
    double flux_error = 0.0, sample_error = 0.0;
    for (verify::Family family : verify::kFamilies)
        for (int group = 1; group <= verify::group_count(family); ++group) {
            std::pair<FluxSide, FluxSide> q;
            if (!verify::state_in_group(sampler, family, group, 0.05, false, q)) continue;
            const auto& [L, R] = q;
            auto S = [](double a) { return a > 0 ? 1.0 : a < 0 ? -1.0 : 0.0; };
            const Outcome o = cli.run("riemann " + arg(L.phi) + " " + arg(L.Phi) + " " + arg(R.phi) + " " + arg(R.Phi) +
                                      " --TL " + arg(L.a * L.a) + " --TR " + arg(R.a * R.a) + " --SL " + arg(S(L.a)) +
                                      " --SR " + arg(S(R.a)) + " --sample " + std::to_string(kSamples));
            ++runs;
            const auto cases = values_of(o.out, "case"), regions = values_of(o.out, "region"), fluxes = values_of(o.out, "flux");
            if (o.status != 0 || cases.size() != 1 || regions.size() != 1 || fluxes.size() != 1) {
                ++failed_runs;
                continue;
            }
            // The CLI rebuilds a = S sqrt(T) from the printed T: the library solves that state.
            const FluxSide cL{L.phi, L.Phi, S(L.a) * std::sqrt(L.a * L.a)}, cR{R.phi, R.Phi, S(R.a) * std::sqrt(R.a * R.a)};
            const RiemannSolution s = solve_riemann(cL, cR);
            const Table1Case c = classify_table1(cL, cR);
            wrong_case += std::stoi(cases[0]) != c.number || regions[0] != std::string(1, c.region);
            flux_error = std::max(flux_error, std::fabs(std::stod(fluxes[0]) - s.flux));
            wrong_waves += values_of(o.out, "wave").size() != s.waves.size();
            for (const std::string& line : values_of(o.out, "sample")) {
                const double xi = std::stod(line), phi = std::stod(line.substr(line.find(' ') + 1));
                sample_error = std::max(sample_error, std::fabs(phi - sample_phi(s, xi)));
            }
        }
    t.note("  granseg riemann on " + std::to_string(runs) + " states (one per case or sign class and family)");
    t.count("riemann: runs failing or missing case/region/flux", failed_runs, 0);
    t.count("riemann: states whose case or region differs from the library", wrong_case, 0);
    t.at_most("riemann: |flux printed - exact solution|, max", flux_error, kPrintTol);
    t.count("riemann: states whose wave lines differ in number", wrong_waves, 0);
    t.at_most("riemann: |phi(xi) printed - sample_phi|, max", sample_error, kPrintTol);
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
    CheckTable t("CLI input validation (granseg run, closures, riemann, direction) and riemann output");

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
    // Segregation column (issue 4): the acceptance cases and the grid-wide conditions.
    const std::string column = "[scene]\nkind = \"segregation1d\"\n[output]\ndir = \"" + out.string() +
                               "\"\n[grid]\ncells = 50\n[time]\nend = 0.75\n";
    const std::string profiles = "Phi = \"0.62 - 0.08*cos(_pi*z)^2\"\nT = \"0.2 + 0.8*z\"\n";
    const std::vector<std::pair<std::string, std::string>> columns = {
        {"segregation1d, phi = Phi + 0.01", column + "[initial]\n" + profiles + "phi = \"Phi + 0.01\"\n"},
        {"segregation1d, cfl = 1.5", column + "cfl = 1.5\n[initial]\n" + profiles + "phi = \"Phi/2\"\n"},
        {"segregation1d, T < 0 on part of the grid",
         column + "[initial]\nPhi = 0.6\nT = \"z - 0.5\"\nphi = \"Phi/2\"\n"},
        {"segregation1d, Phi >= 1 on part of the grid",
         column + "[initial]\nPhi = \"0.5 + z\"\nT = 1\nphi = 0\n"},
        {"segregation1d, classic scheme, T < 0 at a face only",
         column + "[segregation]\nscheme = \"classic-godunov\"\n[initial]\nPhi = 0.6\nT = \"abs(z - 0.5) - 0.001\"\nphi = 0\n"},
        {"segregation1d, unknown scheme",
         column + "[segregation]\nscheme = \"upwind\"\n[initial]\n" + profiles + "phi = \"Phi/2\"\n"},
    };
    // Kinematic tumbler (issue 5): acceptance cases and the conditions between keys.
    const std::string tumbler = "[scene]\nkind = \"tumbler-kinematic\"\n[output]\ndir = \"" + out.string() + "\"\n";
    const std::vector<std::pair<std::string, std::string>> tumblers = {
        {"tumbler-kinematic, fill_fraction = 1.2", tumbler + "[drum]\nfill_fraction = 1.2\n[time]\nend = 1\n"},
        {"tumbler-kinematic, negative end time", tumbler + "[time]\nend = -1\n"},
        {"tumbler-kinematic, unknown key", tumbler + "[time]\nend = 1\n[drum]\nrotation_speed = 0.1\n"},
        {"tumbler-kinematic, layer thicker than the bed allows", tumbler + "[time]\nend = 1\n[drum]\nlayer_thickness = 0.05\n"},
        {"tumbler-kinematic, layer thinner than a cell", tumbler + "[time]\nend = 1\n[drum]\ncells_per_diameter = 10\n"},
        {"tumbler-kinematic, phi_hat > 1 on part of the bed", tumbler + "[time]\nend = 1\n[initial]\nphi_hat = \"x > 0.02 ? 1.5 : 0.5\"\n"},
        {"tumbler-kinematic, classic scheme", tumbler + "[time]\nend = 1\n[segregation]\nscheme = \"classic-upwind\"\n"},
        {"tumbler-kinematic, rotation_rate = 0", tumbler + "[time]\nend = 1\n[drum]\nrotation_rate = 0\n"},
        {"tumbler-kinematic, unknown bulk scheme", tumbler + "[time]\nend = 1\n[bulk]\nscheme = \"upwind\"\n"},
    };
    // The coupled drum (issue 11, check g).
    const std::string coupled = "[scene]\nkind = \"tumbler\"\n[output]\ndir = \"" + out.string() + "\"\n[run]\nt_end = 1\nangle_from = 0\n";
    const std::vector<std::pair<std::string, std::string>> coupled_drums = {
        {"tumbler, phi_hat > 1 on part of the bed", coupled + "[initial]\nphi_hat = \"x > 0.02 ? 1.5 : 0.5\"\n"},
        {"tumbler, phi_hat < 0 at the bottom", coupled + "[initial]\nphi_hat = \"z < -0.04 ? -0.1 : 0.5\"\n"},
        {"tumbler, S < 0", coupled + "[segregation]\nS = -1\n"},
        {"tumbler, unknown key", coupled + "[coupling]\nfeedback = true\n"},
        {"tumbler, [flow] phi_hat (the mixture comes from [initial])", coupled + "[flow]\nphi_hat = 0.5\n"},
        {"tumbler, cells too coarse for the flowing layer", coupled + "[drum]\ncells_per_diameter = 16\n"},
        {"tumbler, classic scheme", coupled + "[segregation]\nscheme = \"classic-godunov\"\n"},
        {"tumbler, Phi_min = 1", coupled + "[segregation]\nPhi_min = 1\n"},
    };
    for (const auto& [label, text] : coupled_drums) {
        const fs::path file = work / "scene.toml";
        std::ofstream(file) << text;
        expect_rejected(t, cli, "run, " + label, "run '" + file.string() + "'", out);
    }
    for (const auto& [label, text] : tumblers) {
        const fs::path file = work / "scene.toml";
        std::ofstream(file) << text;
        expect_rejected(t, cli, "run, " + label, "run '" + file.string() + "'", out);
    }
    for (const auto& [label, text] : columns) {
        const fs::path file = work / "scene.toml";
        std::ofstream(file) << text;
        expect_rejected(t, cli, "run, " + label, "run '" + file.string() + "'", out);
    }
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
    const std::vector<std::pair<std::string, std::string>> bad_riemann = {
        {"phi_L > Phi_L", "0.6 0.5 0.3 0.8"},         {"Phi_R = 1", "0.1 0.5 0.3 1"},
        {"Phi_L = 0", "0 0 0.3 0.8"},                 {"negative phi_R", "0.1 0.5 -0.1 0.8"},
        {"negative --TR", "0.1 0.5 0.3 0.8 --TR -1"}, {"non-numeric PHI_R", "0.1 0.5 0.3 abc"},
        {"missing PHI_R", "0.1 0.5 0.3"},             {"--sample 0", "0.1 0.5 0.3 0.8 --sample 0"},
    };
    for (const auto& [label, arguments] : bad_riemann) expect_rejected(t, cli, "riemann, " + label, "riemann " + arguments, out);
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
    const fs::path good_column = work / "good_column.toml";
    std::ofstream(good_column) << column << "[initial]\n" << profiles << "phi = \"Phi/2\"\n";
    const Outcome column_ran = cli.run("run '" + good_column.string() + "'");
    t.count("run, valid segregation1d scene: exit status", column_ran.status, 0);
    std::ifstream profile(out / "profile.dat");
    std::string first_line;
    std::getline(profile, first_line);
    t.count("run, valid segregation1d scene: first line is '# z Phi T phi'", first_line == "# z Phi T phi", 1);
    const fs::path good_tumbler = work / "good_tumbler.toml";
    std::ofstream(good_tumbler) << tumbler << "[drum]\ncells_per_diameter = 20\nlayer_thickness = 0.01\n[time]\nend = 0.5\n";
    const Outcome tumbler_ran = cli.run("run '" + good_tumbler.string() + "'");
    t.count("run, valid tumbler-kinematic scene: exit status", tumbler_ran.status, 0);
    t.count("run, valid tumbler-kinematic scene: tumbler_metrics.dat written", fs::exists(out / "tumbler_metrics.dat"), 1);
    const fs::path good_coupled = work / "good_coupled.toml";
    std::ofstream(good_coupled) << coupled.substr(0, coupled.find("[run]")) << "[drum]\ncells_per_diameter = 26\n[run]\nt_end = 0.02\nangle_from = 0\nframes = 2\n";
    const Outcome coupled_ran = cli.run("run '" + good_coupled.string() + "'");
    t.count("run, valid tumbler scene: exit status", coupled_ran.status, 0);
    long coupled_files = 0;
    for (const char* name : {"history.dat", "summary.dat", "initial_lab.dat", "fields_lab.dat", "frames/frame_002.dat", "vtk/tumbler_0000.vtk"})
        coupled_files += fs::exists(out / name);
    t.count("run, valid tumbler scene: history, summary, fields, frames, VTK written", coupled_files, 6);
    const Outcome closures = cli.run("closures --Phi 0.59 --phi-hat 0.4 --T 1e-4");
    t.count("closures, valid state: exit status", closures.status, 0);
    long missing = 0;
    for (const char* name : {"g", "Phi_rcp", "Phi_co", "p_k", "p_y", "p", "eta", "lambda", "eps"})
        if (closures.out.find("\n" + std::string(name) + " = ") == std::string::npos) ++missing;
    t.count("closures, valid state: required quantities missing", missing, 0);
    check_riemann_agreement(t, cli);
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
