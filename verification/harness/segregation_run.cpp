#include "harness/segregation_run.hpp"

#include "harness/program.hpp"

#include <algorithm>
#include <cmath>

namespace granseg::verify {

namespace {

long double sum(const std::vector<double>& u) {
    long double s = 0.0L;
    for (double v : u) s += v;
    return s;
}

}  // namespace

double relative_mass_change(const std::vector<double>& before, const std::vector<double>& after) {
    const long double m0 = sum(before), m1 = sum(after);
    return static_cast<double>(std::fabs(m1 - m0) / m0);
}

double bound_violation(const std::vector<double>& phi, const std::vector<double>& Phi) {
    double worst = 0.0;
    for (std::size_t i = 0; i < phi.size(); ++i) worst = std::max({worst, -phi[i], phi[i] - Phi[i]});
    return worst;
}

SegregationOptions scheme_options(SegregationScheme scheme, double cfl) {
    SegregationOptions options;
    options.scheme = scheme;
    options.limiter = Limiter::mc;
    options.cfl = cfl;
    return options;
}

std::string scheme_column(SegregationScheme scheme) {
    std::string name = scheme_name(scheme);
    std::replace(name.begin(), name.end(), '-', '_');
    return name;
}

ColumnRun run_column(const Column& column, const std::vector<double>& phi0, const SegregationOptions& options, double t_end,
                     bool monitor) {
    ColumnRun run;
    run.phi = phi0;
    run.max_excess = -INFINITY;
    run.min_phi = INFINITY;
    SegregationSolver solver(column.grid, options);
    const std::vector<double>& Phi = column.fields.Phi;
    const auto observe = [&](double, double) {
        for (std::size_t i = 0; i < run.phi.size(); ++i) {
            const double v = run.phi[i];
            if (!std::isfinite(v)) ++run.nonfinite;
            run.max_excess = std::max(run.max_excess, v - Phi[i]);
            run.min_phi = std::min(run.min_phi, v);
        }
    };
    const double start = cpu_seconds();
    run.steps = monitor ? solver.advance(column.fields, t_end, run.phi, observe) : solver.advance(column.fields, t_end, run.phi);
    run.seconds = cpu_seconds() - start;
    run.updates = solver.cell_updates();
    run.correction = solver.largest_correction();
    run.mass_drift = relative_mass_change(phi0, run.phi);
    return run;
}

double fitted_order(const std::vector<int>& cells, const std::vector<double>& errors) {
    double sx = 0, sy = 0, sxx = 0, sxy = 0;
    const double n = static_cast<double>(cells.size());
    for (std::size_t i = 0; i < cells.size(); ++i) {
        const double x = std::log(static_cast<double>(cells[i])), y = -std::log(errors[i]);
        sx += x, sy += y, sxx += x * x, sxy += x * y;
    }
    return (n * sxy - sx * sy) / (n * sxx - sx * sx);
}

}  // namespace granseg::verify
