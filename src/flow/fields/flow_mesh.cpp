#include "flow/fields/flow_mesh.hpp"

#include "core/error.hpp"
#include "core/threads.hpp"

#include <algorithm>

namespace granseg {

namespace {
/// Kind of every face of `axis` (FaceKind): interior between two inside cells, a wall where only
/// one side is inside (the domain boundary counts as outside unless the axis is periodic).
std::vector<unsigned char> classify_faces(const Grid& grid, int a) {
    std::vector<unsigned char> kind(grid.faces(a), kNoFace);
    if (grid.n[a] <= 1) return kind;
    std::array<int, 3> m = grid.n;
    m[a] += 1;
    for (int k = 0; k < m[2]; ++k)
        for (int j = 0; j < m[1]; ++j)
            for (int i = 0; i < m[0]; ++i) {
                std::array<int, 3> lo{i, j, k}, hi{i, j, k};
                const int layer = hi[a];
                lo[a] = layer - 1;
                bool has_lo = layer >= 1, has_hi = layer < grid.n[a];
                if (grid.periodic[a]) {
                    if (!has_lo) lo[a] = grid.n[a] - 1, has_lo = true;
                    if (!has_hi) hi[a] = 0, has_hi = true;
                }
                const bool in_lo = has_lo && grid.is_inside(grid.index(lo[0], lo[1], lo[2]));
                const bool in_hi = has_hi && grid.is_inside(grid.index(hi[0], hi[1], hi[2]));
                kind[grid.face_index(a, i, j, k)] = in_lo && in_hi ? kInterior
                                                    : in_hi        ? kWallBelow
                                                    : in_lo        ? kWallAbove
                                                                   : kNoFace;
            }
    return kind;
}
/// The faces of `axis` that are interior or walls, with their cells (MeshFace).
std::vector<MeshFace> face_list(const Grid& grid, int a, const std::vector<unsigned char>& kind) {
    std::vector<MeshFace> list;
    if (grid.n[a] <= 1) return list;
    std::array<int, 3> m = grid.n;
    m[a] += 1;
    for (int k = 0; k < m[2]; ++k)
        for (int j = 0; j < m[1]; ++j)
            for (int i = 0; i < m[0]; ++i) {
                const std::size_t f = grid.face_index(a, i, j, k);
                if (kind[f] == kNoFace) continue;
                std::array<int, 3> lo{i, j, k}, hi{i, j, k};
                lo[a] = (hi[a] + grid.n[a] - 1) % grid.n[a];  // periodic wrap; a wall below has no lower cell
                hi[a] = hi[a] % grid.n[a];
                const std::size_t c_lo = grid.index(lo[0], lo[1], lo[2]), c_hi = grid.index(hi[0], hi[1], hi[2]);
                const FaceKind fk = static_cast<FaceKind>(kind[f]);
                list.push_back({f, fk == kWallBelow ? c_hi : c_lo, fk == kWallAbove ? c_lo : c_hi, fk,
                                grid.periodic[a] && (a == 0   ? i
                                                     : a == 1 ? j
                                                              : k) == grid.n[a]});
            }
    return list;
}
}  // namespace

FlowMesh::FlowMesh(Grid g) : grid(std::move(g)) {
    const std::size_t cells = grid.cells();
    if (!grid.inside.empty() && grid.inside.size() != cells) throw InputError("FlowSolver: grid.inside has the wrong size");
    for (int a = 0; a < 3; ++a) active[a] = grid.n[a] > 1;
    rows = static_cast<std::size_t>(grid.n[1]) * grid.n[2];
    parallel = threads_pay(cells);
    row_lo.assign(rows, 0);
    row_hi.assign(rows, 0);
    inside.assign(cells, 0);
    for (int a = 0; a < 3; ++a) position[a].assign(cells, 0.0);
    for (std::size_t r = 0; r < rows; ++r) {
        const int j = static_cast<int>(r % grid.n[1]), k = static_cast<int>(r / grid.n[1]);
        int lo = grid.n[0], hi = 0;
        for (int i = 0; i < grid.n[0]; ++i) {
            const std::size_t c = grid.index(i, j, k);
            position[0][c] = grid.center(0, i);
            position[1][c] = grid.center(1, j);
            position[2][c] = grid.center(2, k);
            if (!grid.is_inside(c)) continue;
            inside[c] = 1;
            inside_cells.push_back(c);
            lo = std::min(lo, i);
            hi = i + 1;
        }
        row_lo[r] = std::min(lo, hi);
        row_hi[r] = hi;
    }
    for (int a = 0; a < 3; ++a) {
        face_kind[a] = classify_faces(grid, a);
        faces[a] = face_list(grid, a, face_kind[a]);
    }
}

AxisRow FlowMesh::axis_row(int a, std::size_t r) const {
    const std::size_t nx = grid.n[0], ny = grid.n[1];
    const std::size_t j = r % ny, k = r / ny;
    const long n = grid.n[a], stride = static_cast<long>(grid.stride(a));
    const bool periodic = grid.periodic[a];
    const long wrap_lo = periodic ? (n - 1) * stride : 0, wrap_hi = periodic ? -(n - 1) * stride : 0;
    AxisRow row{};
    row.face0 = a == 0 ? (nx + 1) * r : a == 1 ? nx * (j + (ny + 1) * k) : nx * r;
    row.face_step = grid.face_stride(a);
    if (a == 0) {  // the layer is i itself: only the row's first and last cells meet the boundary
        row.lo = -1, row.hi = 1, row.first_lo = wrap_lo, row.last_hi = wrap_hi;
        row.last = static_cast<int>(n) - 1;
    } else {
        const long layer = a == 1 ? static_cast<long>(j) : static_cast<long>(k);
        row.lo = row.first_lo = layer > 0 ? -stride : wrap_lo;
        row.hi = row.last_hi = layer < n - 1 ? stride : wrap_hi;
        row.last = -1;
    }
    return row;
}

}  // namespace granseg
