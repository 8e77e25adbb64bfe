// Verification of the Sect. 2.3 direction procedure on flows whose answer is known.
//
// invariance: simple shear grad0 = gamma e_x e_z^T, u0 = U e_x, seen in 2000 random rotations R:
//     d_s = +/- R e_z (the shear-plane normal) and P = R e_z e_z^T R^T to 1e-12; gamma_dot (eq. 43)
//     and kappa_max - kappa_min equal gamma. With a random added rigid rotation (grad + W, u the
//     velocity relative to the rotating frame) d_s is unchanged, and gamma_dot follows the
//     hand-derived |grad0 + W'|_F: eq. (43) uses the full gradient. Using the inertial velocity
//     instead of the relative one is shown (note only) to pick the wrong plane.
// documented flows: flows with a documented outcome (docs/sect2.3_direction.md, docs/assumptions.md D1-D5):
//     planar extension (the 45-degree diagonals; at the stagnation point: undetermined),
//     axisymmetric extension (repeated eigenvalue), isotropic expansion and pure rotation (no shear),
//     shear plus extension (d_s tilted by (1/2) atan(2e/gamma) from the shear normal, exact formula),
//     compressible 2-D shear in planar and 3-D mode, and a Bagnold chute profile (d_s = the bed
//     normal at every depth, the gradient rule at the no-slip base, no shear at the free surface,
//     S^sl against the Gray-Thornton form).
// Writes direction_tilt.dat (shear plus extension) for figures/fig_direction.gp.
//
// Run: build/verification/verify_direction [--data DIR]   (well under a second)
#include "direction/segregation_direction.hpp"
#include "direction/segregation_velocity.hpp"
#include "harness/check_table.hpp"
#include "harness/program.hpp"
#include "harness/random_tensors.hpp"
#include "harness/tolerances.hpp"

#include <cmath>
#include <random>

using namespace granseg;
using Eigen::Matrix3d, Eigen::Vector3d;
using granseg::verify::CheckTable;
using granseg::verify::direction_error;
using granseg::verify::kRoundOff;

namespace {

// Tolerances, each with its reason.
// The bound for d_s in simple shear. The eigenvalues +-gamma/2, 0 have relative gap 1/2,
// so the eigenvectors carry an error of a few eps/gap ~ 1e-15: 1e-12 leaves a wide margin.
constexpr double kDirectionTol = 1e-12;
// Relative error of a Frobenius norm or of an extreme eigenvalue of a 3x3 matrix of O(1) entries
// rotated by R: a few dozen roundings (kRoundOff = 64 eps).
constexpr double kNormTol = kRoundOff;
constexpr int kRotations = 2000;

const Vector3d e_x(1, 0, 0), e_y(0, 1, 0), e_z(0, 0, 1);

void check_rotated_simple_shear(CheckTable& t) {
    std::mt19937_64 rng(20200451);
    std::uniform_real_distribution<double> rate(0.5, 5.0), speed(0.1, 3.0), coin(0.0, 1.0);
    double worst_d = 0, worst_P = 0, worst_gamma = 0, worst_shear = 0;
    double worst_d_spin = 0, worst_gamma_spin = 0, worst_shear_spin = 0;
    long not_ok = 0, not_ok_spin = 0, wrong_inertial = 0;
    for (int n = 0; n < kRotations; ++n) {
        const double gamma = rate(rng), U = (coin(rng) < 0.5 ? -1 : 1) * speed(rng);
        const Matrix3d R = verify::random_rotation(rng);
        const Matrix3d grad = R * (gamma * e_x * e_z.transpose()) * R.transpose();
        const Vector3d u = R * (U * e_x), normal = R * e_z;
        const SegregationDirection r = segregation_direction(grad, u);
        worst_d = std::max(worst_d, direction_error(r.d_s, normal));
        worst_P = std::max(worst_P, (r.P() - normal * normal.transpose()).cwiseAbs().maxCoeff());
        worst_gamma = std::max(worst_gamma, std::fabs(r.gamma_dot / gamma - 1));
        worst_shear = std::max(worst_shear, std::fabs(r.principal_shear / gamma - 1));
        not_ok += r.status != DirectionStatus::ok;

        // Added rigid rotation with angular velocity w, |w| up to 5 gamma: the strain is unchanged.
        const Vector3d w = 5.0 * gamma * coin(rng) * verify::random_normal_vector(rng).normalized();
        const SegregationDirection s = segregation_direction(grad + verify::spin_matrix(w), u);
        worst_d_spin = std::max(worst_d_spin, direction_error(s.d_s, normal));
        // |grad0 + W'|_F^2 = gamma^2 + 2|w|^2 + 2 gamma W'(0,2), W' = R^T W R the spin of w' = R^T w,
        // whose (0,2) entry is w'_y.
        const double expected = std::sqrt(gamma * gamma + 2 * w.squaredNorm() + 2 * gamma * (R.transpose() * w)(1));
        worst_gamma_spin = std::max(worst_gamma_spin, std::fabs(s.gamma_dot / expected - 1));
        worst_shear_spin = std::max(worst_shear_spin, std::fabs(s.principal_shear / gamma - 1));
        not_ok_spin += s.status != DirectionStatus::ok;

        // The same flow with the inertial velocity u + w x r (arm |r| = 1 m): the wrong frame.
        const Vector3d inertial = u + w.cross(verify::random_normal_vector(rng).normalized());
        wrong_inertial += direction_error(segregation_direction(grad + verify::spin_matrix(w), inertial).d_s, normal) > 0.5;
    }
    t.note("invariance: simple shear in " + std::to_string(kRotations) + " random rotations R");
    t.at_most("max |d_s -/+ R e_z|", worst_d, kDirectionTol);
    t.at_most("max |P - R e_z e_z^T R^T| (entries)", worst_P, kDirectionTol);
    t.at_most("max |gamma_dot/gamma - 1| (eq. 43, invariant)", worst_gamma, kNormTol);
    t.at_most("max |(kappa_max - kappa_min)/gamma - 1|", worst_shear, kNormTol);
    t.count("status != ok, count", not_ok, 0);
    t.note("invariance: with an added rigid rotation W (|w| <= 5 gamma), u relative to the rotating frame");
    t.at_most("max |d_s -/+ R e_z| with spin", worst_d_spin, kDirectionTol);
    t.at_most("max rel. error of gamma_dot vs |grad0 + W'|_F (full gradient)", worst_gamma_spin, kNormTol);
    t.at_most("max |(kappa_max - kappa_min)/gamma - 1| with spin", worst_shear_spin, kNormTol);
    t.count("status != ok with spin, count", not_ok_spin, 0);
    t.note("  with the inertial velocity u + w x r instead: wrong plane in " + std::to_string(wrong_inertial) + " of " +
           std::to_string(kRotations) + " samples (why the rotating-frame u is required)");
}

/// Checks one flow with a documented outcome: the status, and d_s (0 if no segregation).
void expect(CheckTable& t, const std::string& label, const Matrix3d& grad, const Vector3d& u, DirectionStatus status,
            const Vector3d& d_expected, const DirectionOptions& options = {}) {
    const SegregationDirection r = segregation_direction(grad, u, options);
    t.count(label + ": status " + to_string(status), r.status == status ? 1 : 0, 1);
    if (d_expected.squaredNorm() == 0)
        t.near(label + ": |d_s| (no segregation)", r.d_s.norm(), 0.0, 0.0);
    else
        t.at_most(label + ": |d_s -/+ expected|", direction_error(r.d_s, d_expected), kDirectionTol);
}

/// Shear plus planar extension: kappa^s = [[e, gamma/2], [gamma/2, -e]] in the x-z plane has
/// principal angle theta = (1/2) atan2(gamma/2, e); the maximum-shear normals are at theta +/- 45
/// degrees, and with u along x the one at theta + 45 degrees is the more orthogonal.
void check_shear_plus_extension(CheckTable& t, const verify::ProgramOptions& options) {
    const double gamma = 2.385;
    double worst = 0;
    long not_ok = 0;
    DataTable tilt;
    tilt.comment("shear gamma e_x e_z^T plus planar extension e (e_x e_x^T - e_z e_z^T), u = e_x; tilt of d_s from e_z");
    for (int i = -60; i <= 60; ++i) {
        const double e = gamma * i / 20.0;
        Matrix3d grad = gamma * e_x * e_z.transpose();
        grad(0, 0) = e, grad(2, 2) = -e;
        const double angle = 0.5 * std::atan2(gamma / 2, e) + M_PI / 4;  // from the x axis
        const Vector3d expected(std::cos(angle), 0, std::sin(angle));
        const SegregationDirection r = segregation_direction(grad, e_x);
        worst = std::max(worst, direction_error(r.d_s, expected));
        not_ok += r.status != DirectionStatus::ok;
        const double tilt_deg = std::acos(std::min(1.0, std::fabs(r.d_s.dot(e_z)))) * 180 / M_PI;
        tilt.row({{"e_over_gamma", e / gamma}, {"tilt_deg", tilt_deg}, {"tilt_exact_deg", std::fabs(90 - angle * 180 / M_PI)}});
    }
    verify::write_data(options, "direction_tilt.dat", tilt);
    t.at_most("shear + extension, e/gamma in [-3, 3]: max |d_s -/+ exact|", worst, kDirectionTol);
    t.count("shear + extension: status != ok, count", not_ok, 0);
}

/// A chute inclined at zeta: u = U(eta) t with the Bagnold profile U = U0 (1 - (1 - eta/H)^(3/2)),
/// t = (cos zeta, 0, -sin zeta) downslope, eta the height above the bed along n = (sin zeta, 0, cos zeta).
void check_chute(CheckTable& t) {
    const double zeta = 25 * M_PI / 180, H = 0.05, U0 = 0.5, S0 = 1.0, T = 1e-4;
    const Vector3d tangent(std::cos(zeta), 0, -std::sin(zeta)), normal(std::sin(zeta), 0, std::cos(zeta));
    const Vector3d g(0, 0, -9.81);
    double worst_d = 0, worst_S = 0;
    long wrong_status = 0;
    for (int i = 0; i <= 20; ++i) {
        const double eta = H * i / 20.0;
        const double U = U0 * (1 - std::pow(1 - eta / H, 1.5)), dU = 1.5 * U0 / H * std::sqrt(1 - eta / H);
        const SegregationDirection r = segregation_direction(dU * tangent * normal.transpose(), U * tangent);
        const DirectionStatus expected = i == 0    ? DirectionStatus::zero_velocity
                                         : i == 20 ? DirectionStatus::no_shear
                                                   : DirectionStatus::ok;
        wrong_status += r.status != expected;
        if (i == 20) continue;
        worst_d = std::max(worst_d, direction_error(r.d_s, normal));
        // Gray-Thornton form: S^sl = S0 sqrt(T) |g| cos(zeta) n (small particles sink along -n).
        const Vector3d gray_thornton = S0 * std::sqrt(T) * 9.81 * std::cos(zeta) * normal;
        worst_S = std::max(worst_S, (segregation_velocity(S0, T, r.d_s, g) - gray_thornton).norm() / gray_thornton.norm());
    }
    t.count("Bagnold chute: wrong status (base: u = 0, top: no shear), count", wrong_status, 0);
    t.at_most("Bagnold chute: max |d_s -/+ n| below the surface", worst_d, kDirectionTol);
    t.at_most("Bagnold chute: max rel. |S^sl - S0 sqrt(T)|g| cos(zeta) n|", worst_S, kDirectionTol);
}

/// 3b: every flow of the header comment.
void check_documented_flows(CheckTable& t, const verify::ProgramOptions& options) {
    t.note("documented flows: flows with a documented outcome");
    const double e = 1.7, gamma = 2.385;
    Matrix3d planar = Matrix3d::Zero();
    planar(0, 0) = e, planar(2, 2) = -e;  // u = e (x, 0, -z)
    expect(t, "planar extension at (1, 0, 0.5)", planar, e * Vector3d(1, 0, -0.5), DirectionStatus::ok,
           Vector3d(1, 0, 1) / std::sqrt(2.0));
    expect(t, "planar extension at the stagnation point", planar, Vector3d::Zero(), DirectionStatus::undetermined,
           Vector3d::Zero());
    const Matrix3d axisymmetric = e * Vector3d(-0.5, -0.5, 1).asDiagonal();
    expect(t, "axisymmetric extension", axisymmetric, e * Vector3d(-0.5, -0.25, 1), DirectionStatus::repeated_eigenvalue,
           Vector3d::Zero());
    expect(t, "isotropic expansion", e * Matrix3d::Identity(), e * Vector3d(1, 2, 3), DirectionStatus::no_shear,
           Vector3d::Zero());
    const Matrix3d rotation = verify::spin_matrix(Vector3d(0.3, -1.2, 0.5));
    expect(t, "pure rotation", rotation, Vector3d(1, 0, 0), DirectionStatus::no_shear, Vector3d::Zero());
    t.near_relative("pure rotation: gamma_dot = sqrt(2)|w| (eq. 43, frame-dependent)",
                    segregation_direction(rotation, e_x).gamma_dot, std::sqrt(2 * (0.09 + 1.44 + 0.25)), kNormTol);

    // Compressible 2-D shear with expansion a > gamma/2: the in-plane eigenvalues a +/- gamma/2 are
    // both positive, so in 3-D the out-of-plane 0 is kappa_min, the candidates (k_max +/- e_y)/sqrt(2)
    // leave the plane and are equally orthogonal to any in-plane u, and the gradient rule ties too:
    // undetermined. Planar mode keeps the x-z answer e_z (assumption D5).
    Matrix3d dilating = gamma * e_x * e_z.transpose();
    dilating(0, 0) = dilating(2, 2) = 0.8 * gamma;
    expect(t, "shear + expansion, 3-D procedure", dilating, e_x, DirectionStatus::undetermined, Vector3d::Zero());
    DirectionOptions planar_mode;
    planar_mode.planar_xz = true;
    expect(t, "shear + expansion, planar mode (D5)", dilating, e_x, DirectionStatus::ok, e_z, planar_mode);
    check_shear_plus_extension(t, options);
    check_chute(t);
}

}  // namespace

int main(int argc, char** argv) {
    const auto options = verify::parse_program_options(argc, argv);
    CheckTable table("Sect. 2.3 segregation direction: invariance and documented flows");
    check_rotated_simple_shear(table);
    check_documented_flows(table, options);
    return table.finish();
}
