// The paper's statements about Fig. 7 as checks on the finest run of the study,
// each bound widened by the quantity's uncertainty (grid GCI plus dt GCI), and the core: how much
// of its material a passive tracer says stays there, and which mechanism moves phi_hat in it.
//
//   a. "a ring of small particles":      ring - U >= the initial mixture
//   b. "large particles at the wall":    periphery + U <= the initial mixture
//   c. Fig. 7d, denser mixed regions:    (contrast - U) / spread >= 2 (the criterion of verify_tumbler e)
//   d. "a mainly untouched core":        the tracer's retained share - U >= 1/2
// The core's change C(h1) - m0 (m0 the initial mixture) is split into
//   discretisation  C(h1) - C_ext (the default series; its GCI when not monotone),
//   floor           C(h1) - C(h1, lower T_floor): segregation where T sits at its floor,
//   the model       the rest: creep below the layer carrying sorted material in, and segregation
//                   above the floor; the tracer's exchange 1 - K_ext measures the creep,
// and the largest of the three named.
#pragma once

#include "harness/fig7_report.hpp"

namespace granseg::verify {

/// Prints the check table (a-d) and the core's split, writes DIR/fig7_core.md, and returns the
/// exit status of the checks (0 if all hold).
int check_fig7_statements(const Fig7Analysis& analysis, const Fig7Options& options);

}  // namespace granseg::verify
