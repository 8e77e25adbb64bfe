#include "flow/diffusion/diffusion_lines.hpp"

namespace granseg {

DiffusionLines::DiffusionLines(const FlowMesh& mesh) {
    const std::size_t cells = mesh.grid.cells();
    lower_.assign(cells, 0.0);
    upper_.assign(cells, 0.0);
    diag_.assign(cells, 1.0);  // outside cells are identity rows of every line solve
    lines_.set_parallel(mesh.parallel);
}

void DiffusionLines::factor(const FlowMesh& mesh, int a, double r, const std::vector<double>& Phi_in,
                            const std::vector<double>& kappa, bool no_slip, double Phi_vac) {
    const double *Phi = Phi_in.data(), *k = kappa.data();
    const unsigned char *in = mesh.inside.data(), *kind = mesh.face_kind[a].data();
    double *lower = lower_.data(), *diag = diag_.data(), *upper = upper_.data();
    mesh.parallel_for_row_cells(a, [=](std::size_t c, int i, const AxisRow& ar) {
        const std::size_t fl = ar.face0 + i, fu = fl + ar.face_step;
        const bool active = in[c] && Phi[c] > Phi_vac;
        const bool in_lo = kind[fl] == kInterior, in_hi = kind[fu] == kInterior;
        const double w_lo = r * face_conductance(in_lo, k[c], k[c + ar.lo_at(i)], no_slip);
        const double w_hi = r * face_conductance(in_hi, k[c], k[c + ar.hi_at(i)], no_slip);
        lower[c] = active && in_lo ? w_lo : 0.0;
        upper[c] = active && in_hi ? w_hi : 0.0;
        diag[c] = active ? Phi[c] + w_lo + w_hi : 1.0;
    });
    lines_.factor(mesh.grid, a, lower_, diag_, upper_);
}

}  // namespace granseg
