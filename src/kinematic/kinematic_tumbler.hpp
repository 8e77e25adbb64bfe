// Segregation in the drum of Sect. 4.2 on the prescribed rolling-regime flow (kinematic_flow.hpp):
// phi is carried by the flow's face mass fluxes and segregates along the local d_s, with Phi
// constant and T steady. Shared by the tumbler-kinematic scene and verify_tumbler_kinematic, so
// both run exactly this code path.
//
//   solves      eq. (47) in the drum, split as in eq. (65): bulk transport, then eq. (52b)
//   inputs      KinematicTumblerSetup: the drum, cells per diameter, Phi, S, gravity, the material,
//               the schemes, the CFL number, phi_hat at t = 0
//   outputs     phi after each step; d_s, T and a_k per bed cell
//   invariants  sum of phi conserved, 0 <= phi <= Phi after both parts, a = 0 in the solid-body core
//
// Set-up, once (everything in the inertial frame, where the flow is steady):
//   per bed cell c: d_s = segregation_direction(grad u_rel, u_rel) in the x-z plane (Sect. 2.3),
//   T = (3/2)(eta0/eps0) gamma_dot^2 with gamma_dot = sqrt(grad u_rel : grad u_rel) (eqs. 43, 45),
//   a_k = (S^sl)_k = -S sqrt(T) (d_s . g) (d_s)_k (eq. 46; docs/assumptions.md S1), of either sign;
//   a = 0 in the solid-body core (no shear, d_s = 0).
// One step of length dt (docs/assumptions.md G1, T3, T5):
//   1. bulk transport of phi with the face mass fluxes M = Phi u.n (donor cell in phi_hat, unsplit,
//      or FCT: donor cell plus limited antidiffusion, bulk_transport_fct.hpp); Phi_new = Phi_old
//      because the discrete divergence of M vanishes;
//   2. the segregation sub-step with Phi and T frozen (eq. 52b): split over x and z, the
//      sign-robust interface flux of eq. (63) (SegregationSolver), zero flux on every wall face
//      (the stair-stepped drum wall and free surface).
// dt = min(bulk_time_step(cfl), segregation time_step(cfl)): both parts keep 0 <= phi <= Phi.
#pragma once

#include "closures/material.hpp"
#include "kinematic/kinematic_flow.hpp"
#include "run/state_io.hpp"
#include "segregation/bulk_transport_fct.hpp"
#include "segregation/frozen_fields.hpp"
#include "segregation/segregation_solver.hpp"

#include <functional>
#include <vector>

namespace granseg {

/// Everything a kinematic tumbler run needs (defaults: docs/scenes.md, docs/assumptions.md K2, T1-T3).
struct KinematicTumblerSetup {
    RollingDrumParameters drum;
    int cells_per_diameter = 100;
    double Phi = 0.6;                                  // constant granular volume fraction of the bed
    double S = 1.0;                                    // segregation rate S0 of eq. (46), s^2/m (Sect. 4.2: S0 = 1)
    double gravity = 9.81;                             // |g|, m/s^2, along -z
    Material material = Material::glass_substitute();  // eta0, eps0 of eq. (45)
    SegregationOptions segregation;                    // scheme, limiter and the CFL number of the segregation sub-step
    double bulk_cfl = 0.9;                             // CFL number of the bulk transport, 0 < cfl <= 1
    BulkScheme bulk = BulkScheme::fct;                 // donor cell (the coupling contract) or FCT (assumption T5)
    std::function<double(double x, double z)> phi_hat0 = [](double, double) { return 0.5; };  // initial phi_hat
};

class KinematicTumbler {
public:
    /// Builds the grid, the mass fluxes and a_k. Throws InputError if a value is out
    /// of range (the drum parameters, Phi outside (0, 1), phi_hat0 outside [0, 1] at a bed cell).
    explicit KinematicTumbler(const KinematicTumblerSetup& setup);

    /// One step (bulk transport, then segregation) of length dt <= time_step(); after_bulk (if
    /// given) sees phi between the two parts.
    void step(double dt, const std::function<void(const std::vector<double>& phi)>& after_bulk = {});

    /// The largest step both parts allow at their CFL numbers.
    double time_step() const { return dt_max_; }
    /// Bulk part alone (phi_hat leaves [0, 1] beyond it) and segregation part alone.
    double bulk_time_step() const { return dt_bulk_; }
    double segregation_time_step() const { return dt_segregation_; }

    const RollingDrumFlow& flow() const { return flow_; }
    const RollingDrumFields& fields() const { return fields_; }
    const Grid& grid() const { return fields_.grid; }
    const FrozenFields& frozen() const { return frozen_; }
    const std::vector<double>& Phi() const { return frozen_.Phi; }
    const std::vector<double>& phi() const { return phi_; }
    const std::vector<double>& T() const { return T_; }
    /// d_s per cell (x and z components, 0 where there is no segregation), signed so that it
    /// points out of the bed (d_s . n >= 0).
    const std::vector<double>& ds_x() const { return ds_x_; }
    const std::vector<double>& ds_z() const { return ds_z_; }
    double time() const { return t_; }
    long steps() const { return steps_; }
    /// Inside-cell updates: one per bed cell for the bulk step, plus the segregation solver's.
    long long cell_updates() const { return bulk_updates_ + solver_.cell_updates(); }
    /// Largest amount the segregation solver's round-off guard moved phi into [0, Phi].
    double largest_correction() const { return solver_.largest_correction(); }

private:
    RollingDrumFlow flow_;
    RollingDrumFields fields_;
    FrozenFields frozen_;
    SegregationSolver solver_;
    BulkScheme bulk_;
    FctBulkTransport fct_;
    FaceFields no_inflow_;  // closed drum: nothing enters through a domain boundary
    std::vector<double> phi_, T_, ds_x_, ds_z_;
    double dt_bulk_ = 0, dt_segregation_ = 0, dt_max_ = 0, t_ = 0;
    long steps_ = 0;
    long long bulk_updates_ = 0;
    std::size_t bed_cells_ = 0;

public:
    /// Saves or restores (run/state_io.hpp) what a later step or a caller reads (the rest is
    /// built from the setup, as before).
    void checkpoint(StateIO& io) {
        io("kinematic.phi", phi_)("kinematic.t", t_)("kinematic.steps", steps_)("kinematic.bulk_updates", bulk_updates_);
        io("kinematic.solver", solver_);
    }
};

/// phi_hat = phi/Phi per cell (0 outside the bed).
std::vector<double> composition_field(const Grid& grid, const std::vector<double>& phi, const std::vector<double>& Phi);

}  // namespace granseg
