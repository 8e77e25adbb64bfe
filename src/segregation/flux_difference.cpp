#include "segregation/flux_difference.hpp"

namespace granseg {

void apply_flux_difference(const Grid& grid, int axis, const std::vector<double>& F, double dt, std::vector<double>& u) {
    const double ratio = dt / grid.h[axis];
    const std::size_t n = static_cast<std::size_t>(grid.n[axis]);
    const std::size_t stride = grid.stride(axis), face_stride = grid.face_stride(axis);
    for_each_line(grid, axis, [&](std::size_t cell0, std::size_t face0) {
        for (std::size_t l = 0; l < n; ++l) {
            const std::size_t cell = cell0 + l * stride, lower = face0 + l * face_stride;
            if (!grid.is_inside(cell)) continue;
            // (eq. 64), written so that each face moves the same rounded amount ratio*F out of one
            // cell and into the other, and a small net change is never lost against a large u
            // (u + (g_low - g_up) drops any net change below half an ulp of u, always in the same
            // direction near a balance, and drifts): the sum changes only by the rounding of the
            // two additions.
            u[cell] = (u[cell] + ratio * F[lower]) - ratio * F[lower + face_stride];
        }
    });
}

std::vector<double> arithmetic_mean_faces(const Grid& grid, int axis, const std::vector<double>& u) {
    std::vector<double> mean(grid.faces(axis), 0.0);
    for_each_face(grid, axis, [&](const FaceCells& f) {
        const bool has_lower = f.lower != kNoCell && grid.is_inside(f.lower);
        const bool has_upper = f.upper != kNoCell && grid.is_inside(f.upper);
        if (has_lower && has_upper)
            mean[f.face] = 0.5 * (u[f.lower] + u[f.upper]);
        else if (has_lower || has_upper)
            mean[f.face] = u[has_lower ? f.lower : f.upper];
    });
    return mean;
}

}  // namespace granseg
