// The fields of the flow solver (Sect. 2.1, eqs. 8, 9, 14 per intrinsic density rho*), one value
// per grid cell in the order of core/grid.hpp, and per face of each axis:
//   FlowState     the conserved variables Phi, Phi u, Phi T and the primitives u, T kept with them;
//   CellClosures  what the closures (eqs. 15-20) give per cell at the start of a step;
//   Potential     the potential psi of gravity and the centrifugal force per cell and face;
//   AxisLoads     per axis and cell: the weight a cell passes on or cannot carry (free surface);
//   AxisFaces     per axis and face: the convective fluxes and what the time step needs.
//
//   solves      nothing: the fields the kernels share
//   inputs      sized and owned by FlowSolver
//   outputs     read and written by the kernels as the table in flow/flow_solver.hpp says
//   invariants  one value per cell (core/grid.hpp order) or per face of an axis; after the
//               primitives and every update u = Phi u/Phi and T = Phi T/Phi in cells holding
//               material, u = 0 and T = T_floor in empty ones (Phi <= Phi_vacuum)
//
// The kernels (loads, primitives, convection, time_step, viscosity, temperature) read some of
// these as const inputs and write others; the table in flow/flow_solver.hpp lists which.
#pragma once

#include "run/state_io.hpp"

#include <array>
#include <vector>

namespace granseg {

struct FlowState {
    std::vector<double> Phi;               // granular volume fraction
    std::array<std::vector<double>, 3> m;  // Phi u (momentum per rho*)
    std::vector<double> E;                 // Phi T
    std::array<std::vector<double>, 3> u;  // velocity m/Phi (0 in empty cells)
    std::vector<double> T;                 // granular temperature E/Phi (T_floor in empty cells)
    void checkpoint(StateIO& io) { io("Phi", Phi)("m", m)("E", E)("u", u)("T", T); }
};

struct CellClosures {
    std::vector<double> p, c;                 // pressure (eq. 15) and sound speed sqrt(dp/dPhi at fixed T)
    std::vector<double> eta, lambda, epsPhi;  // viscosity, conductivity, eps Phi (eqs. 17, 20)
    std::vector<double> Phi_rcp, Phi_co;      // packing limits at the cell's phi_hat
};

struct Potential {
    std::vector<double> cell;                 // psi = -g . x - omega^2 r^2/2 at the cell centre
    std::array<std::vector<double>, 3> face;  // per axis: the mean of the two cells' psi
};

struct AxisLoads {
    std::vector<double> load;      // weight per area a cell's downhill face carries beyond p + Phi |d_psi|
    std::vector<double> carry;     // pressure an unsupported cell passes on at its uphill face
    std::vector<double> downhill;  // pressure at the downhill face, what rests on the next cell of the sweep
};

struct AxisFaces {
    std::vector<double> mass, energy;        // Phi u_n (the hand-over M), Phi T u_n
    std::array<std::vector<double>, 3> mom;  // momentum flux per component; mom[axis] as seen by the cell above
    std::vector<double> mom_below;           // normal momentum flux as seen by the cell below
    std::vector<double> p, speed;            // face pressure p* and fastest wave speed |u_n| + c
    void checkpoint(StateIO& io) {
        io("mass", mass)("energy", energy)("mom", mom)("mom_below", mom_below)("p", p)("speed", speed);
    }
};

using FlowFaces = std::array<AxisFaces, 3>;

}  // namespace granseg
