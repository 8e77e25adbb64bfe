#include "drum/pattern_metrics.hpp"

#include "segregation/reconstruction.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace granseg {

PatternMetrics pattern_metrics(const Grid& grid, const std::vector<double>& phi, const std::vector<double>& Phi,
                               const PatternRegions& regions, const std::vector<double>& phi_hat_initial) {
    double small[3] = {0, 0, 0}, all[3] = {0, 0, 0}, bed_small = 0, bed_all = 0, sum = 0, sum2 = 0;
    long count = 0;
    PatternMetrics m;
    for_each_bed_cell(grid, [&](const BedCell& b) {
        const std::size_t c = b.c;
        if (!(Phi[c] > regions.bed_level)) return;
        const double r = std::hypot(b.x, b.z);  // distance from the drum centre
        const int region = r < regions.r_core                                     ? 0
                           : r < regions.r_ring                                   ? 1
                           : regions.shape.gauge(b.x, b.z) >= regions.r_periphery ? 2
                                                                                  : -1;
        const double phi_hat = composition(phi[c], Phi[c]);
        if (region >= 0) small[region] += phi[c], all[region] += Phi[c];
        if (region == 0) m.core_deviation = std::max(m.core_deviation, std::fabs(phi_hat - phi_hat_initial[c]));
        bed_small += phi[c], bed_all += Phi[c];
        sum += phi_hat;
        ++count;
    });
    const double mean = sum / count;
    for_each_bed_cell(grid, [&](const BedCell& b) {  // two passes: no cancellation
        if (Phi[b.c] > regions.bed_level) sum2 += std::pow(composition(phi[b.c], Phi[b.c]) - mean, 2);
    });
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const auto fraction = [&](int region) { return all[region] > 0.0 ? small[region] / all[region] : nan; };
    m.core = fraction(0), m.ring = fraction(1), m.periphery = fraction(2);
    m.mean = bed_small / bed_all;
    const double variance = sum2 / count, full = mean * (1 - mean);
    m.index = full > 0.0 ? std::sqrt(variance / full) : 0.0;
    return m;
}

PatternRegions drum_regions(double d, double delta0, double R) {
    PatternRegions r;
    r.r_core = d - delta0;
    r.r_ring = d;
    r.r_periphery = 0.8 * R;
    return r;
}

double disc_share(const Grid& grid, const std::vector<double>& phi, const std::vector<double>& Phi, double radius,
                  double bed_level) {
    double small = 0, all = 0;
    for_each_bed_cell(grid, [&](const BedCell& b) {
        if (Phi[b.c] > bed_level && std::hypot(b.x, b.z) < radius) small += phi[b.c], all += Phi[b.c];
    });
    return all > 0.0 ? small / all : std::numeric_limits<double>::quiet_NaN();
}

ShellProfile shell_profile(const Grid& grid, const std::vector<double>& phi, const std::vector<double>& Phi, double radius,
                           int shells, double bed_level) {
    if (shells < 1 || !(radius > 0.0)) throw InputError("shell profile: needs shells >= 1 and radius > 0");
    std::vector<double> r_sum(shells, 0.0), small(shells, 0.0), all(shells, 0.0);
    ShellProfile p;
    p.cells.assign(shells, 0);
    for_each_bed_cell(grid, [&](const BedCell& b) {
        const std::size_t c = b.c;
        if (!(Phi[c] > bed_level)) return;
        const double r = std::hypot(b.x, b.z);
        const int s = std::min(shells - 1, static_cast<int>(r / radius * shells));
        r_sum[s] += r, small[s] += phi[c], all[s] += Phi[c], ++p.cells[s];
    });
    const double nan = std::numeric_limits<double>::quiet_NaN();
    for (int s = 0; s < shells; ++s) {
        p.r.push_back(p.cells[s] > 0 ? r_sum[s] / p.cells[s] : nan);
        p.phi_hat.push_back(all[s] > 0.0 ? small[s] / all[s] : nan);
    }
    return p;
}

}  // namespace granseg
