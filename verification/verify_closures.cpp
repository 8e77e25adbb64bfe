// Verification of the Sect. 2.1 closures (eqs. 15-21) for the substitute material.
//
// What is checked, and against what independent expectation (the checks that depend on the
// compressibility law run for every law of kCompressibilityLaws: the default material's rows
// unprefixed, another law's rows prefixed by its name):
//   - dilute limit: g -> 1 and p -> Phi T, with the Taylor bound 2 b Phi/Phi_rcp;
//   - divergence at Phi_rcp: the measured exponent of g against the gap 1 - Phi/Phi_rcp, against
//     each law's documented exponent b (documented_exponent, written apart from the code's);
//   - the Heaviside switch of eq. (19): p_y = 0 below Phi_co, p_y > 0 above;
//   - the sound speed c^2 = dp/dPhi against a central finite difference of p, and c^2 > 0;
//   - steady homogeneous shear with T from eq. (45): heating (3/2) eta gamma_dot^2 equals the
//     dissipation eps Phi T of eq. (14); tau/p = sqrt(2 eta0 eps0/3) for every shear rate over four
//     decades (frictional); p_k grows like gamma_dot^2 (Bagnold); the eq. (21) factor sqrt(2/3);
//   - T -> 0 asymptotics: eta ~ T^(-1/2) in the yield regime, eta ~ T^(1/2) below Phi_co, and a
//     finite dissipation;
//   - the packing fits: residual against the table, GSL coefficients against an independent
//     least-squares solve (Eigen QR), Phi_co < Phi_rcp on [0, 1].
// Writes closures_vs_Phi.dat, packing_table.dat and packing_fit.dat for figures/fig_closures.gp.
//
// Run: build/verification/verify_closures [--data DIR]   (well under a second)
#include "closures/closures.hpp"
#include "harness/check_table.hpp"
#include "harness/program.hpp"
#include "harness/tolerances.hpp"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

using namespace granseg;
using granseg::verify::CheckTable;
using granseg::verify::kRoundOff;

namespace {

// Tolerances, each with its reason.
// Divergence exponent from gaps 1e-3 and 1e-6: 1 - Phi/Phi_rcp carries a relative error of
// DBL_EPSILON/gap <= 2.2e-10, which moves the measured exponent by less than 1e-9.
constexpr double kExponentTol = 1e-8;
// Central difference of p with step h = 1e-7 Phi, at least 1e-2 away from Phi_rcp and Phi_co:
// truncation (h/gap)^2 ~ 1e-10, round-off DBL_EPSILON/h * p/(Phi c^2) ~ 1e-8; 1e-6 covers both.
constexpr double kFiniteDifferenceTol = 1e-6;
// Asymptotic exponent of eta at T = 1e-12 vs 1e-10 (yield regime): the neglected term
// Phi sqrt(T) / (T0 (Phi - Phi_co)/sqrt(T)) = Phi T/(T0 (Phi - Phi_co)) is below 1e-6 there.
constexpr double kAsymptoticExponentTol = 1e-5;
// A degree-4 polynomial cannot follow the sqrt-like rise of the Desmond-Weeks data at the ends
// (docs/assumptions.md A3): its maximum residual on the table is 0.0022; 0.003 bounds it.
constexpr double kPackingFitBound = 3e-3;
// GSL (SVD) and Eigen (column-pivoting QR) solve the same 21x5 least-squares problem; the
// Vandermonde matrix on [0, 1] has condition number ~3e3, so coefficients agree to ~1e-12.
constexpr double kFitAgreementTol = 1e-9;
// Least-squares slope from 17 logarithms: the cancellation in n sxx - sx^2 amplifies round-off
// of ~1e-16 to ~1e-13; 1e-11 leaves room.
constexpr double kSlopeTol = 1e-11;

const std::vector<double> kPhiHats = {0.0, 0.2, 0.4, 0.6, 0.8, 1.0};

/// The exponent b of g ~ (1 - Phi/Phi_rcp)^(-b) as docs/assumptions.md A1 documents each law,
/// written here apart from compressibility_exponent(): a law without its case here is NaN, which
/// fails every check that uses it.
double documented_exponent(const Material& m, double Phi_rcp) {
    switch (m.g_law) {
        case CompressibilityLaw::power:
            return m.beta;
        case CompressibilityLaw::lun_savage:
            return 2.5 * Phi_rcp;
    }
    return NAN;
}

void check_dilute_limit(CheckTable& table, const Material& m, const std::string& label) {
    // Taylor: g = 1 + b Phi/Phi_rcp + O(Phi^2), so |g - 1| <= 2 b Phi/Phi_rcp for small Phi.
    double worst_g = 0.0, worst_p = 0.0, bound = 0.0;
    const double Phi = 1e-6, T = 1e-2;
    for (double x : kPhiHats) {
        const ClosureValues v = evaluate_closures(m, Phi, x, T);
        worst_g = std::max(worst_g, std::fabs(v.g - 1.0));
        worst_p = std::max(worst_p, std::fabs(v.p / (Phi * T) - 1.0));
        bound = std::max(bound, 2.0 * documented_exponent(m, v.Phi_rcp) * Phi / v.Phi_rcp);
    }
    table.near(label + "dilute limit: max |g - 1| at Phi = 1e-6", worst_g, 0.0, bound);
    table.near(label + "dilute limit: max |p/(Phi T) - 1| at Phi = 1e-6", worst_p, 0.0, bound);
}

/// Largest error, over phi_hat, of the exponent b in g ~ (1 - Phi/Phi_rcp)^(-b) measured from the
/// gaps 1e-3 and 1e-6, against the law's documented exponent (NaN for a law without one).
double divergence_exponent_error(const Material& m) {
    double worst = 0.0;
    for (double x : kPhiHats) {
        const double rcp = m.packing.Phi_rcp(x);
        const double g3 = evaluate_closures(m, rcp * (1 - 1e-3), x, 0.0).g;
        const double g6 = evaluate_closures(m, rcp * (1 - 1e-6), x, 0.0).g;
        const double measured = std::log(g6 / g3) / std::log(1e3);
        const double error = std::fabs(measured - documented_exponent(m, rcp));
        worst = std::isnan(error) ? error : std::max(worst, error);
    }
    return worst;
}

void check_divergence(CheckTable& table, const Material& power) {
    double smallest = INFINITY;
    long finite_at_rcp = 0;
    for (double x : kPhiHats) {
        const double rcp = power.packing.Phi_rcp(x);
        smallest = std::min(smallest, evaluate_closures(power, rcp * (1 - 1e-6), x, 0.0).g);
        if (std::isfinite(evaluate_closures(power, rcp, x, 0.0).g)) ++finite_at_rcp;
    }
    table.at_least("g at 1 - Phi/Phi_rcp = 1e-6 (diverges)", smallest, 0.999e6);
    table.count("finite g at Phi = Phi_rcp (wall of the model)", finite_at_rcp, 0);
}

void check_yield_switch(CheckTable& table, const Material& m) {
    long nonzero_below = 0, nonpositive_above = 0;
    for (double x : kPhiHats) {
        const double co = m.packing.Phi_co(x), rcp = m.packing.Phi_rcp(x);
        for (int i = 0; i < 1000; ++i) {
            const double below = co * i / 1000.0;
            const double above = co + (rcp - co) * (i + 0.5) / 1000.0;
            for (double T : {0.0, 1e-4, 1.0}) {
                if (evaluate_closures(m, below, x, T).p_y != 0.0) ++nonzero_below;
                if (!(evaluate_closures(m, above, x, T).p_y > 0.0)) ++nonpositive_above;
            }
        }
    }
    table.count("p_y != 0 below Phi_co (eq. 19 Heaviside), count", nonzero_below, 0);
    table.count("p_y <= 0 between Phi_co and Phi_rcp, count", nonpositive_above, 0);
}

void check_sound_speed(CheckTable& table, const Material& m, const std::string& label) {
    double worst = 0.0;
    long nonpositive = 0;
    for (double x : kPhiHats) {
        const double co = m.packing.Phi_co(x), rcp = m.packing.Phi_rcp(x);
        for (double T : {1e-8, 1e-4, 1e-1}) {
            for (int i = 1; i < 400; ++i) {
                const double Phi = rcp * i / 400.0;
                const double gap = std::min(1.0 - Phi / rcp, std::fabs(Phi - co));
                const ClosureValues v = evaluate_closures(m, Phi, x, T);
                if (!(v.c2 > 0.0)) ++nonpositive;
                if (gap < 1e-2) continue;
                const double h = 1e-7 * Phi;
                const double fd = (evaluate_closures(m, Phi + h, x, T).p - evaluate_closures(m, Phi - h, x, T).p) / (2 * h);
                worst = std::max(worst, std::fabs(fd / v.c2 - 1.0));
            }
        }
    }
    table.at_most(label + "c^2 = dp/dPhi vs central difference, max rel. error", worst, kFiniteDifferenceTol);
    table.count(label + "c^2 <= 0 for 0 < Phi < Phi_rcp, T > 0, count", nonpositive, 0);
}

void check_steady_shear(CheckTable& table, const Material& m, const std::string& label) {
    const double expected_mu = std::sqrt(2.0 * m.eta0 * m.eps0 / 3.0);  // from eqs. (14), (43)-(45)
    double worst_balance = 0.0, worst_mu = 0.0, mu_min = INFINITY, mu_max = 0.0, worst_slope = 2.0;
    for (double x : {0.0, 0.4, 1.0}) {
        for (double Phi : {0.3, 0.5, 0.57, 0.59, 0.6, 0.62}) {
            if (Phi >= m.packing.Phi_rcp(x)) continue;
            // Least-squares slope of ln p_k against ln gamma_dot over four decades (Bagnold: 2).
            double sx = 0, sy = 0, sxx = 0, sxy = 0;
            int n = 0;
            for (int k = -8; k <= 8; ++k) {
                const double gamma_dot = std::pow(10.0, k / 4.0);
                const double T = 1.5 * (m.eta0 / m.eps0) * gamma_dot * gamma_dot;  // eq. (45)
                const ClosureValues v = evaluate_closures(m, Phi, x, T);
                const double heating = 1.5 * v.eta * gamma_dot * gamma_dot;  // (3/2) eta kappa:kappa
                worst_balance = std::max(worst_balance, std::fabs(heating / v.dissipation - 1.0));
                const double mu = v.eta * gamma_dot / v.p;  // tau/p with tau = eta gamma_dot
                worst_mu = std::max(worst_mu, std::fabs(mu / expected_mu - 1.0));
                mu_min = std::min(mu_min, mu);
                mu_max = std::max(mu_max, mu);
                const double lx = std::log(gamma_dot), ly = std::log(v.p_k);
                sx += lx, sy += ly, sxx += lx * lx, sxy += lx * ly, ++n;
            }
            const double slope = (n * sxy - sx * sy) / (n * sxx - sx * sx);
            if (std::fabs(slope - 2.0) >= std::fabs(worst_slope - 2.0)) worst_slope = slope;
        }
    }
    table.at_most(label + "shear: |heating/dissipation - 1|, T from eq. (45)", worst_balance, kRoundOff);
    table.near(label + "shear: tau/p at gamma_dot = 1e-2 .. 1e2 (max)", mu_max, expected_mu, kRoundOff * expected_mu);
    table.near(label + "shear: tau/p at gamma_dot = 1e-2 .. 1e2 (min)", mu_min, expected_mu, kRoundOff * expected_mu);
    table.at_most(label + "shear: max |(tau/p)/sqrt(2 eta0 eps0/3) - 1|", worst_mu, kRoundOff);
    table.near(label + "Bagnold: d ln p_k / d ln gamma_dot (worst state)", worst_slope, 2.0, kSlopeTol);
    table.near(label + "eq. (21) factor: (tau/p) / sqrt(eps0 eta0)", mu_max / std::sqrt(m.eps0 * m.eta0), std::sqrt(2.0 / 3.0),
               kRoundOff);
}

void check_low_temperature(CheckTable& table, const Material& m) {
    const double x = 0.4, co = m.packing.Phi_co(x);
    auto exponent = [&](double Phi, double Ta, double Tb) {
        return std::log(evaluate_closures(m, Phi, x, Tb).eta / evaluate_closures(m, Phi, x, Ta).eta) / std::log(Tb / Ta);
    };
    table.near("yield regime: d ln eta / d ln T as T -> 0", exponent(co + 0.01, 1e-12, 1e-10), -0.5, kAsymptoticExponentTol);
    table.near("below Phi_co: d ln eta / d ln T", exponent(co - 0.05, 1e-12, 1e-10), 0.5, kRoundOff * 100);
    long bad = 0;
    for (int i = 0; i < 100; ++i) {
        const double Phi = m.packing.Phi_rcp(x) * i / 100.0;
        const double d = evaluate_closures(m, Phi, x, 0.0).dissipation;
        if (!(std::isfinite(d) && d == 0.0)) ++bad;
    }
    table.count("dissipation eps Phi T at T = 0 not exactly 0, count", bad, 0);
}

void check_packing_fit(CheckTable& table, const Material& m) {
    const PackingTable& data = m.packing.table();
    double worst_rcp = 0.0, worst_co = 0.0;
    for (std::size_t i = 0; i < data.phi_hat.size(); ++i) {
        worst_rcp = std::max(worst_rcp, std::fabs(m.packing.Phi_rcp(data.phi_hat[i]) - data.Phi_rcp[i]));
        worst_co = std::max(worst_co, std::fabs(m.packing.Phi_co(data.phi_hat[i]) - data.Phi_co[i]));
    }
    table.at_most("packing fit: max |Phi_rcp fit - table|", worst_rcp, kPackingFitBound);
    table.at_most("packing fit: max |Phi_co fit - table|", worst_co, kPackingFitBound);

    // Independent least squares: Eigen's column-pivoting QR on the same Vandermonde system.
    const int p = m.packing.degree() + 1, n = static_cast<int>(data.phi_hat.size());
    Eigen::MatrixXd X(n, p);
    Eigen::VectorXd y(n);
    for (int i = 0; i < n; ++i) {
        for (int k = 0; k < p; ++k) X(i, k) = std::pow(data.phi_hat[i], k);
        y(i) = data.Phi_rcp[i];
    }
    const Eigen::VectorXd c = X.colPivHouseholderQr().solve(y);
    double worst_coef = 0.0;
    for (int k = 0; k < p; ++k) worst_coef = std::max(worst_coef, std::fabs(c(k) - m.packing.rcp_polynomial().c[k]));
    table.near("GSL vs Eigen QR fit coefficients, max difference", worst_coef, 0.0, kFitAgreementTol);

    long crossings = 0;
    for (int i = 0; i <= 10000; ++i)
        if (!(m.packing.Phi_co(i / 1e4) < m.packing.Phi_rcp(i / 1e4))) ++crossings;
    table.count("Phi_co >= Phi_rcp on a 10^4-point grid of phi_hat, count", crossings, 0);
}

void write_figure_data(const verify::ProgramOptions& options, const Material& m) {
    DataTable curves;
    curves.comment("T = 1e-4 m^2/s^2; one block per phi_hat (gnuplot index 0, 1, 2)");
    for (double x : {0.0, 0.4, 1.0}) {
        const double rcp = m.packing.Phi_rcp(x);
        // Linear in Phi up to 0.9 Phi_rcp, then geometric in the gap 1 - Phi/Phi_rcp down to 1e-3.
        std::vector<double> Phis;
        for (int i = 1; i <= 300; ++i) Phis.push_back(0.9 * rcp * i / 300.0);
        for (int i = 1; i <= 200; ++i) Phis.push_back(rcp * (1.0 - 0.1 * std::pow(1e-2, i / 200.0)));
        for (double Phi : Phis) {
            const ClosureValues v = evaluate_closures(m, Phi, x, 1e-4);
            curves.row({{"phi_hat", x},
                        {"Phi", Phi},
                        {"g", v.g},
                        {"p_k", v.p_k},
                        {"p_y", v.p_y},
                        {"p", v.p},
                        {"eta", v.eta},
                        {"c", std::sqrt(v.c2)}});
        }
        curves.blank();
        curves.blank();
    }
    verify::write_data(options, "closures_vs_Phi.dat", curves);

    DataTable points;
    for (const auto& c : m.packing.table().comments) points.comment(c);
    for (std::size_t i = 0; i < m.packing.table().phi_hat.size(); ++i)
        points.row({{"phi_hat", m.packing.table().phi_hat[i]},
                    {"Phi_rcp", m.packing.table().Phi_rcp[i]},
                    {"Phi_co", m.packing.table().Phi_co[i]}});
    verify::write_data(options, "packing_table.dat", points);

    DataTable fit;
    fit.comment("degree-" + std::to_string(m.packing.degree()) + " least-squares fits of packing_table.dat");
    for (int i = 0; i <= 200; ++i)
        fit.row({{"phi_hat", i / 200.0}, {"Phi_rcp", m.packing.Phi_rcp(i / 200.0)}, {"Phi_co", m.packing.Phi_co(i / 200.0)}});
    verify::write_data(options, "packing_fit.dat", fit);
}

}  // namespace

int main(int argc, char** argv) {
    const auto options = verify::parse_program_options(argc, argv);
    const Material m = Material::glass_substitute();
    CheckTable table("Sect. 2.1 closures (eqs. 15-21), substitute material");
    // What depends on the law, for every law of the table (exercise 2 of docs/tutorial.md adds
    // one): the default material's rows unprefixed, another law's prefixed by its name.
    const auto for_each_law = [&](const auto& check) {
        for (const auto& law : kCompressibilityLaws) {
            Material with_law = m;
            with_law.g_law = law.value;
            check(with_law, std::string(law.name), law.value == m.g_law ? "" : std::string(law.name) + ": ");
        }
    };
    for_each_law([&](const Material& with_law, const std::string& name, const std::string& label) {
        check_dilute_limit(table, with_law, label);
        table.near("divergence exponent error, law " + name, divergence_exponent_error(with_law), 0.0, kExponentTol);
    });
    check_divergence(table, m);
    check_yield_switch(table, m);
    for_each_law([&](const Material& with_law, const std::string&, const std::string& label) {
        check_sound_speed(table, with_law, label);
        check_steady_shear(table, with_law, label);
    });
    check_low_temperature(table, m);
    check_packing_fit(table, m);
    write_figure_data(options, m);
    return table.finish();
}
