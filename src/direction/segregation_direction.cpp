#include "direction/segregation_direction.hpp"

#include "core/error.hpp"

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>

namespace granseg {

const char* to_string(DirectionStatus status) {
    switch (status) {
        case DirectionStatus::ok:
            return "ok";
        case DirectionStatus::no_shear:
            return "no_shear";
        case DirectionStatus::repeated_eigenvalue:
            return "repeated_eigenvalue";
        case DirectionStatus::zero_velocity:
            return "zero_velocity";
        case DirectionStatus::equal_candidates:
            return "equal_candidates";
        case DirectionStatus::undetermined:
            return "undetermined";
    }
    return "?";
}

Eigen::Matrix3d strain_rate(const Eigen::Matrix3d& grad) {
    return 0.5 * (grad + grad.transpose());  // (eq. 13)
}

double shear_rate(const Eigen::Matrix3d& grad) {
    return std::sqrt(grad.cwiseProduct(grad).sum());  // (eq. 43) with kappa = grad u (eq. 11)
}

Eigen::Vector3d sign_normalised(const Eigen::Vector3d& v) {
    int largest = 0;
    for (int i = 1; i < 3; ++i)
        if (std::fabs(v(i)) > std::fabs(v(largest))) largest = i;
    return v(largest) < 0.0 ? Eigen::Vector3d(-v) : v;
}

namespace {

/// Eigen's solver for a fixed-size symmetric matrix, by the chosen method.
template <class Matrix>
Eigen::SelfAdjointEigenSolver<Matrix> solve(const Matrix& A, EigenMethod method) {
    Eigen::SelfAdjointEigenSolver<Matrix> es;
    if (method == EigenMethod::closed_form)
        es.computeDirect(A);
    else
        es.compute(A);
    return es;
}

}  // namespace

ExtremeEigenpairs extreme_eigenpairs(const Eigen::Matrix3d& strain, const DirectionOptions& options) {
    ExtremeEigenpairs e;
    if (options.planar_xz) {
        // 2-D: the x-z block; eigenvectors embedded with y = 0 (docs/assumptions.md D5).
        Eigen::Matrix2d block;
        block << strain(0, 0), strain(0, 2), strain(2, 0), strain(2, 2);
        const auto es = solve(block, options.method);
        e.kappa_min = e.kappa_mid = es.eigenvalues()(0);
        e.kappa_max = es.eigenvalues()(1);
        e.k_min = Eigen::Vector3d(es.eigenvectors()(0, 0), 0.0, es.eigenvectors()(1, 0));
        e.k_max = Eigen::Vector3d(es.eigenvectors()(0, 1), 0.0, es.eigenvectors()(1, 1));
        e.relative_gap = 1.0;
        return e;
    }
    const auto es = solve(strain, options.method);  // eigenvalues in increasing order
    e.kappa_min = es.eigenvalues()(0);
    e.kappa_mid = es.eigenvalues()(1);
    e.kappa_max = es.eigenvalues()(2);
    e.k_min = es.eigenvectors().col(0);
    e.k_max = es.eigenvectors().col(2);
    const double spread = e.kappa_max - e.kappa_min;
    e.relative_gap = spread > 0.0 ? std::min(e.kappa_max - e.kappa_mid, e.kappa_mid - e.kappa_min) / spread : 0.0;
    return e;
}

CandidateChoice choose_candidate(const Eigen::Vector3d& k_max, const Eigen::Vector3d& k_min, const Eigen::Matrix3d& grad,
                                 const Eigen::Vector3d& u, const DirectionOptions& options) {
    CandidateChoice c;
    c.d_plus = (k_max + k_min) / std::sqrt(2.0);  // Sect. 2.3, step 3: k_max +/- k_min
    c.d_minus = (k_max - k_min) / std::sqrt(2.0);

    // The paper's rule: the candidate most orthogonal to u.
    const double speed = u.norm();
    const double along_plus = std::fabs(c.d_plus.dot(u)), along_minus = std::fabs(c.d_minus.dot(u));
    if (speed <= options.min_speed) {
        c.status = DirectionStatus::zero_velocity;
    } else if (std::fabs(along_plus - along_minus) <= options.tie_tolerance * speed) {
        c.status = DirectionStatus::equal_candidates;
    } else {
        c.d_s = sign_normalised(along_plus < along_minus ? c.d_plus : c.d_minus);
        return c;
    }

    // Gradient rule (D3, D4): the candidate across which the velocity changes most.
    const double change_plus = (grad * c.d_plus).norm(), change_minus = (grad * c.d_minus).norm();
    if (std::fabs(change_plus - change_minus) <= options.tie_tolerance * std::max(change_plus, change_minus)) {
        c.status = DirectionStatus::undetermined;
        return c;
    }
    c.d_s = sign_normalised(change_plus > change_minus ? c.d_plus : c.d_minus);
    return c;
}

SegregationDirection segregation_direction(const Eigen::Matrix3d& grad, const Eigen::Vector3d& u,
                                           const DirectionOptions& options) {
    if (!grad.allFinite() || !u.allFinite()) throw InputError("segregation_direction: grad and u must be finite");
    SegregationDirection r;
    r.strain = strain_rate(grad);
    r.gamma_dot = shear_rate(grad);
    r.eigen = extreme_eigenpairs(r.strain, options);
    r.principal_shear = r.eigen.kappa_max - r.eigen.kappa_min;

    // D1: no shear plane where there is no shear (rigid motion, isotropic strain).
    if (!(r.principal_shear > options.shear_threshold)) {
        r.status = DirectionStatus::no_shear;
        return r;
    }
    const CandidateChoice c = choose_candidate(r.eigen.k_max, r.eigen.k_min, grad, u, options);
    r.d_plus = sign_normalised(c.d_plus);
    r.d_minus = sign_normalised(c.d_minus);
    // D2: a repeated extreme eigenvalue leaves a cone of maximum-shear planes.
    if (r.eigen.relative_gap < options.min_relative_gap) {
        r.status = DirectionStatus::repeated_eigenvalue;
        return r;
    }
    r.status = c.status;
    r.d_s = c.d_s;
    return r;
}

}  // namespace granseg
