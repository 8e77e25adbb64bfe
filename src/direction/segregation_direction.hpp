// The segregation direction of Sect. 2.3: from the velocity gradient and the velocity, the
// normal d_s of the plane of maximum shear rate that is most nearly parallel to the flow.
//
//   solves      steps 1-3 of Sect. 2.3 (eqs. 11, 13, 36): the direction d_s of segregation
//   inputs      the velocity gradient grad u (3x3, 1/s) and the velocity u (m/s), relative to the walls
//   outputs     SegregationDirection: d_s, P = d_s d_s^T, the eigen data, gamma_dot, a status
//   invariants  |d_s| = 1, or d_s = 0 where the status says no direction exists; P does not depend
//               on the signs of d_s, u or the eigenvectors
//
// Conventions: grad(i, j) = d u_i / d x_j, the full velocity gradient kappa = grad u of eq. (11),
// 3x3 in (x, y, z); u in m/s, grad in 1/s. A 2-D flow in the x-z plane is the special case with
// the y row and column zero (DirectionOptions::planar_xz restricts the eigenproblem to that plane).
//
// The procedure (paper, Sect. 2.3, steps 1-3):
//   1. kappa^s = (grad + grad^T)/2 (eq. 13); eigenvalues kappa_min <= kappa_mid <= kappa_max;
//   2. unit eigenvectors k_max, k_min (Eigen's SelfAdjointEigenSolver);
//   3. candidates d_+ = (k_max + k_min)/sqrt(2), d_- = (k_max - k_min)/sqrt(2), the normals of the
//      two planes of maximum shear rate (the paper's k_max +/- k_min, normalised); d_s is the one
//      more orthogonal to u, i.e. with the smaller |d . u|.
// P = d_s d_s^T (eq. 36) does not depend on the sign of d_s, u or the eigenvectors. For printing,
// d_s is signed so that its component of largest magnitude is positive.
//
// WHICH u AND grad: the velocity relative to the walls that drive the flow. In the rotating drum
// that is the rotating-frame velocity u_rel = u - Omega x x (docs/assumptions.md D3).
// kappa^s is the same in every frame; u and gamma_dot = sqrt(grad : grad)
// (eq. 43, full gradient) are not, so pass the rotating-frame u and grad.
//
// Undefined or ill-conditioned cases (docs/assumptions.md D1-D4), reported by `status`:
//   no_shear            kappa_max - kappa_min <= shear_threshold: rigid motion, isotropic strain;
//                       no shear plane exists. d_s = 0: no segregation.
//   repeated_eigenvalue (middle gap)/(kappa_max - kappa_min) < min_relative_gap: k_max or k_min is
//                       not determined; the maximum-shear planes form a cone. d_s = 0.
//   zero_velocity       |u| <= min_speed: step 3 cannot choose; gradient rule (below).
//   equal_candidates    | |d_+ . u| - |d_- . u| | <= tie_tolerance |u|: gradient rule.
//   undetermined        the gradient rule ties as well. d_s = 0.
// Gradient rule: the candidate d with the larger |grad d|, the direction across which the
// velocity changes most, i.e. the normal of the shear layers (e_z in simple shear u = (gz, 0, 0)).
#pragma once

#include <Eigen/Core>

namespace granseg {

/// Which eigen solver of Eigen computes the extreme eigenpairs.
enum class EigenMethod {
    iterative,   // SelfAdjointEigenSolver::compute: tridiagonalisation + implicit QL (default)
    closed_form  // SelfAdjointEigenSolver::computeDirect: trigonometric closed form for 3x3 / 2x2
};

enum class DirectionStatus { ok, no_shear, repeated_eigenvalue, zero_velocity, equal_candidates, undetermined };

/// Name of a status as printed by `granseg direction` ("ok", "no_shear", ...).
const char* to_string(DirectionStatus status);

/// Thresholds of the undefined cases (docs/assumptions.md D1-D4) and the solver choice.
struct DirectionOptions {
    double shear_threshold = 1e-6;   // 1/s; at or below: no shear (D1)
    double min_relative_gap = 1e-6;  // below: repeated extreme eigenvalue (D2)
    double tie_tolerance = 1e-12;    // relative to |u| (and to |grad d| in the gradient rule) (D4)
    double min_speed = 0.0;          // m/s; |u| at or below: u = 0 (D3)
    EigenMethod method = EigenMethod::iterative;
    bool planar_xz = false;  // 2-D: eigenpairs of the x-z block of kappa^s only
};

/// The extreme eigenpairs of kappa^s (steps 1-2).
struct ExtremeEigenpairs {
    double kappa_min = 0, kappa_mid = 0, kappa_max = 0;  // kappa_mid = kappa_min in planar mode
    Eigen::Vector3d k_min = Eigen::Vector3d::Zero(), k_max = Eigen::Vector3d::Zero();
    double relative_gap = 1;  // min(kappa_max - kappa_mid, kappa_mid - kappa_min)/(kappa_max - kappa_min); 1 in 2-D
};

/// Step 3 alone: which candidate, and why.
struct CandidateChoice {
    DirectionStatus status = DirectionStatus::ok;
    Eigen::Vector3d d_plus, d_minus;                // (k_max +/- k_min)/sqrt(2)
    Eigen::Vector3d d_s = Eigen::Vector3d::Zero();  // the chosen one, sign-normalised; 0 if undetermined
};

/// Everything the procedure computes at one point.
struct SegregationDirection {
    DirectionStatus status = DirectionStatus::ok;
    Eigen::Vector3d d_s = Eigen::Vector3d::Zero();     // unit, or 0 where there is no segregation
    Eigen::Matrix3d strain = Eigen::Matrix3d::Zero();  // kappa^s (eq. 13)
    ExtremeEigenpairs eigen;
    Eigen::Vector3d d_plus = Eigen::Vector3d::Zero(), d_minus = Eigen::Vector3d::Zero();  // candidates
    double principal_shear = 0;  // kappa_max - kappa_min (1/s): gamma_dot of simple shear
    double gamma_dot = 0;        // sqrt(grad : grad) (eq. 43, full gradient, frame-dependent)

    /// True if d_s is defined (status ok, zero_velocity or equal_candidates).
    bool segregates() const { return d_s.squaredNorm() > 0.0; }
    /// P = d_s d_s^T (eq. 36); the zero matrix where there is no segregation.
    Eigen::Matrix3d P() const { return d_s * d_s.transpose(); }
};

/// kappa^s = (grad + grad^T)/2 (eq. 13).
Eigen::Matrix3d strain_rate(const Eigen::Matrix3d& grad);

/// gamma_dot = sqrt(kappa : kappa) with kappa = grad (eqs. 11, 43).
double shear_rate(const Eigen::Matrix3d& grad);

/// Steps 1-2: eigenvalues and the eigenvectors of the largest and smallest eigenvalue.
ExtremeEigenpairs extreme_eigenpairs(const Eigen::Matrix3d& strain, const DirectionOptions& options = {});

/// Step 3: the candidate more orthogonal to u (gradient rule on a tie, see above).
CandidateChoice choose_candidate(const Eigen::Vector3d& k_max, const Eigen::Vector3d& k_min, const Eigen::Matrix3d& grad,
                                 const Eigen::Vector3d& u, const DirectionOptions& options = {});

/// The whole procedure. Throws InputError if grad or u has a non-finite entry.
SegregationDirection segregation_direction(const Eigen::Matrix3d& grad, const Eigen::Vector3d& u,
                                           const DirectionOptions& options = {});

/// v with the sign that makes its component of largest magnitude positive (first on a tie).
Eigen::Vector3d sign_normalised(const Eigen::Vector3d& v);

}  // namespace granseg
