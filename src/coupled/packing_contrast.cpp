#include "coupled/packing_contrast.hpp"

#include <algorithm>
#include <cmath>
#include <map>

namespace granseg {

namespace {

/// Count, sum and sum of squares of Phi of one kind of cell in one depth bin.
struct Moments {
    long n = 0;
    double sum = 0, sum2 = 0;
    void add(double v) { ++n, sum += v, sum2 += v * v; }
    double mean() const { return sum / n; }
    double squares_about_mean() const { return std::max(0.0, sum2 - sum * sum / n); }
};

}  // namespace

PackingContrast packing_contrast(const CoupledTumbler& tumbler, double surface_angle_deg, const PackingContrastOptions& o) {
    const FlowSolver& s = tumbler.flow();
    const Grid& g = s.grid();
    const std::vector<double> hat = tumbler.phi_hat();
    const double a = surface_angle_deg * M_PI / 180.0, nx = -std::sin(a), nz = std::cos(a);
    struct Cell {
        double height, Phi, phi_hat;
    };
    std::vector<Cell> cells;
    double top = -INFINITY;
    for_each_bed_cell(g, [&](const BedCell& b) {
        const std::size_t c = b.c;
        if (!(s.Phi()[c] > o.bed_level)) return;
        const std::array<double, 2> X = s.frame().to_lab_position(s.time(), b.x, b.z);
        const double height = nx * X[0] + nz * X[1];
        top = std::max(top, height);
        if (std::hypot(s.u(0)[c], s.u(2)[c]) <= o.v_flow) cells.push_back({height, s.Phi()[c], hat[c]});
    });
    std::map<long, std::array<Moments, 2>> bins;  // depth bin -> {mixed, pure}
    for (const Cell& c : cells) {
        const bool mixed = c.phi_hat > o.mixed_lo && c.phi_hat < o.mixed_hi;
        const bool pure = c.phi_hat < o.pure || c.phi_hat > 1.0 - o.pure;
        if (mixed || pure) bins[static_cast<long>(std::floor((top - c.height) / o.bin))][mixed ? 0 : 1].add(c.Phi);
    }
    PackingContrast r;
    double weight = 0, squares = 0;
    long dof = 0;
    for (const auto& [bin, m] : bins) {
        if (m[0].n == 0 || m[1].n == 0) continue;
        const double w = static_cast<double>(std::min(m[0].n, m[1].n));
        r.contrast += w * (m[0].mean() - m[1].mean()), weight += w;
        squares += m[0].squares_about_mean() + m[1].squares_about_mean();
        dof += m[0].n + m[1].n - 2;
        ++r.bins, r.mixed += m[0].n, r.pure += m[1].n;
    }
    r.contrast = weight > 0 ? r.contrast / weight : NAN;
    r.spread = dof > 0 ? std::sqrt(squares / dof) : NAN;
    return r;
}

}  // namespace granseg
