// Reproducible random rotations and tensors for the verification programs (fixed seeds, so a
// failing sample can be replayed).
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <algorithm>
#include <random>

namespace granseg::verify {

/// A rotation drawn uniformly from SO(3): a unit quaternion from four standard normal numbers.
inline Eigen::Matrix3d random_rotation(std::mt19937_64& rng) {
    std::normal_distribution<double> normal;
    Eigen::Quaterniond q(normal(rng), normal(rng), normal(rng), normal(rng));
    q.normalize();
    return q.toRotationMatrix();
}

/// A vector with independent standard normal components.
inline Eigen::Vector3d random_normal_vector(std::mt19937_64& rng) {
    std::normal_distribution<double> normal;
    return {normal(rng), normal(rng), normal(rng)};
}

/// The antisymmetric matrix W with W x = w x x (a rigid rotation with angular velocity w).
inline Eigen::Matrix3d spin_matrix(const Eigen::Vector3d& w) {
    Eigen::Matrix3d W;
    W << 0.0, -w(2), w(1), w(2), 0.0, -w(0), -w(1), w(0), 0.0;
    return W;
}

/// Distance between two directions irrespective of sign: min(|a - b|, |a + b|).
inline double direction_error(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
    return std::min((a - b).norm(), (a + b).norm());
}

}  // namespace granseg::verify
