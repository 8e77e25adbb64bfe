// Bulk transport with flux-corrected transport (Zalesak, J. Comput. Phys. 31, 335, 1979): the
// donor-cell step of bulk_transport.hpp plus the antidiffusive part of a Lax-Wendroff flux in
// phi_hat, limited so that every new phi_hat lies between the smallest and the largest of the old
// and the donor-cell phi_hat of the cell and its face neighbours (beyond the paper; assumption T5).
//
//   solves      the same bulk transport as bulk_transport.hpp, with limited antidiffusion (assumption T5)
//   inputs      the grid, Phi_old, Phi_new, M per axis, the inflow phi_hat, dt, phi
//   outputs     phi after the step
//   invariants  conservative as the donor-cell step; every new phi_hat between the local extremes of
//               the old and the donor-cell phi_hat, so 0 <= phi <= Phi whenever the donor-cell step keeps it
//
// Per face between inside cells L (lower) and U (upper) along an axis, with c = |M| dt/(h Phi_donor):
//     A = |M| (1 - c)/2 (phi_hat_U - phi_hat_L)          (Lax-Wendroff minus donor cell)
// set to 0 where it points down the gradient of the donor-cell solution (Zalesak's prelimiter),
// then scaled by C = min(R+ of the receiving cell, R- of the giving cell) with
//     R+ = min(1, (phi_hat_max - phi_hat_td) Phi_new / P+),  P+ = dt sum of incoming A/h,
// and likewise R-. The update phi = phi_td - dt sum_axis (C A[upper] - C A[lower])/h (done face by
// face, the same amount out of one cell and into the other) is conservative, so the amount of phi changes only through the donor-cell part (not at all with
// walls), and 0 <= phi_hat <= 1 holds whenever the donor-cell step keeps it (bulk_time_step).
#pragma once

#include "segregation/bulk_transport.hpp"

#include <vector>

namespace granseg {

class FctBulkTransport {
public:
    /// Lists the faces between two inside cells once (the grid's walls do not move).
    explicit FctBulkTransport(Grid grid);

    /// One FCT bulk step, in place (arguments and exceptions as transport_bulk). Phi_new: Phi after
    /// the step, Phi_old - dt div M (apply_mass_fluxes; the flow solver hands it over).
    void step(const std::vector<double>& Phi_old, const std::vector<double>& Phi_new, const FaceFields& M,
              const FaceFields& inflow_phi_hat, double dt, std::vector<double>& phi);

private:
    Grid grid_;
    BulkTransport donor_;  // the low-order (donor-cell) step
    struct OpenFace {
        std::size_t lower, upper, face;
        int axis;
    };
    std::vector<OpenFace> open_faces_;
    // Work space, kept between steps: phi_hat old and donor-cell, local bounds,
    // antidiffusive in- and outflow per cell, their limiters, the faces that carry antidiffusion.
    std::vector<double> hat_old_, hat_td_, hi_, lo_, gain_, loss_, R_plus_, R_minus_;
    struct Transfer {
        std::size_t lower, upper;
        double moved;  // dt A/h: the unlimited antidiffusive amount from lower to upper
    };
    std::vector<Transfer> active_;  // faces with A != 0
};

}  // namespace granseg
