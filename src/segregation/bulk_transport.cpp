#include "segregation/bulk_transport.hpp"

#include "core/error.hpp"
#include "core/threads.hpp"
#include "segregation/reconstruction.hpp"

#include <algorithm>
#include <limits>

namespace granseg {

namespace {

void check_face_field(const Grid& grid, int axis, const std::vector<double>& field, const char* what) {
    if (!field.empty() && field.size() != grid.faces(axis))
        throw InputError(std::string("bulk transport: ") + what + " needs one value per face");
}

}  // namespace

BulkTransport::BulkTransport(Grid grid)
    : grid_(std::move(grid)), inside_(grid_.cells(), 1), parallel_(threads_pay(grid_.cells())) {
    if (!grid_.inside.empty()) inside_ = grid_.inside;
}

void BulkTransport::donor_cell_fluxes(int axis, const std::vector<double>& M, const std::vector<double>& inflow) {
    const Grid& g = grid_;
    std::vector<double>& G = G_[axis];
    G.resize(g.faces(axis));
    const std::size_t n = static_cast<std::size_t>(g.n[axis]), s = g.stride(axis), fs = g.face_stride(axis);
    const std::size_t nx = g.n[0], ny = g.n[1], rows = ny * g.n[2];
    const double* hat = hat_.data();
    const double* m = M.data();
    double* G_out = G.data();
    const unsigned char* in = inside_.data();
    // Faces between two cells of the grid, row by row along x: the face below cell U is f.
    auto row = [&](int& through_wall, std::size_t r) {
        const std::size_t j = r % ny, k = r / ny, layer = axis == 1 ? j : k;
        const std::size_t f0 = g.face_index(axis, 0, static_cast<int>(j), static_cast<int>(k)), c0 = nx * r;
        if (axis != 0 && layer == 0) return;  // the row's faces along y or z lie on the domain boundary
        for (std::size_t i = axis == 0 ? 1 : 0; i < nx; ++i) {
            const std::size_t f = f0 + i, U = c0 + i, L = U - s;
            G_out[f] = m[f] * (m[f] > 0.0 ? hat[L] : hat[U]);  // hat = 0 in outside cells
            through_wall |= (m[f] != 0.0) & !(in[L] & in[U]);
        }
    };
    const int through_wall = parallel_fold(parallel_, rows, 0, row, [](int a, int b) { return a | b; });
    const auto wall_flux = [&](std::size_t face) {
        return InvariantError("bulk transport: mass flux " + std::to_string(M[face]) + " through a wall face (axis " +
                              std::to_string(axis) + ", face " + std::to_string(face) + ")");
    };
    // A face on the domain boundary: periodic (both cells given), wall, or open (in- or outflow).
    const auto boundary = [&](std::size_t f, std::size_t lower, std::size_t upper) {
        G[f] = 0.0;
        if (M[f] == 0.0) return;
        const bool lower_in = lower != kNoCell && in[lower], upper_in = upper != kNoCell && in[upper];
        if (lower_in && upper_in) {
            G[f] = M[f] * hat[M[f] > 0.0 ? lower : upper];
            return;
        }
        if ((lower != kNoCell && !lower_in) || (upper != kNoCell && !upper_in) || (!lower_in && !upper_in)) throw wall_flux(f);
        const bool outflow = lower_in ? M[f] > 0.0 : M[f] < 0.0;
        if (!outflow && inflow.empty()) throw InputError("bulk transport: inflow through a domain boundary needs inflow_phi_hat");
        G[f] = M[f] * (outflow ? hat[lower_in ? lower : upper] : inflow[f]);
    };
    for_each_line(g, axis, [&](std::size_t cell0, std::size_t face0) {
        const std::size_t last = cell0 + (n - 1) * s;
        const bool periodic = g.periodic[axis];
        boundary(face0, periodic ? last : kNoCell, cell0);
        boundary(face0 + n * fs, last, periodic ? cell0 : kNoCell);
        if (through_wall)  // find the face for the message
            for (std::size_t l = 1; l < n; ++l)
                if (M[face0 + l * fs] != 0.0 && !(in[cell0 + (l - 1) * s] && in[cell0 + l * s])) throw wall_flux(face0 + l * fs);
    });
}

double BulkTransport::step(const std::vector<double>& Phi_old, const FaceFieldRefs& M, const FaceFields& inflow_phi_hat,
                           double dt, std::vector<double>& phi, double Phi_min) {
    const Grid& g = grid_;
    const std::size_t cells = g.cells(), nx = g.n[0], ny = g.n[1], rows = ny * g.n[2];
    if (Phi_old.size() != cells || phi.size() != cells)
        throw InputError("bulk transport: Phi_old and phi need one value per cell");
    hat_.resize(cells);
    const unsigned char* in = inside_.data();
    const double* Phi = Phi_old.data();
    double *hat = hat_.data(), *u = phi.data();
    parallel_for(parallel_, cells, [&](std::size_t c) { hat[c] = in[c] ? composition(u[c], Phi[c]) : 0.0; });
    // The axes that carry mass (more than one cell and a flux field), in the order x, y, z.
    int axes[3], along = 0;
    double inv_h[3];
    const double *G[3], *m[3];
    for (int axis = 0; axis < 3; ++axis) {  // every flux from the old phi: unsplit
        if (g.n[axis] <= 1 || M[axis] == nullptr || M[axis]->empty()) continue;
        check_face_field(g, axis, *M[axis], "M");
        check_face_field(g, axis, inflow_phi_hat[axis], "inflow_phi_hat");
        donor_cell_fluxes(axis, *M[axis], inflow_phi_hat[axis]);
        axes[along] = axis, inv_h[along] = 1.0 / g.h[axis], G[along] = G_[axis].data(), m[along] = M[axis]->data();
        ++along;
    }
    // (eqs. 64, 65: F^bulk) in the mass balance's order: the net outflow first, then one subtraction.
    // largest_rate: max of sum_out |M|/(h Phi_old) over cells with Phi_old >= Phi_min
    auto row = [&](double& largest_rate, std::size_t r) {
        const int j = static_cast<int>(r % ny), k = static_cast<int>(r / ny);
        std::size_t lower[3], step[3];
        for (int q = 0; q < along; ++q) lower[q] = g.face_index(axes[q], 0, j, k), step[q] = g.face_stride(axes[q]);
        for (std::size_t i = 0; i < nx; ++i) {
            const std::size_t c = nx * r + i;
            if (!in[c]) continue;
            double net = 0.0, out = 0.0;
            for (int q = 0; q < along; ++q) {
                const std::size_t fl = lower[q] + i, fu = fl + step[q];
                net += (G[q][fu] - G[q][fl]) * inv_h[q];
                out += (std::max(m[q][fu], 0.0) - std::min(m[q][fl], 0.0)) * inv_h[q];
            }
            u[c] = u[c] - dt * net;
            if (Phi[c] >= Phi_min && Phi[c] > 0.0 && out > largest_rate * Phi[c]) largest_rate = out / Phi[c];
        }
    };
    return dt * parallel_fold(parallel_, rows, 0.0, row, [](double a, double b) { return std::max(a, b); });
}

void transport_bulk(const Grid& grid, const std::vector<double>& Phi_old, const FaceFields& M, const FaceFields& inflow_phi_hat,
                    double dt, std::vector<double>& phi) {
    BulkTransport(grid).step(Phi_old, refs(M), inflow_phi_hat, dt, phi);
}

double bulk_time_step(const Grid& grid, const std::vector<double>& Phi_old, const FaceFieldRefs& M, double cfl, double Phi_min) {
    std::vector<double> outflow(grid.cells(), 0.0);  // sum_out |M|/h per cell
    for (int axis = 0; axis < 3; ++axis) {
        if (M[axis] == nullptr || M[axis]->empty()) continue;
        check_face_field(grid, axis, *M[axis], "M");
        for_each_face(grid, axis, [&](const FaceCells& f) {
            if (f.duplicate) return;  // the last layer of a periodic axis is the first one
            const double m = (*M[axis])[f.face] / grid.h[axis];
            if (m > 0.0 && f.lower != kNoCell) outflow[f.lower] += m;
            if (m < 0.0 && f.upper != kNoCell) outflow[f.upper] -= m;
        });
    }
    double dt = std::numeric_limits<double>::infinity();
    for (std::size_t c = 0; c < grid.cells(); ++c)
        if (grid.is_inside(c) && outflow[c] > 0.0 && Phi_old[c] >= Phi_min) dt = std::min(dt, Phi_old[c] / outflow[c]);
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
