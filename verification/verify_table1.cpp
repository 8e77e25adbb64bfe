// Verification of Table 1 (Sect. 3.2): for each of the ten cases, states well inside its region,
// whose exact Riemann solutions are built from wave theory (src/riemann/riemann_solver.cpp) and
// checked here against properties written out independently (verification/table1/
// exact_solution_checks.hpp):
//   - weak solution: Rankine-Hugoniot on every shock, equal flux across the standing wave, and
//     the mass balance of each half-line (which gives the interface flux from the profile alone);
//   - entropy: Lax on every shock, the standing wave does not cross Gamma (Isaacson-Temple);
//   - rarefactions: lambda_1(phi(xi)) = xi, monotone; the wave chain is joined, waves left of
//     z = 0 move left, those right of it move right;
//   - the waves are the ones the case names (table1_states.hpp: kTable1), the flux is the one
//     Table 1 gives, and it equals eq. (63) (modified_godunov_flux);
//   - for T_L = T_R the classifier agrees with Table 1 read literally (conditions on Phi, Phi~).
// Beyond the table as printed: the same for T_L != T_R (half of the states with flux curves crossing inside
// (0, min Phi)), for a_L, a_R < 0 (mirrored cases) and for a_L a_R <= 0 (grouped by sign class).
// The random sweep (consistency, continuity, invariant region) is verify_table1_sweep, the
// fine-grid oracle verify_table1_oracle.
//
// Run: build/verification/verify_table1 [--data DIR]   (well under a second)
#include "harness/check_table.hpp"
#include "harness/program.hpp"
#include "harness/tolerances.hpp"
#include "table1/exact_solution_checks.hpp"
#include "table1/table1_states.hpp"

#include <cmath>
#include <string>
#include <utility>
#include <vector>

using namespace granseg;
using namespace granseg::verify;

namespace {

// States per case and family (item 4a: "several states inside its region").
constexpr int kStatesPerCase = 6;
// Distance from every region boundary (table1_states.hpp: region_margin): 5 % of the largest
// |f_min| and of phi/Phi - 1/2, so that no wave of the expected pattern degenerates.
constexpr double kMargin = 0.05;
// Fluxes and speeds are O(|a|) <= 2 here and come out of a handful of operations plus one square
// root: round-off, kRoundOff per unit of |a|, times 2 (for |a| <= 2).
constexpr double kFluxTol = 2 * kRoundOff;

/// Table 1 read literally for T_L = T_R (docs/paper_notes.md, section 2), with Phi~ = 4 phi_L (Phi_L -
/// phi_L)/Phi_L. Returns a bit mask of the rows whose conditions hold (bit k-1 for case k).
int literal_table1_rows(const FluxSide& L, const FluxSide& R) {
    const double fL = flux_of(L), fR = flux_of(R), f_star = -0.25 * L.a * L.Phi;  // f(Q*)
    const double Phi_tilde = 4.0 * L.phi * (L.Phi - L.phi) / L.Phi;
    const bool L_left = L.phi < L.Phi / 2, R_left = R.phi<R.Phi / 2, R_right = R.phi> R.Phi / 2;
    const bool rows[10] = {
        L_left && R_left && fR > fL,
        L_left && R_left && f_star <= fR && fR < fL,
        L_left && fR < f_star,
        L_left && R_right && R.Phi > L.Phi && fR >= f_star,
        L_left && R_right && Phi_tilde < R.Phi && R.Phi < L.Phi,
        L_left && R_right && R.Phi < Phi_tilde,
        !L_left && R_left && fR > fL,
        !L_left && fR < fL,
        !L_left && R_right && R.Phi > Phi_tilde && fR > fL,
        !L_left && R_right && R.Phi < Phi_tilde,
    };
    int mask = 0;
    for (int k = 0; k < 10; ++k) mask |= rows[k] << k;
    return mask;
}

/// The wave pattern a state of this group must show. Mixed signs: each side with a != 0 moves
/// by one shock to its trace (0 or Phi, an interior state is never already there), then C.
std::string expected_pattern_of(Family family, const FluxSide& L, const FluxSide& R) {
    if (family != Family::mixed) {
        const Table1Case c = classify_table1(L, R);
        return expected_pattern(kTable1[c.number - 1], c.mirrored);
    }
    return std::string(L.a != 0.0 ? "S" : "") + "C" + (R.a != 0.0 ? "S" : "");
}

/// The flux the table names: Table 1's entry, or 0 for mixed signs.
double named_flux(Family family, const FluxSide& L, const FluxSide& R) {
    if (family == Family::mixed) return 0.0;
    return table1_flux(kTable1[classify_table1(L, R).number - 1], L, R);
}

void check_family(CheckTable& t, Family family, StateSampler& sampler) {
    t.note(std::string("--- ") + family_name(family) + " ---");
    SolutionErrors all;
    double named = 0.0;
    long literal_mismatch = 0, missing_states = 0, crossing_states = 0;
    for (int group = 1; group <= group_count(family); ++group) {
        long wrong_pattern = 0;
        std::string pattern;
        for (int k = 0; k < kStatesPerCase; ++k) {
            // With T_L != T_R, every other state has flux curves that cross inside (0, min Phi).
            const bool crossing = family == Family::unequal_T && k % 2 == 0;
            std::pair<FluxSide, FluxSide> q;
            if (!state_in_group(sampler, family, group, kMargin, crossing, q)) {
                ++missing_states;
                continue;
            }
            const auto& [L, R] = q;
            crossing_states += crossing;
            const RiemannSolution s = solve_riemann(L, R);
            all.merge(check_exact_solution(s, modified_godunov_flux({L, R})));
            named = std::max(named, std::fabs(s.flux - named_flux(family, L, R)));
            pattern = expected_pattern_of(family, L, R);
            wrong_pattern += wave_pattern(s) != pattern;
            if (family == Family::equal_T && literal_table1_rows(L, R) != 1 << (group - 1)) ++literal_mismatch;
        }
        t.count(std::string(family_tag(family)) + " " + group_name(family, group) + ": states with waves != " + pattern,
                wrong_pattern, 0);
    }
    t.count(std::string(family_tag(family)) + " states not found inside their region", missing_states, 0);
    if (family == Family::unequal_T) t.count("T!= states with crossing flux curves (3 per case)", crossing_states, 3 * 10);
    t.note("  " + std::to_string(all.solutions) + " exact solutions checked");
    t.at_most(std::string(family_tag(family)) + " Rankine-Hugoniot residual, max", all.rankine_hugoniot, kFluxTol);
    t.count(std::string(family_tag(family)) + " shocks violating Lax", all.lax, 0);
    t.at_most(std::string(family_tag(family)) + " standing wave: |f_L(phi-) - f_R(phi+)|, max", all.standing, kFluxTol);
    t.count(std::string(family_tag(family)) + " standing waves crossing Gamma", all.gamma_crossings, 0);
    t.at_most(std::string(family_tag(family)) + " fans: |lambda_1(phi(xi)) - xi|, max", all.fan, kFluxTol);
    t.count(std::string(family_tag(family)) + " fans not monotone or with wrong order", all.fan_order, 0);
    t.count(std::string(family_tag(family)) + " broken wave chains (joins, speed signs)", all.chain, 0);
    t.at_most(std::string(family_tag(family)) + " |F from mass balance - eq. (63)|, max", all.mass_flux, 10 * kFluxTol);
    t.at_most(std::string(family_tag(family)) + " |F of the solution - eq. (63)|, max", all.eq63, kFluxTol);
    t.at_most(std::string(family_tag(family)) + " |F - flux Table 1 names|, max", named, kFluxTol);
    if (family == Family::equal_T) t.count("T= classifier != Table 1 read literally", literal_mismatch, 0);
}

}  // namespace

int main(int argc, char** argv) {
    return run_over_families(argc, argv,
                             "Table 1: exact Riemann solutions of system (52), case by case, four coefficient families", 20200045,
                             check_family);
}
