// Independent references shared by the flow verification programs (verify_flow_*.cpp): the
// equation of state inverted with GSL's Brent root finder, the lithostatic balance
// dp/ds = Phi(p) |g| integrated with GSL odeiv2, and small helpers to set up and run a column.
// Nothing here calls the solver's own inversion (flow/bed.cpp) or its discrete equilibrium.
#pragma once

#include "closures/material.hpp"
#include "flow/flow_solver.hpp"

#include <vector>

namespace granseg::verify {

/// Phi with p(Phi, T) = p on the dense branch [Phi_co, Phi_rcp) (p >= p(Phi_co)), GSL Brent.
double Phi_of_pressure(const Material& m, double p, double T, double Phi_rcp, double Phi_co);

/// Lithostatic column of mass `mass` per area (m) at temperature T under gravity g (m/s^2):
/// integrates dp/ds = Phi(p) g, dm/ds = Phi(p) from the surface (s = depth, p = p(Phi_co)) with
/// gsl_odeiv2 (RK8(9) Prince-Dormand, relative tolerance 1e-12), finds the depth s* where m = mass
/// and returns Phi at the heights z (z = s* - s above the bottom; 0 above the surface).
std::vector<double> lithostatic_profile(const Material& m, double T, double Phi_rcp, double Phi_co, double g,
                                        double mass, const std::vector<double>& z, double* surface = nullptr);

/// Largest |Phi u| over inside cells (the momentum density, m/s).
double max_momentum(const FlowSolver& s);

/// Sum over inside cells of Phi times cell volume, in long double (a reference for round-off).
long double exact_mass(const FlowSolver& s);

}  // namespace granseg::verify
