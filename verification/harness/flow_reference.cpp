#include "harness/flow_reference.hpp"

#include "closures/closures.hpp"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_odeiv2.h>
#include <gsl/gsl_roots.h>

#include <array>
#include <cmath>
#include <memory>
#include <stdexcept>

namespace granseg::verify {

namespace {

struct Eos {
    const Material* m;
    double T, Phi_rcp, Phi_co, target;
};

double pressure_residual(double Phi, void* params) {
    const Eos* e = static_cast<const Eos*>(params);
    return evaluate_closures_at(*e->m, Phi, e->T, e->Phi_rcp, e->Phi_co).p - e->target;
}

struct Column {
    Eos eos;
    double g;
};

int column_rhs(double /*s*/, const double y[], double dyds[], void* params) {
    Column* c = static_cast<Column*>(params);
    const double Phi = Phi_of_pressure(*c->eos.m, y[0], c->eos.T, c->eos.Phi_rcp, c->eos.Phi_co);
    dyds[0] = Phi * c->g;  // dp/ds
    dyds[1] = Phi;         // dm/ds
    return GSL_SUCCESS;
}

/// (p, m) at depth s, integrated from the surface.
std::array<double, 2> integrate_to(Column& column, double s) {
    gsl_odeiv2_system sys{column_rhs, nullptr, 2, &column};
    std::unique_ptr<gsl_odeiv2_driver, decltype(&gsl_odeiv2_driver_free)> driver(
        gsl_odeiv2_driver_alloc_y_new(&sys, gsl_odeiv2_step_rk8pd, 1e-6, 1e-12, 1e-12), gsl_odeiv2_driver_free);
    double y[2] = {evaluate_closures_at(*column.eos.m, column.eos.Phi_co, column.eos.T, column.eos.Phi_rcp, column.eos.Phi_co).p, 0.0};
    double s0 = 0.0;
    if (s > 0.0 && gsl_odeiv2_driver_apply(driver.get(), &s0, s, y) != GSL_SUCCESS)
        throw std::runtime_error("lithostatic_profile: gsl_odeiv2_driver_apply failed");
    return {y[0], y[1]};
}

}  // namespace

double Phi_of_pressure(const Material& m, double p, double T, double Phi_rcp, double Phi_co) {
    Eos eos{&m, T, Phi_rcp, Phi_co, p};
    double lo = Phi_co, hi = Phi_rcp * (1.0 - 1e-12);
    if (pressure_residual(lo, &eos) >= 0.0) return lo;
    gsl_function f{pressure_residual, &eos};
    std::unique_ptr<gsl_root_fsolver, decltype(&gsl_root_fsolver_free)> solver(
        gsl_root_fsolver_alloc(gsl_root_fsolver_brent), gsl_root_fsolver_free);
    gsl_root_fsolver_set(solver.get(), &f, lo, hi);
    for (int it = 0; it < 200; ++it) {
        gsl_root_fsolver_iterate(solver.get());
        lo = gsl_root_fsolver_x_lower(solver.get());
        hi = gsl_root_fsolver_x_upper(solver.get());
        if (gsl_root_test_interval(lo, hi, 0.0, 1e-15) == GSL_SUCCESS) break;
    }
    return gsl_root_fsolver_root(solver.get());
}

std::vector<double> lithostatic_profile(const Material& m, double T, double Phi_rcp, double Phi_co, double g,
                                        double mass, const std::vector<double>& z, double* surface) {
    Column column{{&m, T, Phi_rcp, Phi_co, 0.0}, g};
    // Depth s* with m(s*) = mass, by bisection (m grows with s; Phi <= Phi_rcp bounds s* below).
    double lo = mass / Phi_rcp, hi = mass / Phi_co;
    for (int it = 0; it < 80; ++it) {
        const double mid = 0.5 * (lo + hi);
        (integrate_to(column, mid)[1] < mass ? lo : hi) = mid;
    }
    const double s_star = 0.5 * (lo + hi);
    if (surface) *surface = s_star;
    std::vector<double> Phi;
    for (double zk : z) {
        const double s = s_star - zk;
        Phi.push_back(s <= 0.0 ? 0.0 : Phi_of_pressure(m, integrate_to(column, s)[0], T, Phi_rcp, Phi_co));
    }
    return Phi;
}

double max_momentum(const FlowSolver& s) {
    double worst = 0.0;
    for (std::size_t c = 0; c < s.grid().cells(); ++c)
        if (s.grid().is_inside(c))
            for (int b = 0; b < 3; ++b) worst = std::max(worst, std::fabs(s.Phi()[c] * s.u(b)[c]));
    return worst;
}

long double exact_mass(const FlowSolver& s) {
    long double sum = 0.0L;
    for (std::size_t c = 0; c < s.grid().cells(); ++c)
        if (s.grid().is_inside(c)) sum += s.Phi()[c];
    return sum * s.grid().cell_volume();
}

}  // namespace granseg::verify
