#include "segregation/bulk_transport_fct.hpp"

#include "segregation/reconstruction.hpp"

#include <algorithm>
#include <cmath>

namespace granseg {

FctBulkTransport::FctBulkTransport(Grid grid, Limiter limiter)
    : grid_(std::move(grid)), donor_(grid_), high_order_(grid_, limiter) {
    for (int axis = 0; axis < 3; ++axis) {
        if (grid_.n[axis] > 1) U_[axis].assign(grid_.faces(axis), 0.0);
        for_each_face(grid_, axis, [&](const FaceCells& f) {
            // A periodic axis's last face layer repeats its first: count it once.
            if (!f.duplicate && is_open_face(grid_, f)) open_faces_.push_back({f.lower, f.upper, f.face, axis});
        });
    }
    moved_.assign(open_faces_.size(), 0.0);
}

double FctBulkTransport::step(const std::vector<double>& Phi_old, const std::vector<double>& Phi_new, const FaceFieldRefs& M,
                              const FaceFields& inflow_phi_hat, double dt, std::vector<double>& phi, double Phi_min) {
    const std::size_t cells = grid_.cells();
    if (Phi_new.size() != cells) throw InputError("bulk transport: Phi_new needs one value per cell");
    hat_old_.resize(cells), hat_td_.resize(cells), hi_.resize(cells), lo_.resize(cells);
    for (std::size_t c = 0; c < cells; ++c) hat_old_[c] = composition(phi[c], Phi_old[c]);
    // The face velocities M/Phi_old(cell M leaves) for the predictor of the face values.
    for (const OpenFace& f : open_faces_) {
        const double m = M[f.axis] == nullptr || M[f.axis]->empty() ? 0.0 : (*M[f.axis])[f.face];
        const double donor_Phi = m > 0.0 ? Phi_old[f.lower] : Phi_old[f.upper];
        U_[f.axis][f.face] = m != 0.0 && donor_Phi > 0.0 ? m / donor_Phi : 0.0;
    }
    for (int axis = 0; axis < 3; ++axis)  // a periodic axis's last face layer repeats its first
        if (grid_.n[axis] > 1 && grid_.periodic[axis])
            for_each_face(grid_, axis, [&](const FaceCells& f) {
                if (f.duplicate) U_[axis][f.face] = U_[axis][f.face - grid_.n[axis] * grid_.face_stride(axis)];
            });
    high_order_.face_values(hat_old_, refs(U_), dt, MusclHancock::Form::advective);
    const double courant = donor_.step(Phi_old, M, inflow_phi_hat, dt, phi, Phi_min);  // the low-order solution
    for (std::size_t c = 0; c < cells; ++c) {
        hat_td_[c] = composition(phi[c], Phi_new[c]);
        hi_[c] = std::max(hat_old_[c], hat_td_[c]), lo_[c] = std::min(hat_old_[c], hat_td_[c]);
    }
    // Local bounds over the face neighbours, and the antidiffusive transfers dt A/h.
    gain_.assign(cells, 0.0), loss_.assign(cells, 0.0);
    for (std::size_t q = 0; q < open_faces_.size(); ++q) {
        const OpenFace& f = open_faces_[q];
        const std::size_t L = f.lower, U = f.upper;
        hi_[L] = std::max(hi_[L], std::max(hat_old_[U], hat_td_[U])),
        lo_[L] = std::min(lo_[L], std::min(hat_old_[U], hat_td_[U]));
        hi_[U] = std::max(hi_[U], std::max(hat_old_[L], hat_td_[L])),
        lo_[U] = std::min(lo_[U], std::min(hat_old_[L], hat_td_[L]));
        const double m = U_[f.axis][f.face] == 0.0 ? 0.0 : (*M[f.axis])[f.face];
        const double face = m > 0.0 ? high_order_.from_lower()[f.axis][f.face] : high_order_.from_upper()[f.axis][f.face];
        const double moved = dt / grid_.h[f.axis] * m * (face - hat_old_[m > 0.0 ? L : U]);
        moved_[q] = moved;
        if (moved == 0.0) continue;
        (moved > 0.0 ? gain_[U] : gain_[L]) += std::fabs(moved);
        (moved > 0.0 ? loss_[L] : loss_[U]) += std::fabs(moved);
    }
    R_plus_.resize(cells), R_minus_.resize(cells);
    for (std::size_t c = 0; c < cells; ++c) {
        R_plus_[c] = gain_[c] > 0.0 ? std::min(1.0, (hi_[c] - hat_td_[c]) * Phi_new[c] / gain_[c]) : 0.0;
        R_minus_[c] = loss_[c] > 0.0 ? std::min(1.0, (hat_td_[c] - lo_[c]) * Phi_new[c] / loss_[c]) : 0.0;
    }
    // The limited antidiffusive transfers, each moving the same rounded amount out of one cell and
    // into the other (conservative like eq. 64).
    for (std::size_t q = 0; q < open_faces_.size(); ++q) {
        const double moved = moved_[q];
        if (moved == 0.0) continue;
        const OpenFace& f = open_faces_[q];
        const double limited =
            moved * (moved > 0.0 ? std::min(R_plus_[f.upper], R_minus_[f.lower]) : std::min(R_plus_[f.lower], R_minus_[f.upper]));
        phi[f.upper] += limited;
        phi[f.lower] -= limited;
    }
    return courant;
}

}  // namespace granseg
