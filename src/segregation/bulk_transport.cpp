#include "segregation/bulk_transport.hpp"

#include "core/error.hpp"
#include "segregation/reconstruction.hpp"

#include <algorithm>
#include <limits>

namespace granseg {

namespace {

void check_face_field(const Grid& grid, int axis, const std::vector<double>& field, const char* what) {
    if (!field.empty() && field.size() != grid.faces(axis))
        throw InputError(std::string("bulk transport: ") + what + " needs one value per face");
}

/// G = M phi_hat(donor) on every face of `axis` (see the header).
std::vector<double> donor_cell_fluxes(const Grid& grid, int axis, const std::vector<double>& Phi_old,
                                      const std::vector<double>& M, const std::vector<double>& inflow,
                                      const std::vector<double>& phi) {
    std::vector<double> G(grid.faces(axis), 0.0);
    for_each_face(grid, axis, [&](const FaceCells& f) {
        const double m = M[f.face];
        if (m == 0.0) return;
        const bool lower_in = f.lower != kNoCell && grid.is_inside(f.lower);
        const bool upper_in = f.upper != kNoCell && grid.is_inside(f.upper);
        if (lower_in && upper_in) {
            const std::size_t donor = m > 0.0 ? f.lower : f.upper;
            G[f.face] = m * composition(phi[donor], Phi_old[donor]);
            return;
        }
        const bool wall = (f.lower != kNoCell && !lower_in) || (f.upper != kNoCell && !upper_in);
        if (wall || (!lower_in && !upper_in))
            throw InvariantError("bulk transport: mass flux " + std::to_string(m) + " through a wall face (axis " +
                                 std::to_string(axis) + ", face " + std::to_string(f.face) + ")");
        const bool outflow = lower_in ? m > 0.0 : m < 0.0;  // open domain boundary
        if (outflow) {
            const std::size_t donor = lower_in ? f.lower : f.upper;
            G[f.face] = m * composition(phi[donor], Phi_old[donor]);
        } else {
            if (inflow.empty())
                throw InputError("bulk transport: inflow through a domain boundary needs inflow_phi_hat");
            G[f.face] = m * inflow[f.face];
        }
    });
    return G;
}

}  // namespace

void transport_bulk(const Grid& grid, const std::vector<double>& Phi_old, const FaceFields& M,
                    const FaceFields& inflow_phi_hat, double dt, std::vector<double>& phi) {
    if (Phi_old.size() != grid.cells() || phi.size() != grid.cells())
        throw InputError("bulk transport: Phi_old and phi need one value per cell");
    FaceFields G;
    for (int axis = 0; axis < 3; ++axis) {  // every flux from the old phi: unsplit
        if (M[axis].empty()) continue;
        check_face_field(grid, axis, M[axis], "M");
        check_face_field(grid, axis, inflow_phi_hat[axis], "inflow_phi_hat");
        G[axis] = donor_cell_fluxes(grid, axis, Phi_old, M[axis], inflow_phi_hat[axis], phi);
    }
    for (int axis = 0; axis < 3; ++axis)
        if (!G[axis].empty()) apply_flux_difference(grid, axis, G[axis], dt, phi);  // (eqs. 64, 65: F^bulk)
}

void apply_mass_fluxes(const Grid& grid, const FaceFields& M, double dt, std::vector<double>& Phi) {
    for (int axis = 0; axis < 3; ++axis)
        if (!M[axis].empty()) {
            check_face_field(grid, axis, M[axis], "M");
            apply_flux_difference(grid, axis, M[axis], dt, Phi);
        }
}

double bulk_time_step(const Grid& grid, const std::vector<double>& Phi_old, const FaceFields& M, double cfl) {
    std::vector<double> outflow(grid.cells(), 0.0);  // sum_out |M|/h per cell
    for (int axis = 0; axis < 3; ++axis) {
        if (M[axis].empty()) continue;
        check_face_field(grid, axis, M[axis], "M");
        for_each_face(grid, axis, [&](const FaceCells& f) {
            if (f.duplicate) return;  // the last layer of a periodic axis is the first one
            const double m = M[axis][f.face] / grid.h[axis];
            if (m > 0.0 && f.lower != kNoCell) outflow[f.lower] += m;
            if (m < 0.0 && f.upper != kNoCell) outflow[f.upper] -= m;
        });
    }
    double dt = std::numeric_limits<double>::infinity();
    for (std::size_t c = 0; c < grid.cells(); ++c)
        if (grid.is_inside(c) && outflow[c] > 0.0) dt = std::min(dt, Phi_old[c] / outflow[c]);
    return cfl * dt;
}

FaceFields stream_function_mass_fluxes(const Grid& grid, const std::function<double(double, double)>& psi) {
    if (grid.n[1] != 1) throw InputError("stream function: needs a grid in the x-z plane (ny = 1)");
    const int nx = grid.n[0], nz = grid.n[2];
    std::vector<double> corner(static_cast<std::size_t>(nx + 1) * (nz + 1));
    const auto at = [nx](int i, int k) { return static_cast<std::size_t>(i) + static_cast<std::size_t>(nx + 1) * k; };
    for (int k = 0; k <= nz; ++k)
        for (int i = 0; i <= nx; ++i) {
            bool wall = false;  // a corner of an outside cell lies on the streamline psi = 0
            for (int di = -1; di <= 0; ++di)
                for (int dk = -1; dk <= 0; ++dk) {
                    const int ci = i + di, ck = k + dk;
                    if (ci >= 0 && ci < nx && ck >= 0 && ck < nz && !grid.is_inside(grid.index(ci, 0, ck))) wall = true;
                }
            corner[at(i, k)] = wall ? 0.0 : psi(grid.origin[0] + i * grid.h[0], grid.origin[2] + k * grid.h[2]);
        }
    FaceFields M;
    M[0].assign(grid.faces(0), 0.0);
    M[2].assign(grid.faces(2), 0.0);
    for (int k = 0; k < nz; ++k)
        for (int i = 0; i <= nx; ++i)  // x-faces: M_x = d(psi)/dz
            M[0][grid.face_index(0, i, 0, k)] = (corner[at(i, k + 1)] - corner[at(i, k)]) / grid.h[2];
    for (int k = 0; k <= nz; ++k)
        for (int i = 0; i < nx; ++i)  // z-faces: M_z = -d(psi)/dx
            M[2][grid.face_index(2, i, 0, k)] = -(corner[at(i + 1, k)] - corner[at(i, k)]) / grid.h[0];
    return M;
}

}  // namespace granseg
