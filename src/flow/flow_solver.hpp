// The compressible granular flow solver (Sect. 2.1, eqs. 8, 9, 14 with the asymmetric stress of
// eqs. 10-11 and the closures of eqs. 15-20). Walk-through: docs/flow_solver.md.
//
// Unknowns per cell (core/grid.hpp layout): Phi, Phi u (3 components), Phi T. One step (Lie
// splitting, first order in time and space):
//   1. primitives and closures at t^n; explicit convection with the HLLC flux and hydrostatic
//      reconstruction (flow/hllc.hpp); transport coefficients at the effective pressure; dt from a
//      CFL condition on |u_n| + c, from the cells' outflow (so Phi stays > 0 and T, u_t stay
//      convex combinations) and from their compaction (so Phi stays < Phi_rcp);
//   2. Coriolis rotation of u over dt (exact), body-force components along inactive or periodic
//      axes as explicit sources, optional manufactured source terms;
//   3. implicit viscosity d(Phi u)/dt = div(eta grad u), split by axis into line solves;
//   4. temperature: heating (3/2) eta kappa:kappa against dissipation eps Phi T, linearly implicit
//      (T relaxes towards (3/2)(eta0/eps0) kappa:kappa, eq. 45), then implicit conduction
//      (3/2) div(lambda grad T) by line solves; T >= T_floor.
// Walls: no-slip (moving domain-boundary walls allowed), adiabatic, no mass flux. An axis with
// one cell is inactive (the field does not vary along it). Embedded walls: grid.inside.
//
// Coupling hand-over (per step): Phi before and after, T, u, the cell velocity gradient, and
// per axis the face mass flux M (Phi u_n) such that in every inside cell
//   Phi_new = Phi_old - dt * sum_axis (M[upper face] - M[lower face]) / h_axis,
// M = 0 on wall faces (one stage per step, so M is also its time average over the step).
#pragma once

#include "closures/material.hpp"
#include "core/grid.hpp"
#include "flow/frame.hpp"
#include "flow/line_solver.hpp"

#include <array>
#include <functional>
#include <limits>
#include <vector>

namespace granseg {

/// Numerical parameters of the flow solver; each default is justified in docs/assumptions.md (F*).
struct FlowSettings {
    double cfl = 0.9;           // dt * sum_axis (|u_axis| + c)/h_axis <= cfl (first-order unsplit stability)
    double T_floor = 1e-12;     // m^2/s^2, lower bound of T (finite eta, lambda ~ T^(-1/2))
    double Phi_vacuum = 1e-12;  // cells with Phi <= this are empty: u = 0, T = T_floor
    double dt_min = 1e-9;       // s; a smaller step stops the run with InvariantError
    double dt_max = 1e-3;       // s
    double phi_hat = 0.5;       // small-particle share used for Phi_rcp, Phi_co when no phi field is set
};

/// Sources added to the conserved variables (manufactured solutions): called per inside cell with
/// time and cell centre, fills rates for (Phi, Phi u_x, Phi u_y, Phi u_z, Phi T).
using FlowSource = std::function<void(double t, double x, double y, double z, double rates[5])>;

/// Wall-clock seconds spent in the phases of step() (for benchmarks).
struct FlowTimers {
    double closures = 0, convection = 0, viscosity = 0, temperature = 0;
};

class FlowSolver {
public:
    FlowSolver(Grid grid, Material material, FlowSettings settings, Frame frame);

    /// Sets the state (Phi >= 0, T >= 0, finite; outside cells are ignored). Throws InvariantError
    /// if a cell has Phi >= Phi_rcp.
    void set_state(const std::vector<double>& Phi, const std::array<std::vector<double>, 3>& u,
                   const std::vector<double>& T);
    /// Small-particle share phi_hat = phi/Phi per cell (same layout, values in [0, 1], copied):
    /// Phi_rcp and Phi_co then follow it cell by cell from the next step on. An empty vector
    /// returns to the uniform settings.phi_hat.
    void set_phi_hat(std::vector<double> phi_hat);
    /// Tangential velocity of the domain-boundary wall on `side` (0 lower, 1 upper) of `axis`.
    void set_wall_velocity(int axis, int side, const Vec3& U) { wall_velocity_[axis][side] = U; }
    void set_source(FlowSource source) { source_ = std::move(source); }

    /// Advances one step, not beyond t_end; returns dt. InvariantError on a broken invariant
    /// (non-finite field, Phi reaching Phi_rcp, dt below dt_min).
    double step(double t_end = std::numeric_limits<double>::infinity());

    const Grid& grid() const { return grid_; }
    const Material& material() const { return material_; }
    const FlowSettings& settings() const { return settings_; }
    const Frame& frame() const { return frame_; }
    double time() const { return t_; }
    long steps() const { return steps_; }
    double last_dt() const { return dt_; }

    // Coupling hand-over, valid after a step (see the header comment).
    const std::vector<double>& Phi() const { return Phi_; }
    const std::vector<double>& Phi_before() const { return Phi_before_; }
    const std::vector<double>& T() const { return T_; }
    const std::vector<double>& u(int b) const { return u_[b]; }
    /// d u_b / d x_a per cell (central differences; wall ghosts carry the wall velocity),
    /// computed when first asked for after a step.
    const std::vector<double>& velocity_gradient(int b, int a) const {
        if (!gradient_valid_) update_velocity_gradient();
        return grad_[3 * b + a];
    }
    const std::vector<double>& mass_flux(int axis) const { return mass_flux_[axis]; }
    bool active(int axis) const { return active_[axis]; }

    /// Total granular volume, sum of Phi times cell volume over inside cells.
    double mass() const;
    /// Phi_rcp and Phi_co of a cell (from the phi_hat field, or settings.phi_hat).
    std::array<double, 2> packing(std::size_t cell) const;
    const FlowTimers& timers() const { return timers_; }

private:
    // Face kinds: wall below/above means the face is a wall and the inside cell is above/below it.
    enum FaceKind : unsigned char { kNoFace = 0, kInterior, kWallBelow, kWallAbove };
    /// Where the cells of row r = j + ny k meet their neighbours along `axis`: cell i of the row
    /// has its lower face at face0 + i and its upper face face_step further; its neighbour cells
    /// are c + lo_at(i) and c + hi_at(i) (0 on a wall of the domain boundary, the partner cell on
    /// a periodic boundary).
    struct AxisRow {
        std::size_t face0, face_step;
        long lo, hi, first_lo, last_hi;
        int last;
        long lo_at(int i) const { return i == 0 ? first_lo : lo; }
        long hi_at(int i) const { return i == last ? last_hi : hi; }
    };
    AxisRow axis_row(int axis, std::size_t row) const;
    /// Calls body(c, i, row) for every cell c = i + nx row of every row's inside range, rows
    /// shared among threads, the cells of a row vectorised (body masks outside cells itself).
    template <class Body>
    void for_row_cells(int axis, Body&& body) const {
        const std::size_t nx = grid_.n[0];
#pragma omp parallel for schedule(static) if (parallel_)
        for (std::size_t r = 0; r < rows_; ++r) {
            const AxisRow row = axis_row(axis, r);
#pragma omp simd
            for (int i = row_lo_[r]; i < row_hi_[r]; ++i) body(nx * r + i, i, row);
        }
    }
    /// Calls body(c, i, rows) for every inside cell, with the AxisRow of each axis in rows[3].
    template <class Body>
    void for_inside_cells(Body&& body) const {
        const std::size_t nx = grid_.n[0];
#pragma omp parallel for schedule(static) if (parallel_)
        for (std::size_t r = 0; r < rows_; ++r) {
            AxisRow rows[3];
            for (int a = 0; a < 3; ++a) rows[a] = axis_row(a, r);
            for (int i = row_lo_[r]; i < row_hi_[r]; ++i)
                if (inside_[nx * r + i]) body(nx * r + i, i, rows);
        }
    }

    void classify_faces();
    void compute_primitives();
    void face_potentials(int axis);
    void flow_loads(int axis, double g_axis, double weight);
    void face_fluxes(int axis);
    double effective_pressure_and_step(double t_end);
    void explicit_update(double dt);
    /// Line coefficients of Phi x - dt d/dx_a(kappa dx/dx_a) with r = dt/h^2 (times 3/2 for T):
    /// harmonic-mean face values, wall faces Dirichlet (no_slip) or zero flux; factorised.
    void diffusion_rows(int axis, double r, const std::vector<double>& kappa, bool no_slip);
    void implicit_viscosity(double dt);
    void implicit_temperature(double dt);
    void update_velocity_gradient() const;
    void check_invariants() const;

    Grid grid_;
    Material material_;
    FlowSettings settings_;
    Frame frame_;
    std::vector<double> phi_hat_;  // per cell, or empty: settings_.phi_hat everywhere
    std::array<std::array<Vec3, 2>, 3> wall_velocity_{};
    FlowSource source_;
    std::array<bool, 3> active_{};
    std::size_t rows_ = 0;                    // ny * nz rows of cells along x
    bool parallel_ = false;                   // threads pay off only on larger grids (kParallelCells)
    std::vector<int> row_lo_, row_hi_;        // inside cells of a row lie in [row_lo_, row_hi_)
    std::vector<std::size_t> inside_cells_;
    std::vector<unsigned char> inside_;       // 1 for inside cells (grid.inside or all)
    std::array<std::vector<unsigned char>, 3> face_kind_;
    std::array<std::vector<double>, 3> position_;  // cell centres

    double t_ = 0.0, dt_ = 0.0;
    long steps_ = 0;
    // Conserved variables and primitives (one value per cell).
    std::vector<double> Phi_, Phi_before_, E_;
    std::array<std::vector<double>, 3> m_, u_;
    std::vector<double> T_, p_, c_, psi_, eta_, lambda_, epsPhi_, Phi_rcp_, Phi_co_;
    mutable std::array<std::vector<double>, 9> grad_;
    mutable bool gradient_valid_ = false;
    // Per axis and face: the face potential, the fluxes (mass is the hand-over M), the pressure p*
    // and the fastest wave speed; mom_[a][a] is the normal momentum flux seen by the cell above
    // the face (with its hydrostatic correction), mom_below_[a] the one seen by the cell below.
    std::array<std::vector<double>, 3> mass_flux_, energy_flux_, mom_below_, p_face_, psi_face_, speed_, load_, carry_;
    std::array<std::array<std::vector<double>, 3>, 3> mom_;
    // Line-solve work space.
    std::vector<double> lower_, diag_, upper_, work_;
    LineSolver lines_;
    FlowTimers timers_;
};

}  // namespace granseg
