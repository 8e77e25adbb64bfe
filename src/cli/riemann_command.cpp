// granseg riemann PHI_SMALL_L PHI_L PHI_SMALL_R PHI_R [--TL x] [--TR x] [--S x] [--SL x] [--SR x]
//                 [--sample N]
// Solves one Riemann problem of system (52) exactly (Sect. 3.2) and prints `name = value` lines:
// the states, the Table 1 case and region, the interface flux, the traces, one `wave` line per
// wave and, with --sample N, N lines `sample = xi phi(xi)`.
#include "cli/commands.hpp"
#include "cli/options.hpp"
#include "core/error.hpp"
#include "core/format.hpp"
#include "riemann/riemann_sample.hpp"
#include "riemann/riemann_solver.hpp"
#include "riemann/table1_classifier.hpp"

#include <cmath>
#include <iostream>
#include <string>

namespace granseg::cli {

namespace {

constexpr int kDigits = 12;

std::string num(double v) { return format_number(v, kDigits); }

/// Throws the one-line InputError of a positional argument outside its range.
double checked_positional(const std::string& name, double v, const Range& range) {
    if (!range.contains(v))
        throw InputError("granseg riemann: " + name + ": " + format_number(v) +
                         " is out of range (allowed: " + range.describe(name) + ")");
    return v;
}

std::string family_of(const FluxSide& L, const FluxSide& R, const Table1Case& c) {
    if (c.number == 0) return "sign change or zero (a_L a_R <= 0): zero interface flux";
    if (c.mirrored) return "concave (a_L, a_R < 0): mirror image of case " + std::to_string(c.number);
    return L.a == R.a ? "convex (a_L = a_R > 0)" : "convex (a_L, a_R > 0, T_L != T_R)";
}

std::string describe(const Wave& w) {
    std::string s = std::string(wave_kind_name(w.kind)) + " phi " + num(w.left.phi) + " -> " + num(w.right.phi) + ", Phi ";
    s += w.kind == WaveKind::standing ? num(w.left.Phi) + " -> " + num(w.right.Phi) : num(w.left.Phi);
    s += ", speed " + num(w.speed_left);
    if (w.kind == WaveKind::rarefaction) s += " .. " + num(w.speed_right);
    return s;
}

}  // namespace

int riemann_main(const std::vector<std::string>& args) {
    double phi_L = 0, Phi_L = 0, phi_R = 0, Phi_R = 0, T_L = 1, T_R = 1, S = 1, S_L = 1, S_R = 1;
    int samples = 0;
    po::options_description desc("arguments and options (a = S sqrt(T) on each side, eqs. 49, 66)");
    desc.add_options()("PHI_SMALL_L", po::value<double>(&phi_L)->required(),
                       "left small-particle fraction phi_L, 0 <= phi_L <= Phi_L")("PHI_L", po::value<double>(&Phi_L)->required(),
                                                                                  "left granular fraction Phi_L, 0 < Phi_L < 1")(
        "PHI_SMALL_R", po::value<double>(&phi_R)->required(), "right small-particle fraction phi_R, 0 <= phi_R <= Phi_R")(
        "PHI_R", po::value<double>(&Phi_R)->required(), "right granular fraction Phi_R, 0 < Phi_R < 1")(
        "TL", po::value<double>(&T_L), "left granular temperature, T >= 0 (default 1)")(
        "TR", po::value<double>(&T_R), "right granular temperature, T >= 0 (default 1)")(
        "S", po::value<double>(&S), "segregation rate of both sides, any sign (default 1)")(
        "SL", po::value<double>(&S_L),
        "segregation rate of the left side (default --S); negative or "
        "opposite signs model (S^sl)_k < 0, docs/assumptions.md S1")("SR", po::value<double>(&S_R),
                                                                     "segregation rate of the right side (default --S)")(
        "sample", po::value<int>(&samples), "also print phi(xi) at N points of [-1.25 a_max, 1.25 a_max]");
    po::positional_options_description positional;
    positional.add("PHI_SMALL_L", 1).add("PHI_L", 1).add("PHI_SMALL_R", 1).add("PHI_R", 1);
    po::variables_map vm;
    if (!parse_options("riemann", "PHI_SMALL_L PHI_L PHI_SMALL_R PHI_R [--TL x] [--TR x] [--S x] [--SL x] [--SR x] [--sample N]",
                       args, desc, positional, vm))
        return 0;

    checked_positional("PHI_L", Phi_L, Range::open(0, 1));
    checked_positional("PHI_R", Phi_R, Range::open(0, 1));
    checked_positional("PHI_SMALL_L", phi_L, Range::closed(0, Phi_L));
    checked_positional("PHI_SMALL_R", phi_R, Range::closed(0, Phi_R));
    checked("riemann", "TL", T_L, Range::at_least(0));
    checked("riemann", "TR", T_R, Range::at_least(0));
    checked("riemann", "S", S, Range::any());
    if (!vm.count("SL")) S_L = S;
    if (!vm.count("SR")) S_R = S;
    checked("riemann", "SL", S_L, Range::any());
    checked("riemann", "SR", S_R, Range::any());
    if (vm.count("sample")) checked("riemann", "sample", samples, Range::closed(1, 100000));

    const FluxSide L{phi_L, Phi_L, S_L * std::sqrt(T_L)}, R{phi_R, Phi_R, S_R * std::sqrt(T_R)};  // eq. (66)
    const RiemannSolution s = solve_riemann(L, R);
    const Table1Case c = classify_table1(L, R);
    const std::pair<const char*, double> states[] = {{"phi_L", L.phi}, {"Phi_L", L.Phi}, {"T_L", T_L}, {"a_L", L.a},
                                                     {"phi_R", R.phi}, {"Phi_R", R.Phi}, {"T_R", T_R}, {"a_R", R.a}};
    for (const auto& [name, value] : states) std::cout << name << " = " << num(value) << '\n';
    std::cout << "family = " << family_of(L, R, c) << '\n'
              << "case = " << c.number << '\n'
              << "region = " << c.region << '\n'
              << "flux = " << num(s.flux) << '\n'
              << "phi_minus = " << num(s.phi_minus) << '\n'
              << "phi_plus = " << num(s.phi_plus) << '\n';
    for (const Wave& w : s.waves) std::cout << "wave = " << describe(w) << '\n';
    const double X = sample_range(s);
    for (int k = 0; k < samples; ++k) {
        const double xi = samples == 1 ? 0.0 : -X + 2.0 * X * k / (samples - 1);
        std::cout << "sample = " << num(xi) << ' ' << num(sample_phi(s, xi)) << '\n';
    }
    return 0;
}

}  // namespace granseg::cli
