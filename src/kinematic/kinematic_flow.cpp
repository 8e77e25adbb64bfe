#include "kinematic/kinematic_flow.hpp"

#include "core/error.hpp"
#include "segregation/bulk_transport.hpp"

#include <algorithm>
#include <cmath>
#include <string>

namespace granseg {

namespace {

using Eigen::Matrix2d;
using Eigen::Vector2d;

/// J with u = J grad(psi): (u_x, u_z) = (d psi/dz, -d psi/dx).
const Matrix2d kJ = (Matrix2d() << 0.0, 1.0, -1.0, 0.0).finished();

void require(bool ok, const std::string& what) {
    if (!ok) throw InputError("RollingDrumFlow: " + what);
}

Eigen::Vector3d embed(const Vector2d& v) { return {v(0), 0.0, v(1)}; }

Eigen::Matrix3d embed(const Matrix2d& m) {
    Eigen::Matrix3d r = Eigen::Matrix3d::Zero();
    r(0, 0) = m(0, 0), r(0, 2) = m(0, 1), r(2, 0) = m(1, 0), r(2, 2) = m(1, 1);
    return r;
}

}  // namespace

RollingDrumFlow::RollingDrumFlow(const RollingDrumParameters& p) : p_(p) {
    require(p.diameter > 0, "diameter must be > 0");
    require(p.fill_fraction > 0 && p.fill_fraction < 1, "fill_fraction must be in (0, 1)");
    require(std::isfinite(p.rotation_rate) && p.rotation_rate != 0, "rotation_rate must be finite and != 0");
    require(p.repose_angle >= 0 && p.repose_angle < 90, "repose_angle must be in [0, 90) degrees");
    R_ = p.diameter / 2;
    Omega_ = 2 * M_PI * p.rotation_rate;
    d_ = (2 * p.fill_fraction - 1) * R_;  // the level surface at rest, turned by beta about the centre
    L_ = std::sqrt(R_ * R_ - d_ * d_);
    delta0_ = p.layer_thickness;
    require(delta0_ > 0 && delta0_ < std::min(L_, R_ + d_),
            "layer_thickness must be in (0, min(half chord, bed depth)) = (0, " + std::to_string(std::min(L_, R_ + d_)) + ") m");
    // Counter-clockwise rotation lifts the bed on the right: the surface rises to the right.
    const double sigma = Omega_ > 0 ? 1.0 : -1.0, beta = p.repose_angle * M_PI / 180;
    n_ = {-sigma * std::sin(beta), 0.0, std::cos(beta)};
    t_ = {-sigma * std::cos(beta), 0.0, -std::sin(beta)};
}

std::array<double, 2> RollingDrumFlow::surface_coordinates(double x, double z) const {
    // Position relative to the middle of the surface, c = d n.
    const double rx = x - d_ * n_(0), rz = z - d_ * n_(2);
    return {rx * t_(0) + rz * t_(2), rx * n_(0) + rz * n_(2)};
}

double RollingDrumFlow::layer_depth(double s) const {
    return std::fabs(s) < L_ ? delta0_ * std::sqrt(1 - s * s / (L_ * L_)) : 0.0;
}

double RollingDrumFlow::surface_speed(double s) const {
    return std::fabs(s) < L_ ? std::fabs(Omega_) * (L_ * L_ - s * s) / layer_depth(s) : 0.0;
}

double RollingDrumFlow::layer_shear_rate() const { return std::fabs(Omega_) * L_ * L_ / (delta0_ * delta0_); }

bool RollingDrumFlow::in_drum(double x, double z) const { return x * x + z * z < R_ * R_; }

bool RollingDrumFlow::in_bed(double x, double z) const { return in_drum(x, z) && surface_coordinates(x, z)[1] <= 0; }

bool RollingDrumFlow::in_layer(double x, double z) const {
    const auto [s, n] = surface_coordinates(x, z);
    return in_bed(x, z) && std::fabs(s) < L_ && n > -layer_depth(s);
}

/// psi, grad psi and its Hessian at one point, in (x, z) components.
struct RollingDrumFlow::StreamDerivatives {
    double psi = 0;
    Vector2d grad = Vector2d::Zero();
    Matrix2d hessian = Matrix2d::Zero();
};

// psi = psi_sb m(chi) and its first and second derivatives by the chain rule (docs/sect2.3_direction.md,
// section 6). Below the layer m = 1: solid-body rotation.
RollingDrumFlow::StreamDerivatives RollingDrumFlow::derivatives(double x, double z) const {
    StreamDerivatives r;
    const Vector2d X(x, z), t(t_(0), t_(2)), nn(n_(0), n_(2));
    const double psi_sb = 0.5 * Omega_ * (R_ * R_ - X.squaredNorm());
    const Vector2d grad_sb = -Omega_ * X;
    const Matrix2d hess_sb = -Omega_ * Matrix2d::Identity();
    if (!in_layer(x, z)) {
        r.psi = psi_sb, r.grad = grad_sb, r.hessian = hess_sb;
        return r;
    }
    // chi = -n q(s) with q = 1/delta = w^(-1/2)/delta0, w = 1 - s^2/L^2; q1 = q', q2 = q''.
    const auto [s, n] = surface_coordinates(x, z);
    const double L2 = L_ * L_, w = 1 - s * s / L2;
    const double q = 1 / (delta0_ * std::sqrt(w));
    const double q1 = s / (delta0_ * L2 * std::pow(w, 1.5));
    const double q2 = (1 / (L2 * std::pow(w, 1.5)) + 3 * s * s / (L2 * L2 * std::pow(w, 2.5))) / delta0_;
    const double chi = -n * q;
    const Vector2d grad_chi = -q * nn - n * q1 * t;
    const Matrix2d hess_chi = -q1 * (nn * t.transpose() + t * nn.transpose()) - n * q2 * t * t.transpose();
    const double m = 2 * chi - chi * chi, m1 = 2 - 2 * chi, m2 = -2;  // m(chi), m', m''
    r.psi = psi_sb * m;
    r.grad = m * grad_sb + psi_sb * m1 * grad_chi;
    r.hessian = m * hess_sb + m1 * (grad_sb * grad_chi.transpose() + grad_chi * grad_sb.transpose()) +
                psi_sb * (m2 * grad_chi * grad_chi.transpose() + m1 * hess_chi);
    return r;
}

double RollingDrumFlow::stream_function(double x, double z) const { return in_bed(x, z) ? derivatives(x, z).psi : 0.0; }

Eigen::Vector3d RollingDrumFlow::velocity(double x, double z) const {
    if (!in_bed(x, z)) return Eigen::Vector3d::Zero();
    return embed(Vector2d(kJ * derivatives(x, z).grad));  // u = J grad(psi)
}

Eigen::Matrix3d RollingDrumFlow::velocity_gradient(double x, double z) const {
    if (!in_bed(x, z)) return Eigen::Matrix3d::Zero();
    return embed(Matrix2d(kJ * derivatives(x, z).hessian));  // d u_i/d x_j = J_ik d^2 psi/(d x_k d x_j)
}

Eigen::Vector3d RollingDrumFlow::relative_velocity(double x, double z) const {
    if (!in_layer(x, z)) return Eigen::Vector3d::Zero();           // the core turns with the drum
    return velocity(x, z) - Omega_ * Eigen::Vector3d(-z, 0.0, x);  // u - Omega x x
}

Eigen::Matrix3d RollingDrumFlow::relative_velocity_gradient(double x, double z) const {
    if (!in_layer(x, z)) return Eigen::Matrix3d::Zero();
    Eigen::Matrix3d spin = Eigen::Matrix3d::Zero();  // grad(Omega x x)
    spin(0, 2) = -Omega_, spin(2, 0) = Omega_;
    return velocity_gradient(x, z) - spin;
}

RollingDrumFields discretize(const RollingDrumFlow& flow, int cells_per_diameter, double Phi) {
    if (cells_per_diameter < 2) throw InputError("discretize: need cells_per_diameter >= 2");
    const double R = flow.radius();
    RollingDrumFields f;
    f.grid = Grid::plane_xz(cells_per_diameter, cells_per_diameter, -R, -R, 2 * R, 2 * R);
    Grid& g = f.grid;
    const int nx = g.n[0], nz = g.n[2];
    const std::size_t cells = g.cells();
    g.inside.assign(cells, 0);
    f.in_drum.assign(cells, 0);
    f.in_layer.assign(cells, 0);
    for (auto& c : f.u) c.assign(cells, 0.0);
    for (auto& c : f.u_rel) c.assign(cells, 0.0);
    for (auto& c : f.grad_rel) c.assign(cells, 0.0);
    for (int k = 0; k < nz; ++k)
        for (int i = 0; i < nx; ++i) {
            const std::size_t c = g.index(i, 0, k);
            const double x = g.center(0, i), z = g.center(2, k);
            f.in_drum[c] = flow.in_drum(x, z);
            g.inside[c] = flow.in_bed(x, z);
            f.in_layer[c] = flow.in_layer(x, z);
            if (!g.inside[c]) continue;
            const Eigen::Vector3d u = flow.velocity(x, z), u_rel = flow.relative_velocity(x, z);
            const Eigen::Matrix3d grad_rel = flow.relative_velocity_gradient(x, z);
            for (int a = 0; a < 3; ++a) {
                f.u[a][c] = u(a), f.u_rel[a][c] = u_rel(a);
                for (int b = 0; b < 3; ++b) f.grad_rel[3 * a + b][c] = grad_rel(a, b);
            }
        }

    // One implementation of the corner differences (segregation/bulk_transport.hpp): every corner
    // of a cell outside the bed gets the wall value 0; the grid-boundary corners lie on or outside
    // the wall circle, where stream_function() is 0 as well.
    f.M = stream_function_mass_fluxes(g, [&flow, Phi](double x, double z) { return Phi * flow.stream_function(x, z); });
    return f;
}

}  // namespace granseg
