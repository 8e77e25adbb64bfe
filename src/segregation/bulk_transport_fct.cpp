#include "segregation/bulk_transport_fct.hpp"

#include "segregation/reconstruction.hpp"

#include <algorithm>
#include <cmath>

namespace granseg {

FctBulkTransport::FctBulkTransport(Grid grid) : grid_(std::move(grid)), donor_(grid_) {
    for (int axis = 0; axis < 3; ++axis)
        for_each_face(grid_, axis, [&](const FaceCells& f) {
            // A periodic axis's last face layer repeats its first: count it once.
            if (!f.duplicate && is_open_face(grid_, f)) open_faces_.push_back({f.lower, f.upper, f.face, axis});
        });
}

void FctBulkTransport::step(const std::vector<double>& Phi_old, const std::vector<double>& Phi_new, const FaceFields& M,
                            const FaceFields& inflow_phi_hat, double dt, std::vector<double>& phi) {
    const std::size_t cells = grid_.cells();
    if (Phi_new.size() != cells) throw InputError("bulk transport: Phi_new needs one value per cell");
    hat_old_.resize(cells), hat_td_.resize(cells), hi_.resize(cells), lo_.resize(cells);
    for (std::size_t c = 0; c < cells; ++c) hat_old_[c] = composition(phi[c], Phi_old[c]);
    donor_.step(Phi_old, refs(M), inflow_phi_hat, dt, phi);  // the donor-cell (low-order) solution
    for (std::size_t c = 0; c < cells; ++c) {
        hat_td_[c] = composition(phi[c], Phi_new[c]);
        hi_[c] = std::max(hat_old_[c], hat_td_[c]), lo_[c] = std::min(hat_old_[c], hat_td_[c]);
    }
    // Local bounds over the face neighbours, and the antidiffusive transfers.
    gain_.assign(cells, 0.0), loss_.assign(cells, 0.0);
    active_.clear();
    for (const OpenFace& f : open_faces_) {
        const std::size_t L = f.lower, U = f.upper;
        hi_[L] = std::max(hi_[L], std::max(hat_old_[U], hat_td_[U])), lo_[L] = std::min(lo_[L], std::min(hat_old_[U], hat_td_[U]));
        hi_[U] = std::max(hi_[U], std::max(hat_old_[L], hat_td_[L])), lo_[U] = std::min(lo_[U], std::min(hat_old_[L], hat_td_[L]));
        const double m = M[f.axis].empty() ? 0.0 : M[f.axis][f.face], donor_Phi = m > 0.0 ? Phi_old[L] : Phi_old[U];
        if (m == 0.0 || donor_Phi <= 0.0) continue;
        const double ratio = dt / grid_.h[f.axis], courant = std::fabs(m) * ratio / donor_Phi;
        const double moved = ratio * std::fabs(m) * std::max(0.0, 1.0 - courant) / 2 * (hat_old_[U] - hat_old_[L]);  // dt A/h
        if (moved * (hat_td_[U] - hat_td_[L]) <= 0.0) continue;  // Zalesak's prelimiter: A = 0
        (moved > 0.0 ? gain_[U] : gain_[L]) += std::fabs(moved);
        (moved > 0.0 ? loss_[L] : loss_[U]) += std::fabs(moved);
        active_.push_back({L, U, moved});
    }
    R_plus_.resize(cells), R_minus_.resize(cells);
    for (std::size_t c = 0; c < cells; ++c) {
        R_plus_[c] = gain_[c] > 0.0 ? std::min(1.0, (hi_[c] - hat_td_[c]) * Phi_new[c] / gain_[c]) : 0.0;
        R_minus_[c] = loss_[c] > 0.0 ? std::min(1.0, (hat_td_[c] - lo_[c]) * Phi_new[c] / loss_[c]) : 0.0;
    }
    // The limited antidiffusive transfers, each moving the same rounded amount out of one cell and
    // into the other (conservative like eq. 64).
    for (const Transfer& t : active_) {
        const double limited = t.moved * (t.moved > 0.0 ? std::min(R_plus_[t.upper], R_minus_[t.lower])
                                                        : std::min(R_plus_[t.lower], R_minus_[t.upper]));
        phi[t.upper] += limited;
        phi[t.lower] -= limited;
    }
}

}  // namespace granseg
