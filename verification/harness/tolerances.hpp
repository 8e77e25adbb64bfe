// Tolerances shared by several verification programs, each with its reason. A program-specific
// tolerance is a named constant at the top of that program, with its reason beside it.
#pragma once

#include <cfloat>

namespace granseg::verify {

/// Relative error of a closed-form expression of a few dozen floating-point operations:
/// each operation adds at most DBL_EPSILON/2, and 64 leaves room for cancellation in sums.
constexpr double kRoundOff = 64 * DBL_EPSILON;

}  // namespace granseg::verify
