// Bulk transport of phi with the flow's own face mass fluxes (the coupling contract of the
// project, docs/sect2.2_segregation.md "Coupling"; eq. 65 with F^bulk from the mass balance).
//
//   solves      the bulk part of eq. (47) split by eq. (65), d_t phi + div(phi u) = 0, with the flow's
//               face mass fluxes M
//   inputs      the grid, Phi_old, M per axis, the inflow phi_hat, dt, phi
//   outputs     phi after the step; bulk_time_step(), the largest safe dt
//   invariants  phi_new/Phi_new is a convex combination of old phi_hat for dt sum_out |M|/h <= Phi_old;
//               the sum of phi changes only through open domain boundaries
//
// The flow solver hands over, per axis, the face mass fluxes M (Phi u . n, averaged over its
// stages) with which it updated Phi:
//     Phi_new = Phi_old - dt sum_axis (M[upper] - M[lower])/h_axis,   M = 0 on wall faces.
// phi moves with the same fluxes, donor cell in phi_hat = phi/Phi_old, unsplit:
//     phi_new = phi_old - dt sum_axis (G[upper] - G[lower])/h_axis,   G = M phi_hat(upwind cell),
// evaluated in the same order as the flow solver's mass balance (the sum over the axes first,
// then one subtraction), so that for a uniform phi_hat = c every operation is the mass balance's
// scaled by c: phi_hat stays c to round-off (exactly for c = 1/2, a power of two), and the
// segregation part alone decides whether a mixture separates (verify_tumbler, S = 0);
// so in every inside cell phi_new = phi_hat_i (Phi_old - dt sum_out |M|/h) + dt sum_in |M| phi_hat_nb/h
// and phi_new/Phi_new is a convex combination of old phi_hat values whenever
// dt sum_out |M|/h <= Phi_old (bulk_time_step). Open domain boundaries (a chute's inflow and
// outflow) carry M != 0: outflow takes the inside cell's phi_hat, inflow the given inflow_phi_hat.
#pragma once

#include "segregation/flux_difference.hpp"

#include <functional>
#include <vector>

namespace granseg {

/// The donor-cell bulk step (see above) with its work space kept between steps.
class BulkTransport {
public:
    explicit BulkTransport(Grid grid);

    /// One bulk step, in place. M: face mass fluxes per axis. inflow_phi_hat: phi_hat entering
    /// through open boundary faces (face fields; may be empty where nothing enters). Returns the
    /// step's largest Courant number dt sum_out |M|/(h Phi_old) over the inside cells with
    /// Phi_old >= Phi_min (the share of a cell's material the step moved out; <= 1 keeps phi_hat a
    /// convex combination). Throws InvariantError if M != 0 on a face next to an outside cell,
    /// InputError if inflow has no phi_hat or a field has the wrong size.
    double step(const std::vector<double>& Phi_old, const FaceFieldRefs& M, const FaceFields& inflow_phi_hat, double dt,
                std::vector<double>& phi, double Phi_min = 0.0);

private:
    /// G on the faces of `axis`: the faces between two cells row by row, the domain boundary line by line.
    void donor_cell_fluxes(int axis, const std::vector<double>& M, const std::vector<double>& inflow);

    Grid grid_;
    std::vector<unsigned char> inside_;  // 1 for inside cells (grid.inside or all)
    bool parallel_;                      // OpenMP threads over rows on larger grids
    std::vector<double> hat_;            // phi_hat of every cell before the step, 0 outside
    FaceFields G_;                       // G = M phi_hat(donor) per face
};

/// One bulk step with a BulkTransport of its own (arguments and exceptions as BulkTransport::step).
void transport_bulk(const Grid& grid, const std::vector<double>& Phi_old, const FaceFields& M, const FaceFields& inflow_phi_hat,
                    double dt, std::vector<double>& phi);

/// cfl times the largest dt with dt sum_out |M|/h <= Phi_old in every inside cell with
/// Phi_old >= Phi_min (+infinity if nothing flows out of any of them).
double bulk_time_step(const Grid& grid, const std::vector<double>& Phi_old, const FaceFieldRefs& M, double cfl,
                      double Phi_min = 0.0);
inline double bulk_time_step(const Grid& grid, const std::vector<double>& Phi_old, const FaceFields& M, double cfl) {
    return bulk_time_step(grid, Phi_old, refs(M), cfl);
}

/// Face mass fluxes of a divergence-free flow in the x-z plane from a mass stream function
/// psi(x, z) evaluated at the cell corners: M_x = d(psi)/dz, M_z = -d(psi)/dx as differences of
/// corner values, so the discrete divergence vanishes to round-off. Corners of outside cells get
/// psi = 0: embedded walls are the streamline psi = 0 and M = 0 on every wall face.
FaceFields stream_function_mass_fluxes(const Grid& grid, const std::function<double(double x, double z)>& psi);

}  // namespace granseg
