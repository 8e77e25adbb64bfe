// The paper's statements about Fig. 7 as checks on the finest run of the study, each bound widened
// by the quantity's band (grid plus dt uncertainty, fig7_report.hpp), and the core: how much of its
// material stays there, by material points and a passive tracer, and the parts of its change that
// runs measure. The letters continue after verify_tumbler's a-e, so that the two tables never
// share one:
//
//   f. dt ~ h:                           dt_max set at least 99 % of every run's steps (fig7_study.hpp)
//   g. "a ring of small particles":      ring - band >= the initial mixture
//   h. "large particles at the wall":    periphery + band <= the initial mixture
//   i. Fig. 7d, denser mixed regions:    (contrast - band) / spread >= 2 (the criterion of verify_tumbler e)
//   j. "a mainly untouched core":        the material points' retained share - U >= 1/2
//
// Each bound is harder to meet as the band grows: a check cannot pass by being uncertain. j rests
// on the material points, which carry no numerical diffusion and whose series the study fits
// inside [0, 1]; a series whose limit falls outside its range gives a check the range of its
// values instead of its fit (check_uncertainty). The share near the axis is reported, not checked:
// "untouched" would need it within a stated distance of the mixture with its band, and no such
// bound follows from the paper.
//
// The core's change C(h1) - m0 (m0 the initial mixture) is split only into measured parts:
//   discretisation  C(h1) - C_ext (established only where the default series is monotone and its
//                   limit inside [0, 1]),
//   floor           C(h1) - C(h1, lower T_floor): segregation where T sits at its floor
//                   (established where it exceeds twice its sampling error),
// and what the material points and the tracer say of the core's material; the remainder is
// printed as a remainder, attributed to no mechanism.
#pragma once

#include "study/fig7_report.hpp"

namespace granseg::verify {

/// Prints the check table (f-j) and the core's split, writes DIR/fig7_core.md and DIR/fig7_checks.md
/// (the check table as markdown), and returns the exit status of the checks (0 if all hold).
int check_fig7_statements(const Fig7Analysis& analysis, const Fig7Options& options);

}  // namespace granseg::verify
