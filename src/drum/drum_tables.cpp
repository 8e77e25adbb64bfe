#include "drum/drum_tables.hpp"

#include "core/format.hpp"

namespace granseg {

DataTable composition_cells(const Grid& grid, const std::vector<double>& phi_hat, const std::string& what,
                            const std::function<bool(std::size_t)>& bed, const InertialPosition& where) {
    DataTable cells;
    cells.comment(what + " (bed cells, inertial frame, m; cell size " + format_number(grid.h[0]) + " m)");
    for_each_bed_cell(grid, [&](const BedCell& b) {
        if (bed && !bed(b.c)) return;
        const std::array<double, 2> xz = where ? where(b.x, b.z) : std::array<double, 2>{b.x, b.z};
        cells.row({{"x", xz[0]}, {"z", xz[1]}, {"phi_hat", phi_hat[b.c]}});
    });
    return cells;
}

}  // namespace granseg
