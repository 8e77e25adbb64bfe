// Slope limiters of the limited linear reconstructions: the segregation flux at second order
// (segregation/reconstruction.hpp) and the high-resolution transport of Phi and phi_hat
// (transport/muscl_hancock.hpp).
//
//   solves      nothing over time: a limited slope from two one-sided differences
//   inputs      the differences to the lower and to the upper neighbour, the limiter
//   outputs     the slope (a difference per cell)
//   invariants  0 at an extremum; the same sign as both differences otherwise; q +- slope/2 lies
//               between the neighbours' values (minmod, mc); limited_slope(c a, c b) = c limited_slope(a, b)
//               for c > 0 (a uniform scaling of the field scales the reconstruction)
#pragma once

#include "core/choice.hpp"

#include <string>
#include <vector>

namespace granseg {

/// Slope limiter of a limited linear reconstruction.
enum class Limiter { minmod, mc };
inline constexpr Choice<Limiter> kLimiters[] = {
    {Limiter::minmod, "minmod", "the smaller one-sided slope (most diffusive)"},
    {Limiter::mc, "mc", "monotonized central (default)"},
};

inline std::vector<std::string> limiter_names() { return choice_names(kLimiters); }
inline Limiter parse_limiter(const std::string& name) { return parse_choice(kLimiters, name, "limiter"); }
inline std::string limiter_name(Limiter l) { return choice_name(kLimiters, l); }

/// The limited slope from the one-sided differences `below` and `above` (0 at an extremum).
double limited_slope(double below, double above, Limiter limiter);

}  // namespace granseg
