// Riemann states for the Table 1 verification programs (verify_table1, verify_table1_oracle,
// verify_table1_figures): the four families of flux coefficients, random states in each, states
// well inside one region, and what each case of Table 1 names (its waves and its flux).
// Header-only: the programs are single files, and this is what they share.
#pragma once

#include "harness/check_table.hpp"
#include "harness/program.hpp"
#include "riemann/flux_curves.hpp"
#include "riemann/segregation_flux.hpp"
#include "riemann/table1_classifier.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <random>
#include <string>
#include <utility>

namespace granseg::verify {

/// The coefficient families of the Table 1 checks: a = S sqrt(T) on each side.
enum class Family { equal_T, unequal_T, negative, mixed };
constexpr Family kFamilies[] = {Family::equal_T, Family::unequal_T, Family::negative, Family::mixed};

inline const char* family_name(Family f) {
    switch (f) {
        case Family::equal_T:
            return "a_L = a_R > 0 (T_L = T_R)";
        case Family::unequal_T:
            return "a_L, a_R > 0, T_L != T_R";
        case Family::negative:
            return "a_L, a_R < 0 (concave, mirrored cases)";
        case Family::mixed:
            return "a_L a_R <= 0 (sign change or zero)";
    }
    return "?";
}

inline const char* family_tag(Family f) {
    switch (f) {
        case Family::equal_T:
            return "T=";
        case Family::unequal_T:
            return "T!=";
        case Family::negative:
            return "a<0";
        case Family::mixed:
            return "mix";
    }
    return "?";
}

/// What one row of Table 1 names. The interface flux is the table's last column (restored in
/// docs/paper_notes.md, section 2). The wave pattern (S shock, R rarefaction, C standing wave, left to
/// right) is derived in docs/sect3_riemann.md, section 3; the paper names it for case 3 only
/// (caption of Fig. 5: rarefaction, standing wave, shock).
enum class Table1Flux { f_QR, f_QL, fL_min, fR_min };
struct Table1Row {
    int number;
    char region;
    const char* pattern;
    Table1Flux flux;
};
inline constexpr Table1Row kTable1[10] = {
    {1, 'A', "SC", Table1Flux::f_QR},     {2, 'B', "RC", Table1Flux::f_QR},    {3, 'C', "RCS", Table1Flux::fL_min},
    {4, 'D', "RCR", Table1Flux::fL_min},  {5, 'E', "RCR", Table1Flux::fR_min}, {6, 'F', "SCR", Table1Flux::fR_min},
    {7, 'G', "SC", Table1Flux::f_QR},     {8, 'H', "CS", Table1Flux::f_QL},    {9, 'I', "CR", Table1Flux::f_QL},
    {10, 'J', "SCR", Table1Flux::fR_min},
};

/// The problem in the convex frame: itself if a_L, a_R > 0, its mirror image (Q_R, -a_R | Q_L,
/// -a_L) if a_L, a_R < 0 (docs/assumptions.md S3).
inline std::pair<FluxSide, FluxSide> convex_frame(const FluxSide& L, const FluxSide& R) {
    if (L.a < 0.0 && R.a < 0.0) return {{R.phi, R.Phi, -R.a}, {L.phi, L.Phi, -L.a}};
    return {L, R};
}

/// The flux Table 1 gives for row `row`, evaluated in the convex frame (negated back if mirrored).
inline double table1_flux(const Table1Row& row, const FluxSide& L, const FluxSide& R) {
    const auto [cL, cR] = convex_frame(L, R);
    double F = 0.0;
    switch (row.flux) {
        case Table1Flux::f_QR:
            F = segregation_flux(cR.phi, cR.Phi, cR.a);
            break;
        case Table1Flux::f_QL:
            F = segregation_flux(cL.phi, cL.Phi, cL.a);
            break;
        case Table1Flux::fL_min:
            F = -0.25 * cL.a * cL.Phi;
            break;
        case Table1Flux::fR_min:
            F = -0.25 * cR.a * cR.Phi;
            break;
    }
    return cL.a == L.a ? F : -F;
}

/// The expected wave pattern of a row in the frame of the problem: the mirror image of a case
/// runs its waves in the opposite order.
inline std::string expected_pattern(const Table1Row& row, bool mirrored) {
    std::string p = row.pattern;
    if (mirrored) std::reverse(p.begin(), p.end());
    return p;
}

/// Sign classes of the mixed family (a_L a_R <= 0); the "cases" its checks are grouped by.
constexpr int kMixedKinds = 7;
inline const char* mixed_kind_name(int k) {
    static const char* names[kMixedKinds] = {"a_L > 0 > a_R", "a_L < 0 < a_R", "a_L > 0 = a_R", "a_L < 0 = a_R",
                                             "a_L = 0 < a_R", "a_L = 0 > a_R", "a_L = a_R = 0"};
    return names[k];
}
inline int mixed_kind(const FluxSide& L, const FluxSide& R) {
    auto sign = [](double a) { return (a > 0.0) - (a < 0.0); };
    const int sL = sign(L.a), sR = sign(R.a);
    if (sL != 0 && sR != 0) return sL > 0 ? 0 : 1;
    if (sL != 0) return sL > 0 ? 2 : 3;
    if (sR != 0) return sR > 0 ? 4 : 5;
    return 6;
}

/// Random states of one family. Phi in [0.02, 0.98], phi = psi Phi with psi uniform in [0, 1]
/// (with `snap`, psi is 0, 1/2 or 1 three times in ten: empty, on Gamma, full), T in [0.05, 4].
class StateSampler {
public:
    explicit StateSampler(std::uint64_t seed) : rng_(seed) {}

    double uniform(double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng_); }

    FluxSide side(double a, bool snap) {
        const double Phi = uniform(0.02, 0.98);
        double psi = uniform(0.0, 1.0);
        if (snap && uniform(0.0, 1.0) < 0.3) psi = 0.5 * std::floor(uniform(0.0, 3.0));
        return {psi * Phi, Phi, a};
    }

    std::pair<FluxSide, FluxSide> pair(Family family, bool snap) {
        const double sL = std::sqrt(uniform(0.05, 4.0)), sR = std::sqrt(uniform(0.05, 4.0));  // sqrt(T)
        switch (family) {
            case Family::equal_T:
                return {side(sL, snap), side(sL, snap)};
            case Family::unequal_T:
                return {side(sL, snap), side(sR, snap)};
            case Family::negative:
                return {side(-sL, snap), side(-sR, snap)};
            case Family::mixed:
                break;
        }
        const int kind = static_cast<int>(std::floor(uniform(0.0, kMixedKinds)));
        static const int signs[kMixedKinds][2] = {{1, -1}, {-1, 1}, {1, 0}, {-1, 0}, {0, 1}, {0, -1}, {0, 0}};
        return {side(signs[kind][0] * sL, snap), side(signs[kind][1] * sR, snap)};
    }

private:
    std::mt19937_64 rng_;
};

/// How far a pair lies from every boundary between the regions of Table 1: the smallest of
/// |phi/Phi - 1/2| on both sides and the pairwise gaps between f(Q_L), f(Q_R), f_L^min, f_R^min
/// (relative to the largest |f_min|). For the mixed family: the distance of phi/Phi from 0 and 1.
inline double region_margin(const FluxSide& L, const FluxSide& R) {
    const double psi_L = L.phi / L.Phi, psi_R = R.phi / R.Phi;
    if (L.a * R.a <= 0.0) return std::min({psi_L, 1.0 - psi_L, psi_R, 1.0 - psi_R});
    const auto [cL, cR] = convex_frame(L, R);
    const double q[4] = {segregation_flux(cL.phi, cL.Phi, cL.a), segregation_flux(cR.phi, cR.Phi, cR.a), -0.25 * cL.a * cL.Phi,
                         -0.25 * cR.a * cR.Phi};
    const double scale = 0.25 * std::max(cL.a * cL.Phi, cR.a * cR.Phi);
    double m = std::min(std::fabs(psi_L - 0.5), std::fabs(psi_R - 0.5));
    for (int i = 0; i < 4; ++i)
        for (int j = i + 1; j < 4; ++j) m = std::min(m, std::fabs(q[i] - q[j]) / scale);
    return m;
}

/// True if the flux curves f_L, f_R cross inside (0, min(Phi_L, Phi_R)): the other root of
/// f_L - f_R = phi (phi (a_L/Phi_L - a_R/Phi_R) - (a_L - a_R)) lies there (possible only for
/// a_L != a_R, i.e. T_L != T_R).
inline bool curves_cross(const FluxSide& L, const FluxSide& R) {
    const double c = L.a / L.Phi - R.a / R.Phi;
    if (c == 0.0) return false;
    const double phi_x = (L.a - R.a) / c;
    return phi_x > 0.02 * std::min(L.Phi, R.Phi) && phi_x < 0.98 * std::min(L.Phi, R.Phi);
}

/// The group a pair is checked in: its Table 1 case (1..10) or, in the mixed family, its sign
/// class (1..7).
inline int group_of(Family family, const FluxSide& L, const FluxSide& R) {
    return family == Family::mixed ? mixed_kind(L, R) + 1 : classify_table1(L, R).number;
}

inline int group_count(Family family) { return family == Family::mixed ? kMixedKinds : 10; }

inline std::string group_name(Family family, int group) {
    if (family == Family::mixed) return mixed_kind_name(group - 1);
    return "case " + std::to_string(group) + " (" + std::string(1, kTable1[group - 1].region) + ")";
}

/// A pair of the family in the given group with region_margin >= margin (and, if `crossing`,
/// crossing flux curves), by rejection sampling. Returns false after `attempts` draws.
inline bool state_in_group(StateSampler& sampler, Family family, int group, double margin, bool crossing,
                           std::pair<FluxSide, FluxSide>& out, long attempts = 200000) {
    for (long k = 0; k < attempts; ++k) {
        const auto p = sampler.pair(family, false);
        if (group_of(family, p.first, p.second) != group) continue;
        if (region_margin(p.first, p.second) < margin) continue;
        if (crossing && !curves_cross(p.first, p.second)) continue;
        out = p;
        return true;
    }
    return false;
}

/// The main() of a Table 1 program: one check table, `check` for every family with one sampler
/// seeded by `seed` (so every run draws the same states), then `after`.
inline int run_over_families(int argc, char** argv, const std::string& title, std::uint64_t seed,
                             const std::function<void(CheckTable&, Family, StateSampler&)>& check,
                             const std::function<void(CheckTable&)>& after = {}) {
    parse_program_options(argc, argv);  // --data is accepted; these programs write no data
    CheckTable t(title);
    StateSampler sampler(seed);
    for (Family family : kFamilies) check(t, family, sampler);
    if (after) after(t);
    return t.finish();
}

}  // namespace granseg::verify
