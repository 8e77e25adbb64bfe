// End-to-end check of bad input handling: runs build/granseg on bad scene files and bad
// arguments and checks, for each, exit status 2, exactly one line on stderr (for a scene file:
// starting with the file and naming the section and key), nothing on stdout and no output file;
// then checks that good input works, and that `granseg riemann` prints the case, region, flux,
// waves and samples of the library's exact solution (one state per Table 1 case and coefficient
// family, verification/table1/table1_states.hpp). The command lines are one table, cli_cases():
// a new case is one row.
//
// Run: build/verification/verify_cli_errors [--data DIR]   (about a second; finds the CLI next
// to its own directory, build/granseg)
#include "harness/check_table.hpp"
#include "harness/cli_process.hpp"
#include "harness/program.hpp"
#include "harness/same_outputs.hpp"
#include "riemann/riemann_sample.hpp"
#include "table1/table1_states.hpp"

#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>
#include <string>
#include <vector>

namespace fs = std::filesystem;
using granseg::verify::CheckTable;
using granseg::verify::Cli;
using granseg::verify::files_below;
using granseg::verify::line_count;
using granseg::verify::Outcome;
using namespace granseg;

namespace {

/// A bad input must give exit status 2, one stderr line, empty stdout, and write no file.
void expect_rejected(CheckTable& t, const std::string& label, const Outcome& o, const fs::path& output_dir) {
    t.count(label + ": exit status", o.status, 2);
    t.count(label + ": stderr lines + stdout lines", line_count(o.err) + line_count(o.out), 1);
    t.count(label + ": files written", files_below(output_dir.string()), 0);
    t.note("  stderr: " + o.err.substr(0, o.err.find('\n')));
}

/// Checks the outcome of a good command line (its output directory is `out`).
using Check = std::function<void(CheckTable& t, const std::string& label, const Outcome& o, const fs::path& out)>;

/// One command line and what it must do.
struct Case {
    std::string label;
    std::string arguments;  // the words after `granseg`; SCENE stands for the path of the scene file
    std::string scene;      // the text of that scene file (empty: the case has none)
    Check check;            // empty: the input must be rejected (expect_rejected)
    std::string names;      // a rejection's message must start with "SCENE: " and this ("[section] key:")
};

Case bad_scene(const std::string& label, const std::string& names, const std::string& scene) {
    return {"run, " + label, "run SCENE", scene, {}, names};
}
Case bad_arguments(const std::string& label, const std::string& arguments) { return {label, arguments, "", {}, ""}; }

/// A good run: exit status 0 and what `also` checks.
Case good(const std::string& label, const std::string& arguments, const std::string& scene, const Check& also) {
    return {label, arguments, scene,
            [also](CheckTable& t, const std::string& l, const Outcome& o, const fs::path& out) {
                t.count(l + ": exit status", o.status, 0);
                also(t, l, o, out);
            },
            ""};
}

/// Passes if every one of `lines` appears as a whole line of the output.
Check prints(const std::vector<std::string>& wanted) {
    return [wanted](CheckTable& t, const std::string& label, const Outcome& o, const fs::path&) {
        long missing = 0;
        for (const std::string& w : wanted) missing += ("\n" + o.out).find("\n" + w + "\n") == std::string::npos;
        t.count(label + ": of " + std::to_string(wanted.size()) + " expected lines, missing", missing, 0);
    };
}

/// The table of command lines: bad scene files and arguments of every command, then good ones.
std::vector<Case> cli_cases(const fs::path& out) {
    const std::string dir = "[output]\ndir = \"" + out.string() + "\"\n";
    const std::string sweep = "[scene]\nkind = \"closure-sweep\"\n" + dir;
    // Segregation column: the acceptance cases and the grid-wide conditions.
    const std::string column = "[scene]\nkind = \"segregation1d\"\n" + dir + "[grid]\ncells = 50\n[time]\nend = 0.75\n";
    const std::string profiles = "Phi = \"0.62 - 0.08*cos(_pi*z)^2\"\nT = \"0.2 + 0.8*z\"\n";
    // Kinematic tumbler: acceptance cases and the conditions between keys.
    const std::string tumbler = "[scene]\nkind = \"tumbler-kinematic\"\n" + dir;
    // The coupled drum.
    const std::string coupled = "[scene]\nkind = \"tumbler\"\n" + dir + "[run]\nt_end = 1\nangle_from = 0\n";
    const std::string shear = "--grad '0 0 2.385 0 0 0 0 0 0'";
    const std::string closures = "closures --Phi 0.59 --phi-hat 0.4 --T 1e-4";
    return {
        bad_scene("tumbler-kinematic, fill_fraction = 1.2",
                  "[drum] fill_fraction:", tumbler + "[drum]\nfill_fraction = 1.2\n[time]\nend = 1\n"),
        bad_scene("tumbler-kinematic, negative end time", "[time] end:", tumbler + "[time]\nend = -1\n"),
        bad_scene("tumbler-kinematic, unknown key",
                  "[drum] rotation_speed:", tumbler + "[time]\nend = 1\n[drum]\nrotation_speed = 0.1\n"),
        bad_scene("tumbler-kinematic, layer thicker than the bed allows",
                  "[drum] layer_thickness:", tumbler + "[time]\nend = 1\n[drum]\nlayer_thickness = 0.05\n"),
        bad_scene("tumbler-kinematic, layer thinner than a cell",
                  "[drum] cells_per_diameter:", tumbler + "[time]\nend = 1\n[drum]\ncells_per_diameter = 10\n"),
        bad_scene("tumbler-kinematic, phi_hat > 1 on part of the bed",
                  "[initial] phi_hat:", tumbler + "[time]\nend = 1\n[initial]\nphi_hat = \"x > 0.02 ? 1.5 : 0.5\"\n"),
        bad_scene("tumbler-kinematic, classic scheme",
                  "[segregation] scheme:", tumbler + "[time]\nend = 1\n[segregation]\nscheme = \"classic-upwind\"\n"),
        bad_scene("tumbler-kinematic, Rusanov scheme (unbounded row)",
                  "[segregation] scheme:", tumbler + "[time]\nend = 1\n[segregation]\nscheme = \"rusanov\"\n"),
        bad_scene("tumbler-kinematic, rotation_rate = 0",
                  "[drum] rotation_rate:", tumbler + "[time]\nend = 1\n[drum]\nrotation_rate = 0\n"),
        bad_scene("tumbler-kinematic, unknown bulk scheme",
                  "[bulk] scheme:", tumbler + "[time]\nend = 1\n[bulk]\nscheme = \"upwind\"\n"),
        bad_scene("tumbler, phi_hat > 1 on part of the bed",
                  "[initial] phi_hat:", coupled + "[initial]\nphi_hat = \"x > 0.02 ? 1.5 : 0.5\"\n"),
        bad_scene("tumbler, phi_hat < 0 at the bottom",
                  "[initial] phi_hat:", coupled + "[initial]\nphi_hat = \"z < -0.04 ? -0.1 : 0.5\"\n"),
        bad_scene("tumbler, a tracer share above 1 in the core",
                  "[initial] tracer:", coupled + "[initial]\ntracer = \"sqrt(x^2 + z^2) < 0.01 ? 2 : 0\"\n"),
        bad_scene("tumbler, S < 0", "[segregation] S:", coupled + "[segregation]\nS = -1\n"),
        bad_scene("tumbler, unknown key", "[coupling] feedback:", coupled + "[coupling]\nfeedback = true\n"),
        bad_scene("tumbler, a fixed mixture with packing feedback",
                  "[coupling] mixture:", coupled + "[coupling]\nmixture = 0.5\n"),
        bad_scene("tumbler, mixture > 1",
                  "[coupling] mixture:", coupled + "[coupling]\npacking_feedback = false\nmixture = 1.5\n"),
        bad_scene("tumbler, [flow] phi_hat (the mixture comes from [initial])",
                  "[flow] phi_hat:", coupled + "[flow]\nphi_hat = 0.5\n"),
        bad_scene("tumbler, unknown viscosity solve", "[flow] viscosity:", coupled + "[flow]\nviscosity = \"diagonal\"\n"),
        bad_scene("tumbler, unknown transport", "[flow] transport:", coupled + "[flow]\ntransport = \"weno\"\n"),
        bad_scene("tumbler, muscl transport with the explicit step",
                  "[flow] transport:", coupled + "[flow]\ntime_stepping = \"explicit\"\ntransport = \"muscl\"\n"),
        bad_scene("tumbler, unknown limiter", "[flow] limiter:", coupled + "[flow]\nlimiter = \"superbee\"\n"),
        bad_scene("tumbler, cells too coarse for the flowing layer",
                  "[drum] cells_per_diameter:", coupled + "[drum]\ncells_per_diameter = 16\n"),
        bad_scene("tumbler, unknown drum shape", "[drum] shape:", coupled + "[drum]\nshape = \"ellipse\"\n"),
        bad_scene("tumbler, a polygon of 2 sides", "[drum] sides:", coupled + "[drum]\nshape = \"polygon\"\nsides = 2\n"),
        bad_scene("tumbler, sides for a circle", "[drum] sides:", coupled + "[drum]\nsides = 4\n"),
        bad_scene("tumbler-flow, triangle with too few cells across its inscribed circle", "[drum] cells_per_diameter:",
                  "[scene]\nkind = \"tumbler-flow\"\n" + dir +
                      "[run]\nt_end = 1\nangle_from = 0\n[drum]\nshape = \"polygon\"\nsides = 3\ncells_per_diameter = 12\n"),
        bad_scene("tumbler, square filled to its top",
                  "[drum] fill_height:", coupled + "[drum]\nshape = \"polygon\"\nsides = 4\nfill_height = 0.0707\n"),
        bad_scene("tumbler, a bed less than two cells deep",
                  "[drum] fill_height:", coupled + "[drum]\ncells_per_diameter = 26\nfill_height = 0.005\n"),
        bad_scene("tumbler, classic scheme", "[segregation] scheme:", coupled + "[segregation]\nscheme = \"classic-godunov\"\n"),
        bad_scene("tumbler, Phi_min = 1", "[segregation] Phi_min:", coupled + "[segregation]\nPhi_min = 1\n"),
        bad_scene("tumbler, a negative shear-rate threshold",
                  "[segregation] diagnostic_min_shear_rate:", coupled + "[segregation]\ndiagnostic_min_shear_rate = -1\n"),
        bad_scene("tumbler, no gravity (no bed to start from)", "[drum] gravity:", coupled + "[drum]\ngravity = 0\n"),
        bad_scene("tumbler, T0 = 0 (no yield pressure holds the bed)", "[material] T0:", coupled + "[material]\nT0 = 0\n"),
        bad_scene("bed-at-rest, T0 = 0 under gravity", "[material] T0:",
                  "[scene]\nkind = \"bed-at-rest\"\n" + dir +
                      "[grid]\nnz = 8\nheight = 0.02\n[bed]\nPhi = 0.6\n[run]\nt_end = 0.1\n[material]\nT0 = 0\n"),
        bad_scene("segregation1d, phi = Phi + 0.01",
                  "[initial] phi:", column + "[initial]\n" + profiles + "phi = \"Phi + 0.01\"\n"),
        bad_scene("segregation1d, cfl = 1.5", "[time] cfl:", column + "cfl = 1.5\n[initial]\n" + profiles + "phi = \"Phi/2\"\n"),
        bad_scene("segregation1d, T < 0 on part of the grid",
                  "[initial] T:", column + "[initial]\nPhi = 0.6\nT = \"z - 0.5\"\nphi = \"Phi/2\"\n"),
        bad_scene("segregation1d, Phi >= 1 on part of the grid",
                  "[initial] Phi:", column + "[initial]\nPhi = \"0.5 + z\"\nT = 1\nphi = 0\n"),
        bad_scene(
            "segregation1d, classic scheme, T < 0 at a face only", "[initial] T:",
            column +
                "[segregation]\nscheme = \"classic-godunov\"\n[initial]\nPhi = 0.6\nT = \"abs(z - 0.5) - 0.001\"\nphi = 0\n"),
        bad_scene("segregation1d, unknown scheme", "[segregation] scheme:",
                  column + "[segregation]\nscheme = \"upwind\"\n[initial]\n" + profiles + "phi = \"Phi/2\"\n"),
        bad_scene("unknown key", "[sweep] pionts:", sweep + "[sweep]\nPhi_max = 0.6\npionts = 10\n"),
        bad_scene("string where a number belongs", "[sweep] Phi_max:", sweep + "[sweep]\nPhi_max = \"0.6\"\n"),
        bad_scene("unknown scene kind", "[scene] kind:", "[scene]\nkind = \"tumbler-magic\"\n" + dir),
        bad_scene("out-of-range value (Phi_max >= Phi_rcp)", "[sweep] Phi_max:", sweep + "[sweep]\nPhi_max = 0.7\n"),
        bad_scene("negative T from an expression", "[sweep] T:", sweep + "[sweep]\nPhi_max = 0.6\nT = \"0.3 - Phi\"\n"),
        bad_scene("malformed expression", "[sweep] T:", sweep + "[sweep]\nPhi_max = 0.6\nT = \"1e-4 * (Phi\"\n"),
        bad_scene("unknown section", "[materail]:", sweep + "[sweep]\nPhi_max = 0.6\n[materail]\neta0 = 1e-4\n"),
        bad_scene("unknown compressibility law",
                  "[material] g_law:", sweep + "[sweep]\nPhi_max = 0.6\n[material]\ng_law = \"carnahan\"\n"),
        bad_scene("TOML syntax error", "TOML syntax error", sweep + "[sweep]\nPhi_max = 0.6 0.7\n"),
        bad_arguments("run, missing scene file", "run '" + (out / "absent.toml").string() + "'"),
        {"run, output directory that cannot be created",
         "run SCENE --output-dir /proc/granseg-out",
         sweep + "[sweep]\nPhi_max = 0.6\n",
         {},
         ""},
        bad_arguments("closures, non-numeric --Phi", "closures --Phi abc --phi-hat 0.4 --T 1e-4"),
        bad_arguments("closures, --Phi >= Phi_rcp", "closures --Phi 0.7 --phi-hat 0.4 --T 1e-4"),
        bad_arguments("closures, negative --T", "closures --Phi 0.5 --phi-hat 0.4 --T -1"),
        bad_arguments("closures, missing --T", "closures --Phi 0.5 --phi-hat 0.4"),
        {"closures, unknown g_law in --scene",
         closures + " --scene SCENE",
         "[material]\ng_law = \"carnahan\"\n",
         {},
         "[material] g_law:"},
        bad_arguments("unknown command", "segregate"),
        bad_arguments("riemann, phi_L > Phi_L", "riemann 0.6 0.5 0.3 0.8"),
        bad_arguments("riemann, Phi_R = 1", "riemann 0.1 0.5 0.3 1"),
        bad_arguments("riemann, Phi_L = 0", "riemann 0 0 0.3 0.8"),
        bad_arguments("riemann, negative phi_R", "riemann 0.1 0.5 -0.1 0.8"),
        bad_arguments("riemann, negative --TR", "riemann 0.1 0.5 0.3 0.8 --TR -1"),
        bad_arguments("riemann, non-numeric PHI_R", "riemann 0.1 0.5 0.3 abc"),
        bad_arguments("riemann, missing PHI_R", "riemann 0.1 0.5 0.3"),
        bad_arguments("riemann, --sample 0", "riemann 0.1 0.5 0.3 0.8 --sample 0"),
        bad_arguments("direction, non-numeric --grad", "direction --grad '0 0 x 0 0 0 0 0 0' --u '1 0 0'"),
        bad_arguments("direction, 8 numbers in --grad", "direction --grad '0 0 1 0 0 0 0 0' --u '1 0 0'"),
        bad_arguments("direction, 10 numbers in --grad", "direction --grad '0 0 1 0 0 0 0 0 0 0' --u '1 0 0'"),
        bad_arguments("direction, 2 numbers in --u", "direction " + shear + " --u '1 0'"),
        bad_arguments("direction, nan in --u", "direction " + shear + " --u '1 nan 0'"),
        bad_arguments("direction, missing --u", "direction " + shear),
        // Good input: each scene writes its files, each command prints what its page documents.
        good("run, valid closure-sweep scene", "run SCENE", sweep + "[sweep]\nPhi_max = 0.6\npoints = 5\n",
             [](CheckTable& t, const std::string& l, const Outcome&, const fs::path& o) {
                 t.count(l + ": files written", files_below(o), 1);
             }),
        good("run, valid segregation1d scene", "run SCENE", column + "[initial]\n" + profiles + "phi = \"Phi/2\"\n",
             [](CheckTable& t, const std::string& l, const Outcome&, const fs::path& o) {
                 std::ifstream profile(o / "profile.dat");
                 std::string first_line;
                 std::getline(profile, first_line);
                 t.count(l + ": first line is '# z Phi T phi'", first_line == "# z Phi T phi", 1);
             }),
        good("run, valid tumbler-kinematic scene", "run SCENE",
             tumbler + "[drum]\ncells_per_diameter = 20\nlayer_thickness = 0.01\n[time]\nend = 0.5\n",
             [](CheckTable& t, const std::string& l, const Outcome&, const fs::path& o) {
                 t.count(l + ": tumbler_metrics.dat written", fs::exists(o / "tumbler_metrics.dat"), 1);
             }),
        good("run, valid tumbler scene", "run SCENE",
             "[scene]\nkind = \"tumbler\"\n" + dir +
                 "[drum]\ncells_per_diameter = 26\n[run]\nt_end = 0.02\nangle_from = 0\nframes = 2\n",
             [](CheckTable& t, const std::string& l, const Outcome&, const fs::path& o) {
                 long written = 0;
                 for (const char* name : {"history.dat", "summary.dat", "initial_lab.dat", "fields_lab.dat",
                                          "frames/frame_002.dat", "vtk/tumbler_0000.vtk"})
                     written += fs::exists(o / name);
                 t.count(l + ": history, summary, fields, frames, VTK written", written, 6);
             }),
        good("closures, valid state", closures, "",
             [](CheckTable& t, const std::string& l, const Outcome& o, const fs::path&) {
                 long missing = 0;
                 for (const char* name : {"g", "Phi_rcp", "Phi_co", "p_k", "p_y", "p", "eta", "lambda", "eps"})
                     missing += o.out.find("\n" + std::string(name) + " = ") == std::string::npos;
                 t.count(l + ": required quantities missing", missing, 0);
             }),
        good("direction, simple shear", "direction " + shear + " --u '-1.3 0 0'", "",
             prints({"status = ok", "d_s = 0 0 1", "gamma_dot = 2.385"})),
        good("direction, rigid rotation", "direction --grad '0 -1 0 1 0 0 0 0 0' --u '1 0 0'", "", prints({"status = no_shear"})),
    };
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
                                      " --TL " + arg(L.a * L.a) + " --TR " + arg(R.a * R.a) + " --SL " + arg(S(L.a)) + " --SR " +
                                      arg(S(R.a)) + " --sample " + std::to_string(kSamples));
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
    const fs::path cli_path = Cli::beside(argv[0]);
    const fs::path work = fs::temp_directory_path() / ("granseg_verify_cli_" + std::to_string(::getpid()));
    fs::create_directories(work);
    const fs::path out = work / "out", scene = work / "scene.toml";
    const Cli cli(cli_path, work);
    CheckTable t("CLI input validation (granseg run, closures, riemann, direction) and riemann output");
    for (const Case& c : cli_cases(out)) {
        fs::remove_all(out);
        std::string arguments = c.arguments;
        if (!c.scene.empty()) {
            std::ofstream(scene) << c.scene;
            arguments.replace(arguments.find("SCENE"), 5, "'" + scene.string() + "'");
        }
        const Outcome o = cli.run(arguments);
        if (c.check) {
            c.check(t, c.label, o, out);
            continue;
        }
        expect_rejected(t, c.label, o, out);
        if (!c.names.empty())
            t.count(c.label + ": message starts with the file and names the key",
                    o.err.rfind(scene.string() + ": " + c.names, 0) == 0, 1);
    }
    check_riemann_agreement(t, cli);
    fs::remove_all(work);
    return t.finish();
}
