#include "core/grid.hpp"

#include "core/error.hpp"

#include <string>

namespace granseg {

Grid Grid::column(int nz, double length) {
    if (nz < 1 || !(length > 0)) throw InputError("Grid::column: need nz >= 1 and length > 0");
    Grid g;
    g.n = {1, 1, nz};
    g.h = {1.0, 1.0, length / nz};
    return g;
}

Grid Grid::plane_xz(int nx, int nz, double x0, double z0, double lx, double lz) {
    if (nx < 1 || nz < 1 || !(lx > 0) || !(lz > 0)) throw InputError("Grid::plane_xz: need nx, nz >= 1 and lx, lz > 0");
    Grid g;
    g.n = {nx, 1, nz};
    g.h = {lx / nx, 1.0, lz / nz};
    g.origin = {x0, 0.0, z0};
    return g;
}

}  // namespace granseg
