#include "coupled/coupled_tables.hpp"

#include "core/format.hpp"
#include "drum/drum_tables.hpp"
#include "flow/flow_tables.hpp"

#include <sstream>

namespace granseg {

namespace {

/// A drum-frame vector (v_x, v_z) in lab components: turned by omega t.
std::array<double, 2> turned(const Frame& f, double t, double vx, double vz) {
    const double a = f.omega * t, ca = std::cos(a), sa = std::sin(a);
    return {ca * vx - sa * vz, sa * vx + ca * vz};
}

}  // namespace

DataTable coupled_field_table(const CoupledTumbler& tumbler) {
    const FlowSolver& s = tumbler.flow();
    const Grid& g = s.grid();
    const Frame& f = s.frame();
    const double t = s.time();
    const std::vector<double> hat = tumbler.phi_hat();
    const FrozenFields& frozen = tumbler.frozen();
    const auto component = [](const std::vector<double>& v, std::size_t c) { return v.empty() ? 0.0 : v[c]; };
    DataTable table;
    table.comment("lab frame, t = " + format_number(t) +
                  " s; slice j = 0; one block per row; m, m/s, m^2/s^2; "
                  "d_s and a = S^sl (eq. 46) of the last segregation sub-step; shear_rate: kappa_max - kappa_min, 1/s");
    for (int k = 0; k < g.n[2]; ++k) {
        for (int i = 0; i < g.n[0]; ++i) {
            const std::size_t c = g.index(i, 0, k);
            const double x = g.center(0, i), z = g.center(2, k);
            const std::array<double, 2> X = f.to_lab_position(t, x, z);
            if (!g.is_inside(c)) {
                table.row({{"x", X[0]},
                           {"z", X[1]},
                           {"Phi", 0},
                           {"phi_hat", 0},
                           {"u_x", 0},
                           {"u_z", 0},
                           {"T", 0},
                           {"ds_x", 0},
                           {"ds_z", 0},
                           {"inside", 0},
                           {"urel_x", 0},
                           {"urel_z", 0},
                           {"a_x", 0},
                           {"a_z", 0},
                           {"shear_rate", 0}});
                continue;
            }
            const std::array<double, 2> u = f.to_lab_velocity(t, x, z, s.u(0)[c], s.u(2)[c]);
            const std::array<double, 2> rel = turned(f, t, s.u(0)[c], s.u(2)[c]);
            const std::array<double, 2> d = turned(f, t, component(tumbler.d_s(0), c), component(tumbler.d_s(2), c));
            const std::array<double, 2> a = turned(f, t, component(frozen.a[0], c), component(frozen.a[2], c));
            table.row({{"x", X[0]},
                       {"z", X[1]},
                       {"Phi", s.Phi()[c]},
                       {"phi_hat", hat[c]},
                       {"u_x", u[0]},
                       {"u_z", u[1]},
                       {"T", s.T()[c]},
                       {"ds_x", d[0]},
                       {"ds_z", d[1]},
                       {"inside", 1.0},
                       {"urel_x", rel[0]},
                       {"urel_z", rel[1]},
                       {"a_x", a[0]},
                       {"a_z", a[1]},
                       {"shear_rate", tumbler.direction(c).principal_shear}});
        }
        table.blank();
    }
    return table;
}

DataTable coupled_composition(const CoupledTumbler& tumbler, double bed_level) {
    const FlowSolver& s = tumbler.flow();
    const double t = s.time();
    return composition_cells(
        s.grid(), tumbler.phi_hat(), "phi_hat at t = " + format_number(t) + " s",
        [&](std::size_t c) { return s.Phi()[c] > bed_level; },
        [&](double x, double z) { return s.frame().to_lab_position(t, x, z); });
}

std::string coupled_vtk(const CoupledTumbler& tumbler) {
    const FlowSolver& s = tumbler.flow();
    const Grid& g = s.grid();
    const std::vector<double> hat = tumbler.phi_hat();
    std::ostringstream out;
    out.precision(9);
    out << flow_vtk(s) << "SCALARS phi_hat double 1\nLOOKUP_TABLE default\n";
    for (int k = 0; k < g.n[2]; ++k)
        for (int i = 0; i < g.n[0]; ++i) out << hat[g.index(i, 0, k)] << "\n";
    out << "VECTORS d_s double\n";
    for (int k = 0; k < g.n[2]; ++k)
        for (int i = 0; i < g.n[0]; ++i) {
            const std::size_t c = g.index(i, 0, k);
            const auto at = [&](int axis) { return tumbler.d_s(axis).empty() ? 0.0 : tumbler.d_s(axis)[c]; };
            const std::array<double, 2> d = turned(s.frame(), s.time(), at(0), at(2));
            out << d[0] << " " << at(1) << " " << d[1] << "\n";
        }
    return out.str();
}

}  // namespace granseg
