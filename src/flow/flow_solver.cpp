// FlowSolver: construction, face topology, primitives and closures, invariants, the step driver.
// Convection is in convection.cpp, the implicit viscosity and temperature steps in implicit.cpp.
#include "flow/flow_solver.hpp"

#include "closures/closures.hpp"
#include "core/error.hpp"
#include "core/format.hpp"

#include <chrono>
#include <cmath>
#include <stdexcept>
#include <string>

namespace granseg {

namespace {
// Below this many cells the work of a loop is smaller than the cost of waking a second thread
// (several microseconds per parallel loop, much more on a loaded machine): loops run serially.
constexpr std::size_t kParallelCells = 2048;

double seconds_since(std::chrono::steady_clock::time_point t0) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}
}  // namespace

FlowSolver::FlowSolver(Grid grid, Material material, FlowSettings settings, Frame frame)
    : grid_(std::move(grid)), material_(std::move(material)), settings_(settings), frame_(frame) {
    const std::size_t cells = grid_.cells();
    if (!grid_.inside.empty() && grid_.inside.size() != cells)
        throw std::invalid_argument("FlowSolver: grid.inside has the wrong size");
    for (int a = 0; a < 3; ++a) active_[a] = grid_.n[a] > 1;
    if (frame_.omega != 0.0 && (grid_.periodic[0] || grid_.periodic[2]))
        throw std::invalid_argument("FlowSolver: a rotating frame needs walls (not periodic ends) along x and z");
    if (!(settings_.T_floor > 0.0) || !(settings_.Phi_vacuum > 0.0) || !(settings_.cfl > 0.0))
        throw std::invalid_argument("FlowSolver: T_floor, Phi_vacuum and cfl must be > 0");

    rows_ = static_cast<std::size_t>(grid_.n[1]) * grid_.n[2];
    parallel_ = cells >= kParallelCells;
    lines_.set_parallel(parallel_);
    row_lo_.assign(rows_, 0);
    row_hi_.assign(rows_, 0);
    inside_.assign(cells, 0);
    for (int a = 0; a < 3; ++a) position_[a].assign(cells, 0.0);
    for (std::size_t r = 0; r < rows_; ++r) {
        const int j = static_cast<int>(r % grid_.n[1]), k = static_cast<int>(r / grid_.n[1]);
        int lo = grid_.n[0], hi = 0;
        for (int i = 0; i < grid_.n[0]; ++i) {
            const std::size_t c = grid_.index(i, j, k);
            position_[0][c] = grid_.center(0, i);
            position_[1][c] = grid_.center(1, j);
            position_[2][c] = grid_.center(2, k);
            if (!grid_.is_inside(c)) continue;
            inside_[c] = 1;
            inside_cells_.push_back(c);
            lo = std::min(lo, i);
            hi = i + 1;
        }
        row_lo_[r] = std::min(lo, hi);
        row_hi_[r] = hi;
    }
    classify_faces();

    for (auto* f : {&Phi_, &Phi_before_, &E_, &T_, &p_, &c_, &psi_, &eta_, &lambda_, &epsPhi_, &Phi_rcp_, &Phi_co_,
                    &lower_, &diag_, &upper_, &work_})
        f->assign(cells, 0.0);
    for (int b = 0; b < 3; ++b) {
        m_[b].assign(cells, 0.0);
        u_[b].assign(cells, 0.0);
        load_[b].assign(cells, 0.0);
        carry_[b].assign(cells, 0.0);
    }
    for (auto& g : grad_) g.assign(cells, 0.0);
    diag_.assign(cells, 1.0);  // outside cells are identity rows of every line solve
    for (int a = 0; a < 3; ++a) {
        const std::size_t faces = grid_.faces(a);
        for (auto* f : {&mass_flux_[a], &energy_flux_[a], &mom_below_[a], &p_face_[a], &psi_face_[a], &speed_[a]})
            f->assign(faces, 0.0);
        for (int b = 0; b < 3; ++b) mom_[a][b].assign(faces, 0.0);
    }
    for (std::size_t c : inside_cells_) T_[c] = settings_.T_floor;
}

FlowSolver::AxisRow FlowSolver::axis_row(int a, std::size_t r) const {
    const std::size_t nx = grid_.n[0], ny = grid_.n[1];
    const std::size_t j = r % ny, k = r / ny;
    const long n = grid_.n[a], stride = static_cast<long>(grid_.stride(a));
    const bool periodic = grid_.periodic[a];
    const long wrap_lo = periodic ? (n - 1) * stride : 0, wrap_hi = periodic ? -(n - 1) * stride : 0;
    AxisRow row{};
    row.face0 = a == 0 ? (nx + 1) * r : a == 1 ? nx * (j + (ny + 1) * k) : nx * r;
    row.face_step = grid_.face_stride(a);
    if (a == 0) {  // the layer is i itself: only the row's first and last cells meet the boundary
        row.lo = -1, row.hi = 1, row.first_lo = wrap_lo, row.last_hi = wrap_hi;
        row.last = static_cast<int>(n) - 1;
    } else {
        const long layer = a == 1 ? static_cast<long>(j) : static_cast<long>(k);
        row.lo = row.first_lo = layer > 0 ? -stride : wrap_lo;
        row.hi = row.last_hi = layer < n - 1 ? stride : wrap_hi;
        row.last = -1;
    }
    return row;
}

void FlowSolver::classify_faces() {
    for (int a = 0; a < 3; ++a) {
        face_kind_[a].assign(grid_.faces(a), kNoFace);
        if (!active_[a]) continue;
        std::array<int, 3> m = grid_.n;
        m[a] += 1;
        for (int k = 0; k < m[2]; ++k)
            for (int j = 0; j < m[1]; ++j)
                for (int i = 0; i < m[0]; ++i) {
                    std::array<int, 3> lo{i, j, k}, hi{i, j, k};
                    const int layer = hi[a];
                    lo[a] = layer - 1;
                    bool has_lo = layer >= 1, has_hi = layer < grid_.n[a];
                    if (grid_.periodic[a]) {
                        if (!has_lo) lo[a] = grid_.n[a] - 1, has_lo = true;
                        if (!has_hi) hi[a] = 0, has_hi = true;
                    }
                    const bool in_lo = has_lo && grid_.is_inside(grid_.index(lo[0], lo[1], lo[2]));
                    const bool in_hi = has_hi && grid_.is_inside(grid_.index(hi[0], hi[1], hi[2]));
                    face_kind_[a][grid_.face_index(a, i, j, k)] =
                        in_lo && in_hi ? kInterior : in_hi ? kWallBelow : in_lo ? kWallAbove : kNoFace;
                }
    }
}

void FlowSolver::set_state(const std::vector<double>& Phi, const std::array<std::vector<double>, 3>& u,
                           const std::vector<double>& T) {
    const std::size_t cells = grid_.cells();
    if (Phi.size() != cells || T.size() != cells || u[0].size() != cells || u[1].size() != cells || u[2].size() != cells)
        throw std::invalid_argument("FlowSolver::set_state: fields must have one value per grid cell");
    for (std::size_t c : inside_cells_) {
        if (!(Phi[c] >= 0.0) || !(T[c] >= 0.0) || !std::isfinite(Phi[c]) || !std::isfinite(T[c]))
            throw InvariantError("flow initial state: Phi = " + format_number(Phi[c]) + ", T = " + format_number(T[c]) +
                                 " at cell " + std::to_string(c) + " (need finite Phi >= 0, T >= 0)");
        const bool empty = Phi[c] <= settings_.Phi_vacuum;
        Phi_[c] = Phi[c];
        for (int b = 0; b < 3; ++b) m_[b][c] = empty ? 0.0 : Phi[c] * u[b][c];
        E_[c] = Phi[c] * (empty ? settings_.T_floor : std::max(T[c], settings_.T_floor));
    }
    Phi_before_ = Phi_;
    compute_primitives();
    gradient_valid_ = false;
}

void FlowSolver::set_phi_hat(std::vector<double> phi_hat) {
    if (!phi_hat.empty() && phi_hat.size() != grid_.cells())
        throw std::invalid_argument("FlowSolver::set_phi_hat: need one value per grid cell");
    for (std::size_t c : inside_cells_)
        if (!phi_hat.empty() && !(phi_hat[c] >= 0.0 && phi_hat[c] <= 1.0))
            throw InvariantError("flow: phi_hat = " + format_number(phi_hat[c]) + " outside [0, 1] at cell " +
                                 std::to_string(c));
    phi_hat_ = std::move(phi_hat);
}

std::array<double, 2> FlowSolver::packing(std::size_t cell) const {
    const double x = phi_hat_.empty() ? settings_.phi_hat : phi_hat_[cell];
    return {material_.packing.Phi_rcp(x), material_.packing.Phi_co(x)};
}

void FlowSolver::compute_primitives() {
    const double Phi_vac = settings_.Phi_vacuum, T_floor = settings_.T_floor;
    const double rcp0 = material_.packing.Phi_rcp(settings_.phi_hat), co0 = material_.packing.Phi_co(settings_.phi_hat);
    const Vec3 g = frame_.gravity_at(t_);
    // Potential psi = -g . x over the bounded active axes, minus the centrifugal potential.
    std::array<double, 3> g_pot{};
    for (int a = 0; a < 3; ++a) g_pot[a] = active_[a] && !grid_.periodic[a] ? g[a] : 0.0;
    const double w2 = frame_.omega * frame_.omega, x_c = frame_.x_c, z_c = frame_.z_c;
    const std::size_t cells = grid_.cells(), nx = grid_.n[0];
    const double *X = position_[0].data(), *Y = position_[1].data(), *Z = position_[2].data();
    double* psi = psi_.data();
#pragma omp parallel for simd schedule(static) if (parallel_)
    for (std::size_t c = 0; c < cells; ++c) {
        const double rx = X[c] - x_c, rz = Z[c] - z_c;
        psi[c] = -(g_pot[0] * X[c] + g_pot[1] * Y[c] + g_pot[2] * Z[c]) - 0.5 * w2 * (rx * rx + rz * rz);
    }
    const Material& mat = material_;
    const double *Phi = Phi_.data(), *E = E_.data(), *mx = m_[0].data(), *my = m_[1].data(), *mz = m_[2].data();
    const unsigned char* in = inside_.data();
    double *ux = u_[0].data(), *uy = u_[1].data(), *uz = u_[2].data(), *T = T_.data(), *p = p_.data(), *cs = c_.data();
    double *eta = eta_.data(), *lambda = lambda_.data(), *epsPhi = epsPhi_.data(), *rcp = Phi_rcp_.data(), *co = Phi_co_.data();
    const bool per_cell = !phi_hat_.empty();
    long packed = 0;
#pragma omp parallel for reduction(+ : packed) schedule(static) if (parallel_)
    for (std::size_t r = 0; r < rows_; ++r) {
        const std::size_t base = nx * r;
        if (per_cell)
            for (int i = row_lo_[r]; i < row_hi_[r]; ++i) {
                const std::array<double, 2> lim = packing(base + i);
                rcp[base + i] = lim[0], co[base + i] = lim[1];
            }
#pragma omp simd reduction(+ : packed)
        for (int i = row_lo_[r]; i < row_hi_[r]; ++i) {
            const std::size_t c = base + i;
            if (!in[c]) continue;
            const bool empty = Phi[c] <= Phi_vac;
            const double inv = empty ? 0.0 : 1.0 / Phi[c];
            ux[c] = mx[c] * inv, uy[c] = my[c] * inv, uz[c] = mz[c] * inv;
            T[c] = empty ? T_floor : E[c] * inv;
            const double Phi_rcp = per_cell ? rcp[c] : rcp0, Phi_co = per_cell ? co[c] : co0;
            packed += Phi[c] < Phi_rcp ? 0 : 1;
            const ClosureValues v = evaluate_closures_at(mat, Phi[c], T[c], Phi_rcp, Phi_co);
            p[c] = v.p;
            cs[c] = std::sqrt(v.c2);
            eta[c] = empty ? 0.0 : v.eta;
            lambda[c] = empty ? 0.0 : v.lambda;
            epsPhi[c] = empty ? 0.0 : v.eps * Phi[c];
            rcp[c] = Phi_rcp, co[c] = Phi_co;
        }
    }
    if (packed > 0)
        for (std::size_t c : inside_cells_)
            if (!(Phi_[c] < Phi_rcp_[c]))
                throw InvariantError("flow: Phi = " + format_number(Phi_[c], 8) + " reached Phi_rcp = " +
                                     format_number(Phi_rcp_[c], 8) + " at x = " + format_number(position_[0][c]) +
                                     ", z = " + format_number(position_[2][c]) + ", t = " + format_number(t_) +
                                     " s: the packing limit is a wall of the model (eq. 18); the flow compacted the "
                                     "bed faster than the pressure could resist at this resolution and cfl");
}

double FlowSolver::step(double t_end) {
    using clock = std::chrono::steady_clock;
    Phi_before_ = Phi_;
    auto t0 = clock::now();
    compute_primitives();
    timers_.closures += seconds_since(t0);

    t0 = clock::now();
    for (int a = 0; a < 3; ++a)
        if (active_[a]) face_potentials(a), face_fluxes(a);
    const double dt = effective_pressure_and_step(t_end);
    explicit_update(dt);
    timers_.convection += seconds_since(t0);

    t0 = clock::now();
    implicit_viscosity(dt);
    timers_.viscosity += seconds_since(t0);
    t0 = clock::now();
    implicit_temperature(dt);
    timers_.temperature += seconds_since(t0);

    t_ += dt;
    dt_ = dt;
    ++steps_;
    check_invariants();
    return dt;
}

double FlowSolver::mass() const {
    double sum = 0.0;
    for (std::size_t c : inside_cells_) sum += Phi_[c];
    return sum * grid_.cell_volume();
}

void FlowSolver::check_invariants() const {
    auto ok = [&](std::size_t c) {
        return Phi_[c] >= 0.0 && std::isfinite(Phi_[c]) && T_[c] >= 0.0 && std::isfinite(T_[c]) &&
               std::isfinite(u_[0][c]) && std::isfinite(u_[1][c]) && std::isfinite(u_[2][c]);
    };
    long bad = 0;
    const std::size_t n = inside_cells_.size();
#pragma omp parallel for reduction(+ : bad) schedule(static) if (parallel_)
    for (std::size_t q = 0; q < n; ++q) bad += ok(inside_cells_[q]) ? 0 : 1;
    if (bad == 0) return;
    for (std::size_t c : inside_cells_)
        if (!ok(c))
            throw InvariantError("flow: invalid state at x = " + format_number(position_[0][c]) + ", z = " +
                                 format_number(position_[2][c]) + ", t = " + format_number(t_) + " s: Phi = " +
                                 format_number(Phi_[c]) + ", T = " + format_number(T_[c]) + ", u = (" +
                                 format_number(u_[0][c]) + ", " + format_number(u_[1][c]) + ", " +
                                 format_number(u_[2][c]) + ") (" + std::to_string(bad) + " cells)");
}

}  // namespace granseg
