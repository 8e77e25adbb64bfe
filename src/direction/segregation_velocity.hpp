// The segregation velocity S^sl of Sect. 2.2 on the direction d_s of Sect. 2.3 (eqs. 36, 42, 45, 46).
//
//   solves      eqs. (42), (45), (46): the segregation velocity S^sl
//   inputs      S0 (s^2/m), T (m^2/s^2), d_s, gravity g (m/s^2)
//   outputs     S^sl (m/s), the flux coefficients a_k = (S^sl)_k
//   invariants  S^sl is parallel to d_s and vanishes where d_s = 0 or T = 0
//
//   eq. (42): S^sl = -(B/c) gamma_dot P g          (B: load-sharing magnitude, c: drag coefficient)
//   eq. (45): gamma_dot = sqrt((2/3) (eps0/eta0) T) (heating = dissipation, heat flux neglected)
//   eq. (46): S^sl = -S0 sqrt(T) P g,  S0 = (B/c) sqrt((2/3) eps0/eta0)
// with P x = (x . d_s) d_s (eq. 36). S^sl enters eq. (47) as div(S^sl phi (Phi - phi)/Phi) on the
// right-hand side, so per axis k the flux coefficient of src/riemann/segregation_flux.hpp is
// a_k = (S^sl)_k (docs/assumptions.md S1): small particles move along -S^sl, i.e. along g
// projected on d_s. Where d_s = 0 (no shear, undetermined direction) S^sl = 0.
// Units: T in m^2/s^2, g in m/s^2, gamma_dot in 1/s, S^sl in m/s, so S0 in s^2/m and B/c in s^2
// (kSegregationRateUnit, kLoadSharingOverDragUnit; tests/direction/units.cpp derives them from
// eqs. 42, 45, 46 by a dimension check).
// Sign: S^sl points against the part of g along d_s (upwards when gravity points down), and small
// particles move against S^sl: a = (S^sl)_z > 0 for z up means small particles sinking.
#pragma once

#include <Eigen/Core>

#include <cmath>

namespace granseg {

/// The units of S0 (eq. 46) and of B/c (eq. 42), as the command line's help prints them.
inline constexpr const char* kSegregationRateUnit = "s^2/m";
inline constexpr const char* kLoadSharingOverDragUnit = "s^2";

/// P g = (g . d_s) d_s (eq. 36).
inline Eigen::Vector3d project(const Eigen::Vector3d& d_s, const Eigen::Vector3d& g) { return d_s.dot(g) * d_s; }

/// S^sl = -S0 sqrt(T) P g (eq. 46). Precondition: T >= 0.
inline Eigen::Vector3d segregation_velocity(double S0, double T, const Eigen::Vector3d& d_s, const Eigen::Vector3d& g) {
    return -S0 * std::sqrt(T) * project(d_s, g);  // (eq. 46)
}

/// S^sl = -(B/c) gamma_dot P g (eq. 42), with the shear rate given directly.
inline Eigen::Vector3d segregation_velocity_from_shear_rate(double B_over_c, double gamma_dot, const Eigen::Vector3d& d_s,
                                                            const Eigen::Vector3d& g) {
    return -B_over_c * gamma_dot * project(d_s, g);  // (eq. 42)
}

/// S0 = (B/c) sqrt((2/3) eps0/eta0), the segregation rate of eq. (46).
inline double segregation_rate(double B_over_c, double eps0, double eta0) {
    return B_over_c * std::sqrt(2.0 / 3.0 * eps0 / eta0);  // (eq. 46)
}

/// gamma_dot = sqrt((2/3) (eps0/eta0) T) (eq. 45).
inline double shear_rate_from_temperature(double T, double eps0, double eta0) {
    return std::sqrt(2.0 / 3.0 * eps0 / eta0 * T);  // (eq. 45)
}

}  // namespace granseg
