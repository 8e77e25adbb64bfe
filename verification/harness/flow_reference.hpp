// Independent references shared by the flow verification programs (verify_flow_*.cpp): the
// equation of state inverted with GSL's Brent root finder, the lithostatic balance
// dp/ds = Phi(p) |g| integrated with GSL odeiv2, and small helpers to set up and run a column.
// Nothing here calls the solver's own inversion (drum/bed.cpp) or its discrete equilibrium.
#pragma once

#include "closures/material.hpp"
#include "flow/flow_solver.hpp"
#include "harness/check_table.hpp"
#include "harness/program.hpp"

#include <functional>
#include <string>
#include <vector>

namespace granseg::verify {

/// Phi with p(Phi, T) = p on [0, Phi_rcp) (0 for p <= 0), GSL Brent.
double Phi_of_pressure(const Material& m, double p, double T, double Phi_rcp, double Phi_co);

/// Lithostatic column of mass `mass` per area (m) at temperature T under gravity g (m/s^2): the
/// bottom carries the whole weight, p(0) = g mass, and dp/dz = -g Phi(p) is integrated upwards
/// with gsl_odeiv2 (RK8(9) Prince-Dormand, relative tolerance 1e-12) through the dense and the
/// kinetic branch of p(Phi). Returns Phi at the heights z (increasing); the dense part ends where
/// p falls to p(Phi_co), and `surface` receives the last z below that.
std::vector<double> lithostatic_profile(const Material& m, double T, double Phi_rcp, double Phi_co, double g, double mass,
                                        const std::vector<double>& z, double* surface = nullptr);
/// The same with a temperature that varies with height, T(z).
std::vector<double> lithostatic_profile(const Material& m, const std::function<double(double)>& T_of_z, double Phi_rcp,
                                        double Phi_co, double g, double mass, const std::vector<double>& z,
                                        double* surface = nullptr);

/// The start of every flow verification program: its command line, and the substitute material.
/// The solver runs on one OpenMP thread: `make verify` runs two programs at a time on the
/// machine's two cores, and a second, spinning thread per program would only contend for them.
struct FlowProgram {
    ProgramOptions options;
    Material material;
};
FlowProgram flow_program(int argc, char** argv);

/// The flow solver's time-stepping modes, in the order every flow verification program runs them
/// with the same checks and tolerances (docs/flow_solver.md Sect. 3).
inline constexpr TimeStepping kFlowModes[] = {TimeStepping::explicit_waves, TimeStepping::semi_implicit};

/// The checks of one mode: what a flow verification program runs once per mode of kFlowModes.
using FlowModeCheck = std::function<void(CheckTable& table, const ProgramOptions& options, const Material& m, TimeStepping mode)>;

/// Runs `check` for every mode of kFlowModes into one table titled `title`; returns its exit code.
int run_flow_modes(const FlowProgram& program, const std::string& title, const FlowModeCheck& check);

/// "[explicit] " or "[semi-implicit] ": the prefix of a check's name in a mode.
std::string mode_tag(TimeStepping mode);

/// "" for the explicit mode, "_semi_implicit" otherwise: the suffix of a data file's name (the
/// figures plot the explicit mode's files).
std::string mode_suffix(TimeStepping mode);

/// Largest |Phi u| over inside cells (the momentum density, m/s).
double max_momentum(const FlowSolver& s);

/// Sum over inside cells of Phi times cell volume, in long double (a reference for round-off).
long double exact_mass(const FlowSolver& s);

}  // namespace granseg::verify
