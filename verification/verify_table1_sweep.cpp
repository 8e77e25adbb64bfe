// Random sweep of the Riemann problem (52) (Sect. 3): per coefficient family
// (T_L = T_R; T_L != T_R; a_L, a_R < 0; a_L a_R <= 0) 10^5 random state pairs,
// with phi snapped to 0, Phi/2 or Phi on three sides in ten, and for every pair:
//   - the exact solution has every property of verification/table1/exact_solution_checks.hpp,
//     and its flux equals eq. (63); the pairs hit every case (counts printed);
//   - consistency F(u, u) = f(u) of eq. (63) and of the exact solution;
//   - reflection symmetry F(Q_L, Q_R) = -F(Q_R', Q_L') with Q' = (phi, Phi, -a): the concave
//     formula of assumption S1 is the mirror image of eq. (63);
//   - invariant region, for every first-order row of the scheme table (src/segregation/scheme.hpp;
//     interface values, where a row reads them, by the "mean" rule G2): one step of eq. (64) for
//     the middle of three cells at CFL number 1 (half the pairs) or uniform in (0, 1],
//     dt = CFL h / max|a|. A row marked bounded must never leave 0 <= phi <= Phi; a row marked
//     not bounded (the classic fluxes, the paper's claim of Sect. 4.1; Rusanov) must leave it at
//     least once in each family with a_L, a_R of one sign. Consistency and reflection symmetry
//     are checked for every row too. Then the same step on triples that share Phi: with a
//     shared a too (one scalar conservation law, eq. 49) every row must keep the bounds, being a
//     monotone scheme for it at CFL <= 1; with a per cell (T varies, Phi does not) the bounded
//     rows must, and what the others do is printed.
// Continuity across case boundaries: along random segments in state space (Q_R moving with Q_L
// fixed, or Q_L moving), the point where the case (or the sign class) changes is located by
// bisection to |ds| = 2^-52, and the jump of the flux across it is measured.
//
// Run: build/verification/verify_table1_sweep [--data DIR]   (about a second)
#include "harness/check_table.hpp"
#include "harness/program.hpp"
#include "harness/tolerances.hpp"
#include "segregation/scheme.hpp"
#include "table1/exact_solution_checks.hpp"
#include "table1/table1_states.hpp"

#include <cmath>
#include <set>
#include <string>
#include <utility>
#include <vector>

using namespace granseg;
using namespace granseg::verify;

namespace {

constexpr long kPairs = 100000;    // item 4c: at least 10^5 states per family
constexpr long kSegments = 20000;  // random segments searched for case boundaries
constexpr int kBisections = 52;    // |ds| = 2^-52 at the located boundary
// Fluxes are O(|a|) <= 2: round-off, kRoundOff per unit of |a|.
constexpr double kFluxTol = 2 * kRoundOff;
// |F| is Lipschitz in the states: |dF| <= max|a| (|dphi| + |dPhi|) + |da|/4 (|df/dphi|,
// |df/dPhi| <= |a|, |df/da| <= Phi/4). At |ds| = 2^-52 along a segment of length <= 4 that is
// < 1e-14, plus round-off; 1e-12 leaves room. A jump between cases would be O(|a| Phi/4) ~ 0.01.
constexpr double kContinuityTol = 1e-12;
// phi_new of eq. (64) is a sum of three O(1) terms: round-off of a few DBL_EPSILON.
constexpr double kBoundsTol = kRoundOff;

FluxSide mirror(const FluxSide& q) { return {q.phi, q.Phi, -q.a}; }

/// Which case or sign class a pair is in; a change of key along a segment is a boundary.
int boundary_key(const FluxSide& L, const FluxSide& R) {
    const Table1Case c = classify_table1(L, R);
    if (c.number > 0) return c.number + (c.mirrored ? 10 : 0);
    return 100 + mixed_kind(L, R);
}

FluxSide lerp(const FluxSide& a, const FluxSide& b, double s) {
    return {a.phi + s * (b.phi - a.phi), a.Phi + s * (b.Phi - a.Phi), a.a + s * (b.a - a.a)};
}

/// The flux of a scheme-table row between two cells (interface values by the "mean" rule).
double row_flux(const SchemeRow& row, const FluxSide& l, const FluxSide& r) { return row.flux(mean_interface(l, r)); }

/// phi_i after one step of eq. (64) for the middle cell of (q0, q1, q2) with dt/h = cfl/max|a|.
double one_step(const FluxSide& q0, const FluxSide& q1, const FluxSide& q2, double cfl, const SchemeRow& row) {
    const double a_max = std::max({std::fabs(q0.a), std::fabs(q1.a), std::fabs(q2.a)});
    if (a_max == 0.0) return q1.phi;
    return q1.phi - cfl / a_max * (row_flux(row, q1, q2) - row_flux(row, q0, q1));
}

/// The rows of the scheme table whose update is the first-order one above.
std::vector<SchemeRow> first_order_rows() {
    std::vector<SchemeRow> rows;
    for (const SchemeRow& row : kSegregationSchemes)
        if (row.order == 1) rows.push_back(row);
    return rows;
}

bool outside(double phi, double Phi) { return phi < -kBoundsTol || phi > Phi + kBoundsTol; }

/// Per first-order row of the scheme table: steps leaving the bounds, consistency, reflection.
struct RowResult {
    long bounds = 0;
    double consistency = 0.0, reflection = 0.0;
};

struct SweepResult {
    SolutionErrors exact;
    std::vector<long> hits;
    double consistency = 0.0, reflection = 0.0;  // eq. (63) and the exact solution
    std::vector<RowResult> rows;                 // first_order_rows() order
};

SweepResult sweep(Family family, StateSampler& sampler) {
    SweepResult r;
    r.hits.assign(group_count(family) + 1, 0);
    const std::vector<SchemeRow> rows = first_order_rows();
    r.rows.resize(rows.size());
    for (long n = 0; n < kPairs; ++n) {
        const auto [L, R] = sampler.pair(family, true);
        const double F = modified_godunov_flux({L, R});
        r.exact.merge(check_exact_solution(solve_riemann(L, R), F));
        ++r.hits[group_of(family, L, R)];
        for (const FluxSide& q : {L, R}) {
            const double f = flux_of(q);
            r.consistency =
                std::max({r.consistency, std::fabs(modified_godunov_flux({q, q}) - f), std::fabs(solve_riemann(q, q).flux - f)});
        }
        r.reflection = std::max(r.reflection, std::fabs(F + modified_godunov_flux({mirror(R), mirror(L)})));

        const FluxSide X = sampler.pair(family, true).second;  // the right neighbour of R
        const double cfl = n % 2 == 0 ? 1.0 : 1.0 - sampler.uniform(0.0, 1.0);
        for (std::size_t k = 0; k < rows.size(); ++k) {
            RowResult& row = r.rows[k];
            row.bounds += outside(one_step(L, R, X, cfl, rows[k]), R.Phi);
            for (const FluxSide& q : {L, R})
                row.consistency = std::max(row.consistency, std::fabs(row_flux(rows[k], q, q) - flux_of(q)));
            row.reflection =
                std::max(row.reflection, std::fabs(row_flux(rows[k], L, R) + row_flux(rows[k], mirror(R), mirror(L))));
        }
    }
    return r;
}

struct Boundaries {
    double jump_eq63 = 0.0, jump_exact = 0.0;
    std::set<std::pair<int, int>> found;  // pairs of keys met at a located boundary
};

Boundaries locate_boundaries(Family family, StateSampler& sampler) {
    Boundaries b;
    for (long n = 0; n < kSegments; ++n) {
        const auto p = sampler.pair(family, false), q = sampler.pair(family, false);
        const bool move_right = n % 2 == 0;  // move Q_R (Q_L fixed) or Q_L (Q_R fixed)
        auto at = [&](double s) {
            return move_right ? std::make_pair(p.first, lerp(p.second, q.second, s))
                              : std::make_pair(lerp(p.first, q.first, s), p.second);
        };
        double lo = 0.0, hi = 1.0;
        const int key_lo = boundary_key(at(lo).first, at(lo).second);
        if (boundary_key(at(hi).first, at(hi).second) == key_lo) continue;
        for (int k = 0; k < kBisections; ++k) {
            const double mid = 0.5 * (lo + hi);
            (boundary_key(at(mid).first, at(mid).second) == key_lo ? lo : hi) = mid;
        }
        const auto [L0, R0] = at(lo);
        const auto [L1, R1] = at(hi);
        b.jump_eq63 = std::max(b.jump_eq63, std::fabs(modified_godunov_flux({L1, R1}) - modified_godunov_flux({L0, R0})));
        b.jump_exact = std::max(b.jump_exact, std::fabs(solve_riemann(L1, R1).flux - solve_riemann(L0, R0).flux));
        const int k0 = boundary_key(L0, R0), k1 = boundary_key(L1, R1);
        b.found.insert({std::min(k0, k1), std::max(k0, k1)});
    }
    return b;
}

/// Groups of the family (cases, or the two sign classes of positive measure) that no located
/// boundary touches.
long groups_without_boundary(Family family, const Boundaries& b) {
    long missing = 0;
    const int groups = family == Family::mixed ? 2 : 10;  // a = 0 classes are boundaries themselves
    for (int g = 1; g <= groups; ++g) {
        const int key = family == Family::mixed ? 100 + g - 1 : g + (family == Family::negative ? 10 : 0);
        bool touched = false;
        for (const auto& [k0, k1] : b.found) touched = touched || k0 == key || k1 == key;
        missing += !touched;
    }
    return missing;
}

void check_family(CheckTable& t, Family family, StateSampler& sampler) {
    const std::string tag = family_tag(family);
    t.note(std::string("--- ") + family_name(family) + ": " + std::to_string(kPairs) + " random pairs ---");
    const SweepResult r = sweep(family, sampler);
    std::string counts = " ";
    long not_hit = 0;
    for (int g = 1; g <= group_count(family); ++g) {
        counts +=
            " " +
            (family == Family::mixed ? std::string(mixed_kind_name(g - 1)) + ":" : std::string(1, kTable1[g - 1].region) + ":") +
            std::to_string(r.hits[g]);
        not_hit += r.hits[g] == 0;
    }
    t.note("  pairs per " + std::string(family == Family::mixed ? "sign class" : "region") + ":" + counts);
    t.count(tag + " cases (sign classes) not hit", not_hit, 0);
    t.at_most(tag + " |F of the exact solution - eq. (63)|, max", r.exact.eq63, kFluxTol);
    t.at_most(tag + " |F from mass balance - eq. (63)|, max", r.exact.mass_flux, 10 * kFluxTol);
    t.at_most(tag + " RH and standing-wave residuals, max", std::max(r.exact.rankine_hugoniot, r.exact.standing), kFluxTol);
    t.count(tag + " Lax, Gamma-crossing, fan and wave-chain violations",
            r.exact.lax + r.exact.gamma_crossings + r.exact.chain + r.exact.fan_order, 0);
    t.at_most(tag + " consistency |F(u, u) - f(u)|, max", r.consistency, kFluxTol);
    t.at_most(tag + " reflection |F(L, R) + F(R', L')|, max", r.reflection, kFluxTol);
    const std::vector<SchemeRow> rows = first_order_rows();
    std::string violations;
    for (std::size_t k = 0; k < rows.size(); ++k) {
        const std::string name = tag + " " + std::string(rows[k].name);
        violations += " " + std::string(rows[k].name) + " " + std::to_string(r.rows[k].bounds);
        t.at_most(name + ": consistency and reflection, max", std::max(r.rows[k].consistency, r.rows[k].reflection), kFluxTol);
        if (rows[k].bounded)
            t.count(name + ": eq. (64) steps leaving 0 <= phi <= Phi", r.rows[k].bounds, 0);
        else if (family != Family::mixed)  // a_L a_R <= 0: whether a row breaks the bounds there is not claimed
            t.at_least(name + ": eq. (64) steps leaving 0 <= phi <= Phi", r.rows[k].bounds, 1);
    }
    t.note("  eq. (64) steps leaving 0 <= phi <= Phi, of " + std::to_string(kPairs) + ":" + violations);

    const Boundaries b = locate_boundaries(family, sampler);
    t.note("  " + std::to_string(b.found.size()) + " kinds of case boundary located along " + std::to_string(kSegments) +
           " segments");
    t.at_most(tag + " flux jump across case boundaries, eq. (63)", b.jump_eq63, kContinuityTol);
    t.at_most(tag + " flux jump across case boundaries, exact", b.jump_exact, kContinuityTol);
    t.count(tag + " cases without a located boundary", groups_without_boundary(family, b), 0);
}

/// One step of eq. (64) on triples with one Phi (and one a if `shared_a`): violations per row.
std::vector<long> shared_Phi_violations(StateSampler& sampler, bool shared_a) {
    const std::vector<SchemeRow> rows = first_order_rows();
    std::vector<long> violations(rows.size(), 0);
    for (long n = 0; n < kPairs; ++n) {
        const double Phi = sampler.uniform(0.02, 0.98), sign = n % 2 ? -1.0 : 1.0;
        const double a = sign * std::sqrt(sampler.uniform(0.05, 4.0));
        FluxSide q[3];
        for (FluxSide& side : q) {
            side = sampler.side(shared_a ? a : sign * std::sqrt(sampler.uniform(0.05, 4.0)), true);
            side.phi *= Phi / side.Phi;  // the shared Phi, same phi/Phi
            side.Phi = Phi;
        }
        const double cfl = n % 4 < 2 ? 1.0 : 1.0 - sampler.uniform(0.0, 1.0);
        for (std::size_t k = 0; k < rows.size(); ++k) violations[k] += outside(one_step(q[0], q[1], q[2], cfl, rows[k]), Phi);
    }
    return violations;
}

void check_shared_Phi(CheckTable& t) {
    StateSampler sampler(20200047);
    const std::vector<SchemeRow> rows = first_order_rows();
    t.note("--- one Phi in all three cells: " + std::to_string(kPairs) + " random triples each ---");
    const std::vector<long> scalar = shared_Phi_violations(sampler, true), varying = shared_Phi_violations(sampler, false);
    std::string counts;
    for (std::size_t k = 0; k < rows.size(); ++k) {
        const std::string name(rows[k].name);
        t.count("one Phi, one a: " + name + ": steps leaving 0 <= phi <= Phi", scalar[k], 0);
        if (rows[k].bounded) t.count("one Phi, a per cell: " + name + ": steps leaving 0 <= phi <= Phi", varying[k], 0);
        counts += " " + name + " " + std::to_string(varying[k]);
    }
    t.note("  one Phi, a per cell (T varies), steps leaving 0 <= phi <= Phi:" + counts);
}

}  // namespace

int main(int argc, char** argv) {
    return run_over_families(argc, argv, "Table 1: random sweep of the Riemann problem (52), four coefficient families", 20200046,
                             check_family, check_shared_Phi);
}
