#include "harness/flow_reference.hpp"

#include "closures/closures.hpp"
#include "core/threads.hpp"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_odeiv2.h>
#include <gsl/gsl_roots.h>

#include <array>
#include <cmath>
#include <functional>
#include <memory>

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

struct HydrostaticColumn {
    Eos eos;
    double g;
    const std::function<double(double)>* T_of_z;  // or nullptr: T = eos.T
};

int column_rhs(double z, const double y[], double dydz[], void* params) {
    HydrostaticColumn* c = static_cast<HydrostaticColumn*>(params);
    const double T = c->T_of_z ? (*c->T_of_z)(z) : c->eos.T;
    dydz[0] = -c->g * Phi_of_pressure(*c->eos.m, y[0], T, c->eos.Phi_rcp, c->eos.Phi_co);  // dp/dz
    return GSL_SUCCESS;
}

}  // namespace

double Phi_of_pressure(const Material& m, double p, double T, double Phi_rcp, double Phi_co) {
    if (!(p > 0.0)) return 0.0;
    Eos eos{&m, T, Phi_rcp, Phi_co, p};
    double lo = 0.0, hi = Phi_rcp * (1.0 - 1e-12);
    gsl_function f{pressure_residual, &eos};
    std::unique_ptr<gsl_root_fsolver, decltype(&gsl_root_fsolver_free)> solver(gsl_root_fsolver_alloc(gsl_root_fsolver_brent),
                                                                               gsl_root_fsolver_free);
    gsl_root_fsolver_set(solver.get(), &f, lo, hi);
    for (int it = 0; it < 300; ++it) {
        gsl_root_fsolver_iterate(solver.get());
        lo = gsl_root_fsolver_x_lower(solver.get());
        hi = gsl_root_fsolver_x_upper(solver.get());
        if (gsl_root_test_interval(lo, hi, 0.0, 1e-15) == GSL_SUCCESS) break;
    }
    return gsl_root_fsolver_root(solver.get());
}

std::vector<double> lithostatic_profile(const Material& m, double T, double Phi_rcp, double Phi_co, double g, double mass,
                                        const std::vector<double>& z, double* surface) {
    return lithostatic_profile(
        m, [T](double) { return T; }, Phi_rcp, Phi_co, g, mass, z, surface);
}

std::vector<double> lithostatic_profile(const Material& m, const std::function<double(double)>& T_of_z, double Phi_rcp,
                                        double Phi_co, double g, double mass, const std::vector<double>& z, double* surface) {
    // The bottom carries the whole weight, p(0) = g mass; integrate dp/dz = -g Phi(p) upwards.
    HydrostaticColumn column{{&m, T_of_z(0.0), Phi_rcp, Phi_co, 0.0}, g, &T_of_z};
    gsl_odeiv2_system sys{column_rhs, nullptr, 1, &column};
    std::unique_ptr<gsl_odeiv2_driver, decltype(&gsl_odeiv2_driver_free)> driver(
        gsl_odeiv2_driver_alloc_y_new(&sys, gsl_odeiv2_step_rk8pd, 1e-7, 1e-13, 1e-12), gsl_odeiv2_driver_free);
    double y[1] = {g * mass}, zz = 0.0;
    std::vector<double> Phi;
    if (surface) *surface = 0.0;
    for (double zk : z) {
        const double T = T_of_z(zk), p_co = evaluate_closures_at(m, Phi_co, T, Phi_rcp, Phi_co).p;
        // Stop once the dense part ends (p below p(Phi_co)); above lies the kinetic tail, whose
        // pressure decays on the scale T/g (1e-13 m at the floor temperature).
        if (y[0] > p_co && gsl_odeiv2_driver_apply(driver.get(), &zz, zk, y) != GSL_SUCCESS) y[0] = 0.0;
        if (y[0] <= p_co) y[0] = 0.0;
        if (y[0] > 0.0 && surface) *surface = zk;
        Phi.push_back(Phi_of_pressure(m, y[0], T, Phi_rcp, Phi_co));
    }
    return Phi;
}

FlowProgram flow_program(int argc, char** argv) {
    ProgramOptions options = parse_program_options(argc, argv);
    static const ThreadScope one(1);  // the program runs on one thread
    return {options, Material::glass_substitute()};
}

int run_flow_modes(const FlowProgram& program, const std::string& title, const FlowModeCheck& check) {
    CheckTable table(title);
    for (const TimeStepping mode : kFlowModes) check(table, program.options, program.material, mode);
    return table.finish();
}

std::string mode_tag(TimeStepping mode) { return "[" + choice_name(kTimeSteppings, mode) + "] "; }

std::string mode_suffix(TimeStepping mode) {
    if (mode == TimeStepping::explicit_waves) return "";
    std::string name = "_" + choice_name(kTimeSteppings, mode);
    for (char& ch : name) ch = ch == '-' ? '_' : ch;
    return name;
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
