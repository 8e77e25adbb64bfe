#include "kinematic/kinematic_tables.hpp"

#include "core/format.hpp"

#include <Eigen/Core>

#include <cmath>

namespace granseg {

DataTable drum_outline(const RollingDrumFlow& flow) {
    DataTable outline;
    outline.comment("index 0: drum wall; 1: free surface; 2: bottom of the flowing layer (inertial frame, m)");
    const double R = flow.radius(), L = flow.half_chord(), d = flow.surface_distance();
    for (int i = 0; i <= 360; ++i) outline.row({{"x", R * std::cos(i * M_PI / 180)}, {"z", R * std::sin(i * M_PI / 180)}});
    outline.blank(), outline.blank();
    for (const double s : {-L, L}) {
        const Eigen::Vector3d X = d * flow.normal() + s * flow.tangent();
        outline.row({{"x", X(0)}, {"z", X(2)}});
    }
    outline.blank(), outline.blank();
    for (int i = 0; i <= 200; ++i) {
        const double s = L * (i / 100.0 - 1);
        const Eigen::Vector3d X = (d - flow.layer_depth(s)) * flow.normal() + s * flow.tangent();
        if (flow.in_drum(X(0), X(2))) outline.row({{"x", X(0)}, {"z", X(2)}});
    }
    return outline;
}

DataTable kinematic_flow_cells(const KinematicTumbler& tumbler) {
    const Grid& g = tumbler.grid();
    const RollingDrumFields& f = tumbler.fields();
    DataTable cells;
    cells.comment(
        "bed cells: inertial velocity (m/s), d_s (out of the bed; 0 in the core), T (m^2/s^2, eq. 45), "
        "a_k = (S^sl)_k (m/s, eq. 46)");
    for_each_bed_cell(g, [&](const BedCell& b) {
        const std::size_t c = b.c;
        cells.row({{"x", b.x},
                   {"z", b.z},
                   {"in_layer", double(f.in_layer[c])},
                   {"ux", f.u[0][c]},
                   {"uz", f.u[2][c]},
                   {"ds_x", tumbler.ds_x()[c]},
                   {"ds_z", tumbler.ds_z()[c]},
                   {"T", tumbler.T()[c]},
                   {"a_x", tumbler.frozen().a[0][c]},
                   {"a_z", tumbler.frozen().a[2][c]}});
    });
    return cells;
}

DataTable kinematic_metrics(const KinematicRunResult& result, const PatternRegions& regions) {
    DataTable table;
    table.comment(
        "segregation index = std(phi_hat over the bed)/sqrt(m (1 - m)); core, ring, periphery: sum(phi)/sum(Phi) for r < " +
        format_number(regions.r_core) + ", " + format_number(regions.r_core) + " <= r < " + format_number(regions.r_ring) +
        ", r >= " + format_number(regions.r_periphery) + " m; core_deviation = max |phi_hat - initial| in the core");
    for (const KinematicSample& r : result.history)
        table.row({{"t", r.t},
                   {"index", r.metrics.index},
                   {"core", r.metrics.core},
                   {"ring", r.metrics.ring},
                   {"periphery", r.metrics.periphery},
                   {"mean", r.metrics.mean},
                   {"core_deviation", r.metrics.core_deviation}});
    return table;
}

DataTable kinematic_shells(const KinematicTumbler& tumbler, const KinematicRunResult& result, int shells) {
    const Grid& g = tumbler.grid();
    std::vector<double> phi0(g.cells());
    for (std::size_t c = 0; c < g.cells(); ++c) phi0[c] = result.phi_hat_initial[c] * tumbler.Phi()[c];
    const ShellProfile before = shell_profile(g, phi0, tumbler.Phi(), tumbler.flow().radius(), shells);
    const ShellProfile after = shell_profile(g, tumbler.phi(), tumbler.Phi(), tumbler.flow().radius(), shells);
    DataTable table;
    table.comment("phi_hat averaged (mass-weighted) over the bed cells of " + std::to_string(shells) +
                  " equal radial shells; r: mean radius of the shell's cells, m; t = " + format_number(tumbler.time()) + " s");
    for (int s = 0; s < shells; ++s)
        if (after.cells[s] > 0)
            table.row({{"r", after.r[s]},
                       {"phi_hat_initial", before.phi_hat[s]},
                       {"phi_hat_final", after.phi_hat[s]},
                       {"cells", double(after.cells[s])}});
    return table;
}

}  // namespace granseg
