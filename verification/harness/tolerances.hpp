// Tolerances shared by several verification programs, each with its reason. A program-specific
// tolerance is a named constant at the top of that program, with its reason beside it.
#pragma once

#include <cfloat>

namespace granseg::verify {

/// Relative error of a closed-form expression of a few dozen floating-point operations:
/// each operation adds at most DBL_EPSILON/2, and 64 leaves room for cancellation in sums.
constexpr double kRoundOff = 64 * DBL_EPSILON;

/// Fig. 7d, "denser where mixed": the contrast of Phi between mixed and pure cells at equal depth
/// must be at least this many spreads (the pooled standard deviation of Phi within a kind and a
/// depth bin, the noise of one cell): a difference of bin means that exceeds two such spreads is
/// no noise. One criterion for verify_tumbler e, bench_tumbler e and the Fig. 7 study's check i,
/// which docs/sect4.2_fig7_study.md quotes from verify_tumbler's table.
constexpr double kContrastSpreads = 2.0;

}  // namespace granseg::verify
