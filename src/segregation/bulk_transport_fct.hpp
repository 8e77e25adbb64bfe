// Bulk transport of phi at second order with flux-corrected transport (Boris & Book, J. Comput.
// Phys. 11, 1973; Zalesak, J. Comput. Phys. 31, 1979): the donor-cell step of bulk_transport.hpp
// plus the antidiffusive part of a MUSCL-Hancock flux in phi_hat (transport/muscl_hancock.hpp),
// limited so that every new phi_hat lies between the smallest and the largest of the old and the
// donor-cell phi_hat of the cell and its face neighbours (beyond the paper; assumption T5).
//
//   solves      the same bulk transport as bulk_transport.hpp, at second order in space and time
//               where phi_hat is smooth (assumption T5)
//   inputs      the grid, the limiter; per step Phi_old, Phi_new, M per axis, the inflow phi_hat, dt, phi
//   outputs     phi after the step; the donor-cell step's Courant number (BulkTransport::step)
//   invariants  conservative as the donor-cell step; every new phi_hat between the local extremes
//               of the old and the donor-cell phi_hat, so 0 <= phi <= Phi whenever the donor-cell
//               step keeps it; a uniform phi_hat stays uniform
//
// The high-order flux of a face between inside cells L (lower) and U (upper) along an axis is
// M phi_hat_f, phi_hat_f the MUSCL-Hancock value (advective form) that the cell M leaves gives the
// face, for the face velocities M/Phi_old(cell M leaves); the antidiffusive flux is what it adds to
// the donor cell's M phi_hat(cell M leaves):
//     A = M (phi_hat_f - phi_hat_donor),
// scaled by C = min(R+ of the receiving cell, R- of the giving cell) with
//     R+ = min(1, (phi_hat_max - phi_hat_td) Phi_new / P+),  P+ = dt sum of incoming |A|/h,
// and likewise R-. The update phi = phi_td - dt sum_axis (C A[upper] - C A[lower])/h (done face by
// face, the same amount out of one cell and into the other) is conservative, so the amount of phi
// changes only through the donor-cell part (not at all with walls), and 0 <= phi_hat <= 1 holds
// whenever the donor-cell step keeps it (bulk_time_step). Where the limiter of the reconstruction
// is inactive and the bounds are not reached, C = 1 and the step is the MUSCL-Hancock step.
#pragma once

#include "segregation/bulk_transport.hpp"
#include "transport/muscl_hancock.hpp"

#include <vector>

namespace granseg {

class FctBulkTransport {
public:
    /// Lists the faces between two inside cells once (the grid's walls do not move).
    explicit FctBulkTransport(Grid grid, Limiter limiter = Limiter::mc);

    /// One FCT bulk step, in place (arguments, result and exceptions as BulkTransport::step).
    /// Phi_new: Phi after the step, Phi_old - dt div M (the flow solver hands it over).
    double step(const std::vector<double>& Phi_old, const std::vector<double>& Phi_new, const FaceFieldRefs& M,
                const FaceFields& inflow_phi_hat, double dt, std::vector<double>& phi, double Phi_min = 0.0);

private:
    Grid grid_;
    BulkTransport donor_;      // the low-order (donor-cell) step
    MusclHancock high_order_;  // the face values of phi_hat
    struct OpenFace {
        std::size_t lower, upper, face;
        int axis;
    };
    std::vector<OpenFace> open_faces_;
    // Work space, kept between steps: phi_hat old and donor-cell, local bounds, face velocities,
    // antidiffusive in- and outflow per cell, their limiters, the unlimited transfers per open face.
    std::vector<double> hat_old_, hat_td_, hi_, lo_, gain_, loss_, R_plus_, R_minus_, moved_;
    FaceFields U_;
};

}  // namespace granseg
