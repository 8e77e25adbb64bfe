// Numerical parameters of the flow solver, the optional source terms, and the wall velocities
// (docs/flow_solver.md Sect. 4; every default is justified in docs/assumptions.md F1-F8).
//
//   solves      nothing: the numerical parameters and their defaults
//   inputs      a scene's [flow] section (src/scenes) or a program
//   outputs     FlowSettings, FlowSource, WallVelocities, the viscosity solve of each mode
//   invariants  T_floor, Phi_vacuum and cfl > 0 (checked by FlowSolver)
#pragma once

#include "core/choice.hpp"
#include "flow/fields/frame.hpp"
#include "transport/limiter.hpp"

#include <array>
#include <functional>
#include <optional>

namespace granseg {

/// How a step treats the acoustic waves (docs/flow_solver.md Sect. 1).
enum class TimeStepping { explicit_waves, semi_implicit };
inline constexpr Choice<TimeStepping> kTimeSteppings[] = {
    {TimeStepping::explicit_waves, "explicit", "HLLC fluxes, dt bounded by the sound speed (cfl on |u_n| + c)"},
    {TimeStepping::semi_implicit, "semi-implicit",
     "pressure implicit (one Newton-Krylov solve per step), dt bounded by the material speed (cfl on |u_n|)"},
};

/// How the implicit viscosity treats the axes (docs/flow_solver_choices.md, "Why these choices").
enum class ViscositySolve { split, coupled };
inline constexpr Choice<ViscositySolve> kViscositySolves[] = {
    {ViscositySolve::coupled, "coupled", "all axes in one sparse Cholesky solve per step (default with semi-implicit)"},
    {ViscositySolve::split, "split",
     "one axis after the other, tridiagonal line solves; creep too slow when dt eta/(Phi h^2) >> 1 (default with explicit)"},
};

/// Which sparse LDL^T factorises the coupled viscosity's matrix (docs/flow_solver_choices.md,
/// "Why these choices"): the same solution up to round-off, at different cost.
enum class Factorisation { supernodal, simplicial };
inline constexpr Choice<Factorisation> kFactorisations[] = {
    {Factorisation::supernodal, "supernodal", "the project's supernodal LDL^T, two subtrees on two threads (default)"},
    {Factorisation::simplicial, "simplicial", "Eigen's SimplicialLDLT, row by row on one thread"},
};

/// How the semi-implicit step carries the mass balance: which Phi a face's mass flux M = Phi_d U takes
/// (docs/flow_solver.md, transport; docs/flow_solver_choices.md, "The transport"). The coupled drum carries phi
/// with the same scheme (coupled/coupled_tumbler.hpp).
enum class Transport { donor_cell, muscl };
inline constexpr Choice<Transport> kTransports[] = {
    {Transport::donor_cell, "donor-cell",
     "first-order upwind: a face carries the Phi of the cell the flow leaves (the paper's order)"},
    {Transport::muscl, "muscl",
     "limited linear reconstruction with a half-step predictor (MUSCL-Hancock): second order, bounded"},
};

/// The time of the face velocities' pressure smoothing (Rhie-Chow, docs/assumptions_flow.md F13):
/// the cell's acoustic time (the default: the same at every dt, so dt -> 0 converges to one scheme)
/// or the step (Rhie and Chow's coefficient: strong at every dt, but it vanishes with dt).
enum class FaceSmoothing { step, acoustic };
inline constexpr Choice<FaceSmoothing> kFaceSmoothings[] = {
    {FaceSmoothing::step, "step", "tau_s = dt: damps a pressure checkerboard within a step at any dt; the scheme depends on dt"},
    {FaceSmoothing::acoustic, "acoustic",
     "tau_s = h/c (fading with c where the material is soft): converges in dt, damps a checkerboard by about 1 - tau_s/dt "
     "per step at dt >> h/c"},
};

/// Numerical parameters of the flow solver; each default is justified in docs/assumptions.md (F*).
struct FlowSettings {
    TimeStepping time_stepping = TimeStepping::semi_implicit;  // the default (docs/flow_solver.md Sect. 1)
    std::optional<ViscositySolve> viscosity;                   // unset: coupled with semi-implicit, split with explicit
    Factorisation factorisation = Factorisation::supernodal;   // of the coupled viscosity
    double cfl = 0.9;                  // dt * sum_axis (|u_axis| + c)/h_axis <= cfl (explicit), |u_axis| only (semi-implicit)
    double T_floor = 1e-12;            // m^2/s^2, lower bound of T (finite eta, lambda ~ T^(-1/2))
    double Phi_vacuum = 1e-12;         // cells with Phi <= this are empty: u = 0, T = T_floor
    double dt_min = 1e-9;              // s; a smaller step stops the run with InvariantError
    double dt_max = 2e-3;              // s (the drum's angle against dt_max: docs/flow_solver.md)
    double pressure_tolerance = 1e-2;  // semi-implicit: Newton stops at this share of the step's largest explicit mass change
    FaceSmoothing face_smoothing = FaceSmoothing::acoustic;  // semi-implicit: the face smoothing's time (F13)
    double smoothing_time_max = 2e-3;    // s; face_smoothing = acoustic: tau_s = h/c at most this (soft material)
    double acoustic_courant_max = 5.0;   // face_smoothing = acoustic: dt * max_axis c/h_axis <= this (F13)
    double phi_hat = 0.5;                // small-particle share used for Phi_rcp, Phi_co when no phi field is set
    std::optional<Transport> transport;  // unset: muscl with semi-implicit; the explicit step's HLLC fluxes are donor cell
    Limiter limiter = Limiter::mc;       // of the reconstruction with transport = muscl
};

/// The viscosity solve `s` asks for, or the default of its time stepping (the semi-implicit
/// step's dt makes the splitting error of the line solves too large; docs/assumptions.md F10).
inline ViscositySolve viscosity_solve(const FlowSettings& s) {
    return s.viscosity                                      ? *s.viscosity
           : s.time_stepping == TimeStepping::semi_implicit ? ViscositySolve::coupled
                                                            : ViscositySolve::split;
}

/// The transport `s` asks for, or the default of its time stepping: muscl for the semi-implicit
/// step, donor-cell for the explicit one (its HLLC fluxes carry the upwind values; muscl needs
/// the semi-implicit step, FlowSolver and the scene reader refuse it there).
inline Transport transport_scheme(const FlowSettings& s) {
    return s.transport ? *s.transport : s.time_stepping == TimeStepping::semi_implicit ? Transport::muscl : Transport::donor_cell;
}

/// Sources added to the conserved variables (manufactured solutions): called per inside cell with
/// time and cell centre, fills rates for (Phi, Phi u_x, Phi u_y, Phi u_z, Phi T).
using FlowSource = std::function<void(double t, double x, double y, double z, double rates[5])>;

/// Velocity of the domain-boundary walls: [axis][side] (side 0 lower, 1 upper), tangential.
using WallVelocities = std::array<std::array<Vec3, 2>, 3>;

}  // namespace granseg
