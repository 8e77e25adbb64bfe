#include "segregation/face_fluxes.hpp"

#include "riemann/segregation_flux.hpp"
#include "segregation/reconstruction.hpp"

#include <algorithm>
#include <cmath>

namespace granseg {

void segregation_face_fluxes(const Grid& grid, int axis, const FrozenFields& fields, SegregationScheme scheme,
                             const std::vector<double>& phi, const std::vector<double>& at_lower,
                             const std::vector<double>& at_upper, std::vector<double>& F) {
    F.assign(grid.faces(axis), 0.0);
    const std::vector<double>& a = fields.a[axis];
    const std::vector<double>& Phi = fields.Phi;
    const std::vector<double>& Phi_face = fields.Phi_face[axis];
    const std::vector<double>& a_face = fields.a_face[axis];
    const double diffusion = fields.D / grid.h[axis];
    const InterfaceFlux interface_flux = scheme.row().flux;
    const bool interface_values = scheme.row().interface_values;
    for_each_face(grid, axis, [&](const FaceCells& f) {
        if (!is_open_face(grid, f)) return;  // zero-flux wall
        const std::size_t L = f.lower, U = f.upper;
        // The states either side of the face: each cell's value there, with its own Phi and a;
        // the interface values where the scheme reads them: given, else the means (assumption G2).
        // (Built in place: a copy of the struct stalls store forwarding; docs/history.md.)
        InterfaceStates q{{at_upper[L], Phi[L], a[L]}, {at_lower[U], Phi[U], a[U]}};
        if (interface_values) {
            q.Phi_face = Phi_face.empty() ? 0.5 * (Phi[L] + Phi[U]) : Phi_face[f.face];
            q.a_face = a_face.empty() ? 0.5 * (a[L] + a[U]) : a_face[f.face];
        }
        double flux = interface_flux(q);  // e.g. eq. (63)
        if (diffusion > 0.0)              // remixing, -D Phi_face d(phi_hat)/dx (docs/assumptions.md G3)
            flux -= diffusion * std::min(Phi[L], Phi[U]) * (composition(phi[U], Phi[U]) - composition(phi[L], Phi[L]));
        F[f.face] = flux;
    });
}

double max_coefficient(const Grid& grid, int axis, const FrozenFields& fields, SegregationScheme scheme) {
    const std::vector<double>& a = fields.a[axis];
    if (a.empty()) return 0.0;
    double largest = 0.0;
    for (std::size_t c = 0; c < a.size(); ++c)
        if (grid.is_inside(c) && fields.Phi[c] > 0.0) largest = std::max(largest, std::fabs(a[c]));
    if (uses_interface_values(scheme) && !fields.a_face[axis].empty())
        for_each_face(grid, axis, [&](const FaceCells& f) {
            if (is_open_face(grid, f)) largest = std::max(largest, std::fabs(fields.a_face[axis][f.face]));
        });
    return largest;
}

}  // namespace granseg
