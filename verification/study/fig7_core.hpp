// The paper's statements about Fig. 7 as checks on the finest run of the study,
// each bound widened by the quantity's uncertainty (grid plus dt), and the core: how much
// of its material a passive tracer says stays there, and which mechanism moves phi_hat in it.
//
//   a. "a ring of small particles":      ring - U >= the initial mixture
//   b. "large particles at the wall":    periphery + U <= the initial mixture
//   c. Fig. 7d, denser mixed regions:    (contrast - U) / spread >= 2 (the criterion of verify_tumbler e)
//   d. "a mainly untouched core":        the tracer's retained share - U >= 1/2
//   e. untouched near the axis:          axis share - U <= the initial mixture (one-sided)
// and first that dt_max set at least 99 % of every run's steps (dt ~ h, fig7_study.hpp).
// The core's change C(h1) - m0 (m0 the initial mixture) is split into
//   discretisation  C(h1) - C_ext (established only where the default series is monotone and its
//                   limit inside [0, 1]),
//   floor           C(h1) - C(h1, lower T_floor): segregation where T sits at its floor
//                   (established where it exceeds twice its sampling error),
//   the model       the rest: creep below the layer carrying sorted material in, and segregation
//                   above the floor (established only with the discretisation part); the tracer's
//                   exchange 1 - K_ext measures the creep,
// each printed "not established" where it is not, and the largest established part named.
#pragma once

#include "study/fig7_report.hpp"

namespace granseg::verify {

/// Prints the check table (a-d) and the core's split, writes DIR/fig7_core.md, and returns the
/// exit status of the checks (0 if all hold).
int check_fig7_statements(const Fig7Analysis& analysis, const Fig7Options& options);

}  // namespace granseg::verify
