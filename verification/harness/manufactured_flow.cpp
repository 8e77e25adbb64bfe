#include "harness/manufactured_flow.hpp"

#include "closures/closures.hpp"
#include "core/error.hpp"
#include "flow/flow_solver.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <functional>
#include <vector>

namespace granseg::verify {

namespace {

constexpr double L = kManufacturedSide, kTEnd = kManufacturedEnd, kTau = 0.2;
constexpr double kPhi0 = 0.63, kdPhi = 0.008, kU = 0.05, kT0 = 1e-3, kdT = 0.3;
constexpr double kDelta = 1e-4;  // m, finite-difference step for the source terms
// A fast frame rotation, so that the Coriolis (2 Omega U = 2 m/s^2) and centrifugal (Omega^2 L/2
// = 10 m/s^2) accelerations are as large as gravity and an error in either shows; gravity turns
// by Omega t_end = 1 rad during the run.
constexpr double kOmega = 20.0;
constexpr int kTimeNodes = 33;  // plus one node before 0 and one after t_end

struct State {
    double Phi, ux, uz, T;
};

double amplitude(double t) { return 1.0 + 0.5 * std::sin(2.0 * M_PI * t / kTau); }

/// sin A, cos A and sin 2A, remembered for recent arguments A: the sources' nested differences
/// ask exact() at some nine abscissae per cell hundreds of times each (most of the program's
/// time went to sin and cos). The same values as computed afresh: a hit needs A's very bits.
/// Returned by value: the next call may overwrite the slot.
struct Waves {
    double sin, cos, sin2;
};
Waves waves(double A) {
    struct Slot {
        bool filled = false;
        std::uint64_t bits = 0;
        Waves w{};
    };
    thread_local std::array<Slot, 512> seen;
    std::uint64_t bits;
    std::memcpy(&bits, &A, sizeof bits);
    Slot& s = seen[(bits ^ (bits >> 32)) % seen.size()];
    if (!s.filled || s.bits != bits) s = {true, bits, {std::sin(A), std::cos(A), std::sin(2 * A)}};
    return s.w;
}

State exact(double x, double z, double t) {
    const Waves X = waves(M_PI * x / L), Z = waves(M_PI * z / L);
    const double a = amplitude(t);
    return {kPhi0 + kdPhi * X.cos * Z.cos * a, kU * X.sin * Z.sin2 * a, -kU * X.sin2 * Z.sin * a,
            kT0 * (1.0 + kdT * X.cos * Z.cos * a)};
}

/// Fourth-order central difference of f along x (axis 0), z (axis 2) or t (axis 1), step d.
double derivative(const std::function<double(double, double, double)>& f, int axis, double x, double z, double t, double d) {
    auto at = [&](double s) { return f(x + (axis == 0 ? s : 0), z + (axis == 2 ? s : 0), t + (axis == 1 ? s : 0)); };
    return (at(-2 * d) - 8 * at(-d) + 8 * at(d) - at(2 * d)) / (12 * d);
}

/// The source rates (Phi, Phi u_x, Phi u_y, Phi u_z, Phi T) of the manufactured solution at (x, z, t).
std::array<double, 5> source(const Material& m, const Frame& frame, double rcp, double co, double x, double z, double t) {
    auto closures = [&](double xx, double zz, double tt) {
        const State s = exact(xx, zz, tt);
        return evaluate_closures_at(m, s.Phi, s.T, rcp, co);
    };
    using F = std::function<double(double, double, double)>;
    const F Phi = [](double a, double b, double c) { return exact(a, b, c).Phi; };
    const F mx = [](double a, double b, double c) {
        const State s = exact(a, b, c);
        return s.Phi * s.ux;
    };
    const F mz = [](double a, double b, double c) {
        const State s = exact(a, b, c);
        return s.Phi * s.uz;
    };
    const F E = [](double a, double b, double c) {
        const State s = exact(a, b, c);
        return s.Phi * s.T;
    };
    const F ux = [](double a, double b, double c) { return exact(a, b, c).ux; };
    const F uz = [](double a, double b, double c) { return exact(a, b, c).uz; };
    const F T = [](double a, double b, double c) { return exact(a, b, c).T; };
    const double d = kDelta, dt = 1e-4 * kTau;
    auto D = [&](const F& f, int axis) { return derivative(f, axis, x, z, t, axis == 1 ? dt : d); };
    // Diffusion d/dx_a (k d f/dx_a) with k from the closures (eta or lambda).
    auto diffusion = [&](const F& f, int axis, bool lambda) {
        const F flux = [&](double a, double b, double c) {
            const ClosureValues v = closures(a, b, c);
            return (lambda ? v.lambda : v.eta) * derivative(f, axis, a, b, c, d);
        };
        return D(flux, axis);
    };
    const State s = exact(x, z, t);
    const ClosureValues v = closures(x, z, t);
    const F p = [&](double a, double b, double c) { return closures(a, b, c).p; };
    const F mxx = [](double a, double b, double c) {
        const State q = exact(a, b, c);
        return q.Phi * q.ux * q.ux;
    };
    const F mxz = [](double a, double b, double c) {
        const State q = exact(a, b, c);
        return q.Phi * q.ux * q.uz;
    };
    const F mzz = [](double a, double b, double c) {
        const State q = exact(a, b, c);
        return q.Phi * q.uz * q.uz;
    };
    const F Ex = [](double a, double b, double c) {
        const State q = exact(a, b, c);
        return q.Phi * q.T * q.ux;
    };
    const F Ez = [](double a, double b, double c) {
        const State q = exact(a, b, c);
        return q.Phi * q.T * q.uz;
    };
    // Gravity in the frame turning counter-clockwise at Omega: the lab's (0, -|g|) turned by -Omega t
    // (written here, not taken from Frame, so that an error there shows).
    const double w = frame.omega, rx = x - frame.x_c, rz = z - frame.z_c;
    const double g[3] = {-frame.gravity * std::sin(w * t), 0.0, -frame.gravity * std::cos(w * t)};
    const double grad2 = D(ux, 0) * D(ux, 0) + D(ux, 2) * D(ux, 2) + D(uz, 0) * D(uz, 0) + D(uz, 2) * D(uz, 2);
    std::array<double, 5> S{};
    S[0] = D(Phi, 1) + D(mx, 0) + D(mz, 2);  // eq. (8)
    S[1] = D(mx, 1) + D(mxx, 0) + D(mxz, 2) + D(p, 0) - diffusion(ux, 0, false) - diffusion(ux, 2, false) -
           s.Phi * (g[0] + w * w * rx + 2 * w * s.uz);  // eq. (9), rotating frame
    S[3] = D(mz, 1) + D(mxz, 0) + D(mzz, 2) + D(p, 2) - diffusion(uz, 0, false) - diffusion(uz, 2, false) -
           s.Phi * (g[2] + w * w * rz - 2 * w * s.ux);
    S[4] = D(E, 1) + D(Ex, 0) + D(Ez, 2) - 1.5 * v.eta * grad2 - 1.5 * (diffusion(T, 0, true) + diffusion(T, 2, true)) +
           v.dissipation;  // eq. (14)
    return S;
}

/// The square's frame: turning at kOmega about its centre, gravity 9.81 m/s^2.
Frame frame() {
    Frame f;
    f.omega = kOmega;
    f.x_c = f.z_c = 0.5 * L;
    return f;
}

}  // namespace

ManufacturedFlow::ManufacturedFlow(const Material& m, int n)
    : m_(m), n_(n), grid_(Grid::plane_xz(n, n, 0.0, 0.0, L, L)), nodes_(grid_.cells() * (kTimeNodes + 2)) {
    const FlowSettings s;
    const double rcp = m.packing.Phi_rcp(s.phi_hat), co = m.packing.Phi_co(s.phi_hat);
    // Sources at the time nodes t_j = j h_t, j = -1 .. kTimeNodes, for every cell; cubic Hermite
    // interpolation in time with central-difference slopes (Catmull-Rom) in run().
    const double h_t = kTEnd / (kTimeNodes - 1);
    for (int j = -1; j <= kTimeNodes; ++j)
        for (int k = 0; k < n; ++k)
            for (int i = 0; i < n; ++i)
                nodes_[(j + 1) * grid_.cells() + grid_.index(i, 0, k)] =
                    source(m, frame(), rcp, co, grid_.center(0, i), grid_.center(2, k), j * h_t);
}

ManufacturedRun ManufacturedFlow::run(const FlowSettings& s) const {
    if (s.phi_hat != FlowSettings{}.phi_hat)
        throw InvariantError("ManufacturedFlow::run: the sources assume the default phi_hat");
    const Grid& g = grid_;
    const int n = n_;
    const std::size_t cells = g.cells();
    const double h_t = kTEnd / (kTimeNodes - 1);
    auto index_of = [&](double x, double z) { return g.index(static_cast<int>(x / g.h[0]), 0, static_cast<int>(z / g.h[2])); };
    FlowSolver solver(g, m_, s, frame());
    solver.set_source([&](double t, double x, double, double z, double rates[5]) {
        const int j = std::min(kTimeNodes - 2, std::max(0, static_cast<int>(t / h_t)));
        const double r = t / h_t - j, r2 = r * r, r3 = r2 * r;
        const double h00 = 2 * r3 - 3 * r2 + 1, h10 = r3 - 2 * r2 + r, h01 = -2 * r3 + 3 * r2, h11 = r3 - r2;
        const std::size_t c = index_of(x, z);
        const auto& a0 = nodes_[j * cells + c];  // t_(j-1)
        const auto& a = nodes_[(j + 1) * cells + c];
        const auto& b = nodes_[(j + 2) * cells + c];
        const auto& b1 = nodes_[(j + 3) * cells + c];
        for (int q = 0; q < 5; ++q) rates[q] = h00 * a[q] + h10 * 0.5 * (b[q] - a0[q]) + h01 * b[q] + h11 * 0.5 * (b1[q] - a[q]);
    });
    std::vector<double> Phi(cells), T(cells), ux(cells), uy(cells, 0.0), uz(cells);
    for (int k = 0; k < n; ++k)
        for (int i = 0; i < n; ++i) {
            const State e = exact(g.center(0, i), g.center(2, k), 0.0);
            const std::size_t c = g.index(i, 0, k);
            Phi[c] = e.Phi, T[c] = e.T, ux[c] = e.ux, uz[c] = e.uz;
        }
    solver.set_state(Phi, {ux, uy, uz}, T);
    ManufacturedRun r;
    add_timed(r.time, [&] {
        for (; solver.time() < kTEnd; ++r.steps) solver.step(kTEnd);
    });
    r.work = solver.counters();
    if (s.time_stepping == TimeStepping::semi_implicit) {
        for (int a : {0, 2})
            for (double v : solver.smoothing(a)) r.smoothing += std::fabs(v);
        r.smoothing /= 2.0 * n * (n - 1);  // interior faces (walls carry none)
    }
    for (int k = 0; k < n; ++k)
        for (int i = 0; i < n; ++i) {
            const State e = exact(g.center(0, i), g.center(2, k), kTEnd);
            const std::size_t c = g.index(i, 0, k);
            r.error_Phi += std::fabs(solver.Phi()[c] - e.Phi);
            r.error_u += std::hypot(solver.u(0)[c] - e.ux, solver.u(2)[c] - e.uz);
            r.error_T += std::fabs(solver.T()[c] - e.T);
        }
    const double cells_n = static_cast<double>(n) * n;
    r.error_Phi /= cells_n, r.error_u /= cells_n, r.error_T /= cells_n;
    r.Phi = solver.Phi(), r.u_x = solver.u(0), r.u_z = solver.u(2), r.T = solver.T();
    return r;
}

}  // namespace granseg::verify
