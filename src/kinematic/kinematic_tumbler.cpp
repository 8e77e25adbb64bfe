#include "kinematic/kinematic_tumbler.hpp"

#include "closures/closures.hpp"
#include "core/format.hpp"
#include "direction/segregation_direction.hpp"
#include "direction/segregation_velocity.hpp"
#include "segregation/bulk_transport.hpp"
#include "segregation/bulk_transport_fct.hpp"
#include "segregation/reconstruction.hpp"

#include <algorithm>
#include <cmath>

namespace granseg {

namespace {

RollingDrumFields checked_fields(const RollingDrumFlow& flow, const KinematicTumblerSetup& setup) {
    if (!(setup.Phi > 0.0 && setup.Phi < 1.0))
        throw InputError("kinematic tumbler: Phi = " + format_number(setup.Phi) + " outside (0, 1)");
    if (!(setup.S >= 0.0 && std::isfinite(setup.S))) throw InputError("kinematic tumbler: S must be finite and >= 0");
    if (!(setup.bulk_cfl > 0.0 && setup.bulk_cfl <= 1.0)) throw InputError("kinematic tumbler: bulk CFL number outside (0, 1]");
    return discretize(flow, setup.cells_per_diameter, setup.Phi);
}

}  // namespace

KinematicTumbler::KinematicTumbler(const KinematicTumblerSetup& setup)
    : flow_(setup.drum),
      fields_(checked_fields(flow_, setup)),
      solver_(fields_.grid, setup.segregation),
      bulk_(setup.bulk),
      fct_(fields_.grid) {
    const Grid& g = fields_.grid;
    const std::size_t cells = g.cells();
    frozen_.Phi.assign(cells, 0.0);
    frozen_.a[0].assign(cells, 0.0);
    frozen_.a[2].assign(cells, 0.0);
    phi_.assign(cells, 0.0);
    T_.assign(cells, 0.0);
    ds_x_.assign(cells, 0.0);
    ds_z_.assign(cells, 0.0);
    const Eigen::Vector3d gravity(0.0, 0.0, -setup.gravity);
    DirectionOptions planar;
    planar.planar_xz = true;
    for_each_bed_cell(g, [&](const BedCell& b) {
        const std::size_t c = b.c;
        ++bed_cells_;
        const double phi_hat = setup.phi_hat0(b.x, b.z);
        if (!(phi_hat >= 0.0 && phi_hat <= 1.0))
            throw InputError("kinematic tumbler: initial phi_hat = " + format_number(phi_hat) + " at x = " + format_number(b.x) +
                             ", z = " + format_number(b.z) + " outside [0, 1]");
        frozen_.Phi[c] = setup.Phi;
        phi_[c] = phi_hat * setup.Phi;
        const Eigen::Matrix3d grad_rel = cell_tensor(fields_.grad_rel, c);
        const SegregationDirection dir = segregation_direction(grad_rel, cell_vector(fields_.u_rel, c), planar);
        const Eigen::Vector3d d_s = dir.d_s.dot(flow_.normal()) < 0.0 ? Eigen::Vector3d(-dir.d_s) : dir.d_s;
        T_[c] = steady_shear_temperature(setup.material, shear_rate(grad_rel));        // (eq. 45)
        const Eigen::Vector3d a = segregation_velocity(setup.S, T_[c], d_s, gravity);  // (eq. 46)
        frozen_.a[0][c] = a(0), frozen_.a[2][c] = a(2);
        ds_x_[c] = d_s(0), ds_z_[c] = d_s(2);
    });
    dt_bulk_ = granseg::bulk_time_step(g, frozen_.Phi, fields_.M, setup.bulk_cfl);
    dt_segregation_ = solver_.time_step(frozen_);
    dt_max_ = std::min(dt_bulk_, dt_segregation_);
}

void KinematicTumbler::step(double dt, const std::function<void(const std::vector<double>&)>& after_bulk) {
    if (!(dt > 0.0 && dt <= dt_max_ * (1 + 1e-12)))
        throw InputError("kinematic tumbler: step " + format_number(dt) + " outside (0, time_step()]");
    // Phi_old = Phi_new = Phi: the discrete divergence of M vanishes (kinematic_flow.hpp).
    if (bulk_ == BulkScheme::fct)
        fct_.step(frozen_.Phi, frozen_.Phi, refs(fields_.M), no_inflow_, dt, phi_);  // (eq. 65, F^bulk; assumption T5)
    else
        transport_bulk(fields_.grid, frozen_.Phi, fields_.M, no_inflow_, dt, phi_);  // (eq. 65, F^bulk)
    bulk_updates_ += static_cast<long long>(bed_cells_);
    if (after_bulk) after_bulk(phi_);
    solver_.step(frozen_, dt, phi_);  // (eq. 52b)
    t_ += dt;
    ++steps_;
}

std::vector<double> composition_field(const Grid& grid, const std::vector<double>& phi, const std::vector<double>& Phi) {
    std::vector<double> phi_hat(grid.cells(), 0.0);
    for (std::size_t c = 0; c < grid.cells(); ++c)
        if (grid.is_inside(c)) phi_hat[c] = composition(phi[c], Phi[c]);
    return phi_hat;
}

}  // namespace granseg
