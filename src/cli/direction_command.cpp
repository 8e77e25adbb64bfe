// granseg direction --grad "g11 g12 g13 g21 g22 g23 g31 g32 g33" --u "u1 u2 u3" [options]
// Runs the Sect. 2.3 procedure at one point and prints `name = value` lines: status, d_s, P,
// gamma_dot, the eigenpairs, both candidates and the segregation velocity S^sl (eq. 46).
#include "cli/commands.hpp"
#include "cli/options.hpp"
#include "closures/closures.hpp"
#include "core/error.hpp"
#include "core/format.hpp"
#include "direction/segregation_direction.hpp"
#include "direction/segregation_velocity.hpp"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <sstream>

namespace granseg::cli {

namespace {

/// The numbers of a list option ("1 0 0", commas allowed); InputError unless exactly `count`
/// finite numbers.
std::vector<double> number_list(const std::string& option, const std::string& text, std::size_t count,
                                const std::string& layout) {
    std::string spaced = text;
    for (char& c : spaced)
        if (c == ',') c = ' ';
    std::istringstream in(spaced);
    std::vector<double> values;
    for (std::string word; in >> word;) {
        errno = 0;
        char* end = nullptr;
        const double v = std::strtod(word.c_str(), &end);
        if (end != word.c_str() + word.size() || errno == ERANGE || !std::isfinite(v))
            throw InputError("granseg direction: --" + option + ": \"" + word + "\" is not a finite number");
        values.push_back(v);
    }
    if (values.size() != count)
        throw InputError("granseg direction: --" + option + ": expected " + std::to_string(count) + " numbers (" + layout +
                         "), got " + std::to_string(values.size()));
    return values;
}

/// A number with 10 digits; -0 prints as 0.
std::string number_text(double v) { return format_number(v + 0.0, 10); }

std::string vector_text(const Eigen::Vector3d& v) {
    return number_text(v(0)) + " " + number_text(v(1)) + " " + number_text(v(2));
}

/// The direction's answer, one "name = value" line each: status, d_s, P, the shear rates and
/// eigenvalues, k_max, k_min, d_plus, d_minus and their |d . u|, T and S^sl.
void print_direction(const SegregationDirection& r, const Eigen::Vector3d& u, double T, const Eigen::Vector3d& S_sl) {
    std::cout << "status = " << to_string(r.status) << '\n' << "d_s = " << vector_text(r.d_s) << '\n';
    const Eigen::Matrix3d P = r.P();
    std::cout << "P = " << vector_text(P.row(0).transpose()) << ' ' << vector_text(P.row(1).transpose()) << ' '
              << vector_text(P.row(2).transpose()) << '\n';
    const std::pair<const char*, double> scalars[] = {
        {"gamma_dot", r.gamma_dot},       {"principal_shear", r.principal_shear}, {"kappa_min", r.eigen.kappa_min},
        {"kappa_mid", r.eigen.kappa_mid}, {"kappa_max", r.eigen.kappa_max},       {"relative_gap", r.eigen.relative_gap},
    };
    for (const auto& [name, value] : scalars) std::cout << name << " = " << number_text(value) << '\n';
    std::cout << "k_max = " << vector_text(sign_normalised(r.eigen.k_max)) << '\n'
              << "k_min = " << vector_text(sign_normalised(r.eigen.k_min)) << '\n'
              << "d_plus = " << vector_text(r.d_plus) << '\n'
              << "d_minus = " << vector_text(r.d_minus) << '\n'
              << "abs_d_plus_dot_u = " << number_text(std::fabs(r.d_plus.dot(u))) << '\n'
              << "abs_d_minus_dot_u = " << number_text(std::fabs(r.d_minus.dot(u))) << '\n'
              << "T = " << number_text(T) << '\n'
              << "S_sl = " << vector_text(S_sl) << '\n';
}

}  // namespace

int direction_main(const std::vector<std::string>& args) {
    std::string grad_text, u_text, gravity_text = "0 0 -9.81", method = "iterative";
    double T = -1, S0 = 1;
    DirectionOptions options;
    const std::string S0_help = std::string("segregation rate S0 of eq. (46) (") + kSegregationRateUnit + ")";
    po::options_description desc("options (grad in 1/s, u in m/s; pass the rotating-frame u and grad in a rotating drum)");
    desc.add_options()("grad", po::value<std::string>(&grad_text)->required(),
                       "velocity gradient, 9 numbers row by row, grad(i,j) = du_i/dx_j")(
        "u", po::value<std::string>(&u_text)->required(), "velocity, 3 numbers")(
        "T", po::value<double>(&T),
        "granular temperature for S^sl (m^2/s^2; default: eq. (45) at gamma_dot, substitute material)")(
        "S0", po::value<double>(&S0)->default_value(1.0), S0_help.c_str())(
        "gravity", po::value<std::string>(&gravity_text)->default_value(gravity_text), "gravity vector g (m/s^2), 3 numbers")(
        "shear-threshold",
        po::value<double>(&options.shear_threshold)
            ->default_value(options.shear_threshold, format_number(options.shear_threshold)),
        "no shear if kappa_max - kappa_min <= this (1/s), assumption D1")(
        "min-relative-gap",
        po::value<double>(&options.min_relative_gap)
            ->default_value(options.min_relative_gap, format_number(options.min_relative_gap)),
        "repeated eigenvalue below this relative gap, assumption D2")(
        "tie-tolerance",
        po::value<double>(&options.tie_tolerance)->default_value(options.tie_tolerance, format_number(options.tie_tolerance)),
        "equal candidates within this fraction of |u|, assumption D4")(
        "min-speed", po::value<double>(&options.min_speed)->default_value(options.min_speed, format_number(options.min_speed)),
        "u = 0 if |u| <= this (m/s), assumption D3")("solver", po::value<std::string>(&method)->default_value(method),
                                                     "Eigen solver: iterative | closed-form")(
        "planar", po::bool_switch(&options.planar_xz), "2-D flow in the x-z plane: eigenpairs of the x-z block (assumption D5)");
    po::variables_map vm;
    if (!parse_options("direction", "--grad \"g11 ... g33\" --u \"u1 u2 u3\" [options]", args, desc, {}, vm)) return 0;

    const auto g9 = number_list("grad", grad_text, 9, "g11 g12 g13 g21 g22 g23 g31 g32 g33");
    const auto u3 = number_list("u", u_text, 3, "u1 u2 u3");
    const auto gv = number_list("gravity", gravity_text, 3, "gx gy gz");
    checked("direction", "shear-threshold", options.shear_threshold, Range::at_least(0));
    checked("direction", "min-relative-gap", options.min_relative_gap, Range::closed(0, 0.5));
    checked("direction", "tie-tolerance", options.tie_tolerance, Range::closed(0, 1));
    checked("direction", "min-speed", options.min_speed, Range::at_least(0));
    checked("direction", "S0", S0, Range::at_least(0));
    if (method == "closed-form")
        options.method = EigenMethod::closed_form;
    else if (method != "iterative")
        throw InputError("granseg direction: --solver: \"" + method + "\" is not a solver (allowed: iterative, closed-form)");
    if (vm.count("T")) checked("direction", "T", T, Range::at_least(0));

    Eigen::Matrix3d grad;
    grad << g9[0], g9[1], g9[2], g9[3], g9[4], g9[5], g9[6], g9[7], g9[8];
    const Eigen::Vector3d u(u3[0], u3[1], u3[2]), g(gv[0], gv[1], gv[2]);
    const SegregationDirection r = segregation_direction(grad, u, options);
    if (!vm.count("T")) T = steady_shear_temperature(Material::glass_substitute(), r.gamma_dot);  // eq. (45)

    print_direction(r, u, T, segregation_velocity(S0, T, r.d_s, g));
    return 0;
}

}  // namespace granseg::cli
