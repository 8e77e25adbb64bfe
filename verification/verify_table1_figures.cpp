// Data and checks for Figs. 3-5 of Sect. 3.2 (S = 1, T = 1 on both sides, a = 1).
//   Fig. 3: integral curves through the critical state Q* = (0.25, 0.5): the wave curve
//     Phi = Phi* (eigenvector r_1) and the standing-wave curve f = f(Q*) (r_0), with Gamma and a
//     family of curves f = const. Checked: eqs. (54)-(56) as restored in docs/paper_notes.md against
//     finite differences of the code's f (DF r_0 = 0, DF r_1 = lambda_1 r_1), and the computed
//     curve f = f(Q*) against f and against the slope r_0 gives.
//   Fig. 4a/4b: regions A-F for Q_L = (0.15, 0.5) (left of Gamma) and G-J for Q_L = (0.4, 0.5)
//     (right of Gamma), by classifying a 400 x 400 grid of Q_R with classify_table1. Checked:
//     which regions appear, and that the exact flux equals eq. (63) at every grid point. A-F again
//     for Q_L = (0.1, 0.5), the left state of docs/tutorial.md's step 2 (tutorial_fig4a_*.dat).
//   Fig. 5: the region C example Q_L = (0.1, 0.5), Q_R = (0.3, 0.8): waves in state space, on
//     the flux curves f_L, f_R, and the profile phi(z/t). Checked: case, waves and their speeds
//     as the caption of Fig. 5 states them, F = f_L^min, and every property of
//     verification/table1/exact_solution_checks.hpp.
//
// Run: build/verification/verify_table1_figures [--data DIR]   (well under a second)
#include "harness/check_table.hpp"
#include "harness/program.hpp"
#include "harness/tolerances.hpp"
#include "table1/exact_solution_checks.hpp"
#include "table1/table1_states.hpp"

#include <algorithm>
#include <cmath>
#include <deque>
#include <string>
#include <vector>

using namespace granseg;
using namespace granseg::verify;

namespace {

constexpr int kGrid = 400;  // Fig. 4: grid points per axis
// Central differences of f (quadratic in phi, rational in Phi) with step 1e-6: truncation
// ~1e-12, round-off DBL_EPSILON/1e-6 ~ 2e-10; 1e-8 covers both.
constexpr double kDifferenceTol = 1e-8;
// Slope dphi/dPhi of the computed curve f = f(Q*) by a central chord of half-width 1e-5 in Phi,
// against r_0: truncation (1e-5)^2 |phi'''| < 1e-8 for Phi >= 1.2 Phi* (the curve has a square-root
// point on Gamma, so its derivatives grow towards Phi*), round-off DBL_EPSILON/1e-5 ~ 2e-11.
constexpr double kSlopeTol = 1e-7;

void check_figure3(CheckTable& t, const ProgramOptions& options) {
    const double Phi_star = 0.5, a = 1.0, f_star = flux_extremum(Phi_star, a);
    // Eqs. (54)-(56): DF = [[lambda_1, df/dPhi], [0, 0]], r_0 = (phi^2/Phi^2, 2 phi/Phi - 1), r_1 = (1, 0).
    double worst_r0 = 0.0, worst_r1 = 0.0;
    for (double Phi : {0.2, 0.5, 0.9})
        for (double psi : {0.1, 0.3, 0.5, 0.7, 0.9}) {
            const double phi = psi * Phi, d = 1e-6;
            const double f_phi = (segregation_flux(phi + d, Phi, a) - segregation_flux(phi - d, Phi, a)) / (2 * d);
            const double f_Phi = (segregation_flux(phi, Phi + d, a) - segregation_flux(phi, Phi - d, a)) / (2 * d);
            const double r0[2] = {psi * psi, 2 * psi - 1};
            worst_r0 = std::max(worst_r0, std::fabs(f_phi * r0[0] + f_Phi * r0[1]));  // lambda_0 = 0
            worst_r1 = std::max(worst_r1, std::fabs(f_phi - segregation_speed(phi, Phi, a)));
        }
    t.at_most("Fig. 3: |DF r_0| (lambda_0 = 0, eq. 56), finite differences", worst_r0, kDifferenceTol);
    t.at_most("Fig. 3: |DF r_1 - lambda_1 r_1| (eq. 55), finite differences", worst_r1, kDifferenceTol);

    DataTable curves;
    curves.comment("Fig. 3: block 0 the standing-wave curve f = f(Q*) through Q* = (0.25, 0.5) (left branch, then");
    curves.comment("right branch); block 1 the wave curve Phi = Phi*; blocks 2.. curves f = const, S = T = 1");
    double worst_f = 0.0, worst_slope = 0.0;
    for (int side = 0; side < 2; ++side)
        for (int k = 0; k <= 500; ++k) {
            const double Phi = side == 0 ? 1.0 - 0.5 * k / 500.0 : Phi_star + 0.5 * k / 500.0;
            const double phi = side == 0 ? phi_left_of_gamma(f_star, Phi, a) : phi_right_of_gamma(f_star, Phi, a);
            worst_f = std::max(worst_f, std::fabs(segregation_flux(phi, Phi, a) - f_star));
            curves.row({{"phi", phi}, {"Phi", Phi}, {"f", f_star}});
        }
    for (double Phi : {0.6, 0.7, 0.8, 0.9, 0.99}) {
        const double d = 1e-5;
        for (auto branch : {phi_left_of_gamma, phi_right_of_gamma}) {
            const double chord = (branch(f_star, Phi + d, a) - branch(f_star, Phi - d, a)) / (2 * d);
            const double psi = branch(f_star, Phi, a) / Phi;
            worst_slope = std::max(worst_slope, std::fabs(chord - psi * psi / (2 * psi - 1)));  // r_0: dphi/dPhi
        }
    }
    t.at_most("Fig. 3: |f - f(Q*)| on the computed standing-wave curve", worst_f, kRoundOff);
    t.at_most("Fig. 3: |slope of that curve - r_0 slope|", worst_slope, kSlopeTol);
    curves.blank(), curves.blank();
    curves.row({{"phi", 0.0}, {"Phi", Phi_star}, {"f", 0.0}}), curves.row({{"phi", Phi_star}, {"Phi", Phi_star}, {"f", 0.0}});
    for (double F : {-0.025, -0.05, -0.075, -0.1, -0.15, -0.2}) {
        curves.blank(), curves.blank();
        for (int k = 0; k <= 200; ++k) {
            const double Phi = -4 * F / a + (1.0 + 4 * F / a) * k / 200.0;  // from Gamma (f_min = F) to Phi = 1
            curves.row({{"phi", phi_left_of_gamma(F, Phi, a)}, {"Phi", Phi}, {"f", F}});
        }
        curves.blank(), curves.blank();
        for (int k = 0; k <= 200; ++k) {
            const double Phi = -4 * F / a + (1.0 + 4 * F / a) * k / 200.0;
            curves.row({{"phi", phi_right_of_gamma(F, Phi, a)}, {"Phi", Phi}, {"f", F}});
        }
    }
    write_data(options, "fig3_curves.dat", curves);
}

/// Fig. 4: the case of every Q_R of a grid, and a label position inside each region (the grid
/// point farthest, in grid steps, from the region's boundary).
void check_figure4(CheckTable& t, const ProgramOptions& options, const FluxSide& L, const std::string& name, int first_case,
                   int last_case) {
    std::vector<int> cell(kGrid * kGrid, 0);
    std::vector<long> hits(11, 0);
    double worst = 0.0;
    auto phi_at = [](int i) { return (i + 0.5) / kGrid; };
    for (int j = 0; j < kGrid; ++j)
        for (int i = 0; i < kGrid; ++i) {
            const FluxSide R{phi_at(i), phi_at(j), L.a};
            if (R.phi > R.Phi) continue;  // unphysical, phi > Phi
            const int c = classify_table1(L, R).number;
            cell[j * kGrid + i] = c;
            ++hits[c];
            worst = std::max(worst, std::fabs(solve_riemann(L, R).flux - modified_godunov_flux({L, R})));
        }
    long wrong = 0;
    std::string counts;
    for (int c = 1; c <= 10; ++c) {
        const bool expected = c >= first_case && c <= last_case;
        wrong += expected != (hits[c] > 0);
        counts += " " + std::string(1, kTable1[c - 1].region) + ":" + std::to_string(hits[c]);
    }
    t.note("  " + name + " grid points per region:" + counts);
    t.count(name + ": regions present != " + std::string(1, kTable1[first_case - 1].region) + "-" +
                std::string(1, kTable1[last_case - 1].region),
            wrong, 0);
    t.at_most(name + ": |exact flux - eq. (63)| on the grid", worst, kRoundOff);

    DataTable regions;
    regions.comment(name + ": Q_L = (" + std::to_string(L.phi) + ", " + std::to_string(L.Phi) +
                    "), S = T = 1; case 0: phi > Phi");
    for (int j = 0; j < kGrid; ++j) {
        for (int i = 0; i < kGrid; ++i)
            regions.row({{"phi_R", phi_at(i)}, {"Phi_R", phi_at(j)}, {"case", static_cast<double>(cell[j * kGrid + i])}});
        regions.blank();
    }
    write_data(options, name + "_regions.dat", regions);

    // Depth of every grid point below its region's boundary (multi-source breadth-first search).
    std::vector<int> depth(kGrid * kGrid, -1);
    std::deque<int> queue;
    for (int j = 0; j < kGrid; ++j)
        for (int i = 0; i < kGrid; ++i) {
            const int k = j * kGrid + i;
            const bool edge = i == 0 || j == 0 || i == kGrid - 1 || j == kGrid - 1 || cell[k] != cell[k - 1] ||
                              cell[k] != cell[k + 1] || cell[k] != cell[k - kGrid] || cell[k] != cell[k + kGrid];
            if (edge) depth[k] = 0, queue.push_back(k);
        }
    while (!queue.empty()) {
        const int k = queue.front();
        queue.pop_front();
        for (int n : {k - 1, k + 1, k - kGrid, k + kGrid})
            if (n >= 0 && n < kGrid * kGrid && depth[n] < 0) depth[n] = depth[k] + 1, queue.push_back(n);
    }
    DataTable labels;
    for (int c = first_case; c <= last_case; ++c) {
        int best = -1;
        for (int k = 0; k < kGrid * kGrid; ++k)
            if (cell[k] == c && (best < 0 || depth[k] > depth[best])) best = k;
        if (best >= 0)
            labels.row({{"phi_R", phi_at(best % kGrid)}, {"Phi_R", phi_at(best / kGrid)}, {"case", static_cast<double>(c)}});
    }
    write_data(options, name + "_labels.dat", labels);
}

void check_figure5(CheckTable& t, const ProgramOptions& options) {
    const FluxSide L{0.1, 0.5, 1.0}, R{0.3, 0.8, 1.0};
    const RiemannSolution s = solve_riemann(L, R);
    const SolutionErrors e = check_exact_solution(s, modified_godunov_flux({L, R}));
    t.count("Fig. 5: case of Q_R = (0.3, 0.8) for Q_L = (0.1, 0.5)", classify_table1(L, R).number, 3);
    t.count("Fig. 5: waves != rarefaction, standing, shock (caption)", wave_pattern(s) != "RCS", 0);
    t.at_most("Fig. 5: rarefaction speed lambda_1(Q_L) (caption: < 0)", s.waves.front().speed_left, -0.1);
    t.at_least("Fig. 5: shock speed s (caption: > 0)", s.waves.back().speed_left, 0.1);
    t.near("Fig. 5: interface flux = f_L^min = -Phi_L/4", s.flux, -0.25 * L.Phi, kRoundOff);
    t.count("Fig. 5: violated properties of the exact solution",
            e.lax + e.gamma_crossings + e.chain + e.fan_order + (e.rankine_hugoniot > kRoundOff) + (e.mass_flux > kRoundOff), 0);

    const double phi_check = s.phi_plus;  // Q-check_R: the right end of the standing wave
    DataTable states;
    states.comment("Fig. 5 states: Q_L, Q* = (Phi_L/2, Phi_L), Q-check_R (right end of the standing wave), Q_R");
    for (const FluxSide& q : {L, FluxSide{0.5 * L.Phi, L.Phi, 1.0}, FluxSide{phi_check, R.Phi, 1.0}, R})
        states.row({{"phi", q.phi}, {"Phi", q.Phi}, {"f", flux_of(q)}});
    write_data(options, "fig5_states.dat", states);

    DataTable path;
    path.comment(
        "Fig. 5 wave path: block 0 rarefaction (Phi = Phi_L), block 1 standing wave (f = F), block 2 shock (Phi = Phi_R)");
    for (int k = 0; k <= 50; ++k) {
        const double phi = L.phi + (0.5 * L.Phi - L.phi) * k / 50.0;
        path.row({{"phi", phi}, {"Phi", L.Phi}, {"f", segregation_flux(phi, L.Phi, 1.0)}});
    }
    path.blank(), path.blank();
    for (int k = 0; k <= 100; ++k) {
        const double Phi = L.Phi + (R.Phi - L.Phi) * k / 100.0;
        path.row({{"phi", phi_right_of_gamma(s.flux, Phi, 1.0)}, {"Phi", Phi}, {"f", s.flux}});
    }
    path.blank(), path.blank();
    path.row({{"phi", phi_check}, {"Phi", R.Phi}, {"f", s.flux}}), path.row({{"phi", R.phi}, {"Phi", R.Phi}, {"f", flux_of(R)}});
    write_data(options, "fig5_path.dat", path);

    DataTable curves;
    curves.comment("Fig. 5b: the flux curves f_L = f(.; Phi_L) on [0, Phi_L] and f_R on [0, Phi_R] (f_L = nan beyond Phi_L)");
    for (int k = 0; k <= 400; ++k) {
        const double phi = R.Phi * k / 400.0;
        curves.row({{"phi", phi},
                    {"f_L", phi <= L.Phi ? segregation_flux(phi, L.Phi, 1.0) : NAN},
                    {"f_R", segregation_flux(phi, R.Phi, 1.0)}});
    }
    write_data(options, "fig5_flux_curves.dat", curves);

    DataTable profile;
    profile.comment("Fig. 5c: phi(xi) and Phi(xi), xi = z/t, with points on both sides of every wave speed");
    std::vector<double> xs;
    for (int k = 0; k <= 600; ++k) xs.push_back(-1.0 + 2.0 * k / 600.0);
    for (const Wave& w : s.waves)
        for (double c : {w.speed_left, w.speed_right}) xs.push_back(c - 1e-9), xs.push_back(c + 1e-9);
    std::sort(xs.begin(), xs.end());
    for (double xi : xs) profile.row({{"xi", xi}, {"phi", sample_phi(s, xi)}, {"Phi", sample_Phi(s, xi)}});
    write_data(options, "fig5_profile.dat", profile);
}

}  // namespace

int main(int argc, char** argv) {
    const auto options = parse_program_options(argc, argv);
    CheckTable t("Sect. 3.2 figures: integral curves (Fig. 3), regions A-J (Fig. 4), region C example (Fig. 5)");
    check_figure3(t, options);
    check_figure4(t, options, {0.15, 0.5, 1.0}, "fig4a", 1, 6);
    check_figure4(t, options, {0.1, 0.5, 1.0}, "tutorial_fig4a", 1, 6);  // the left state of docs/tutorial.md, step 2
    check_figure4(t, options, {0.4, 0.5, 1.0}, "fig4b", 7, 10);
    check_figure5(t, options);
    return t.finish();
}
