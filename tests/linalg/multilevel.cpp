// The multilevel preconditioner of the pressure solve (linalg/multilevel.hpp) on a model of the
// drum's Jacobian J = diag(dPhi/dp) + K: the inside cells of a disc on an n x n grid, faces of
// the bed (the lower 75 % of the disc) with weights K_f = (c dt/h)^2 w_f, w_f in [0.8, 1.2] like
// Phi_donor/Phi_face, and weight 0 on every face that touches the dust above; diagonal 1.
// c dt is a fixed fraction of the diameter, so c dt/h grows like n, as in the drum at a fixed dt.
#include "linalg/multilevel.hpp"

#include <boost/test/unit_test.hpp>

#include <Eigen/IterativeLinearSolvers>
#include <Eigen/SparseCholesky>

#include <cmath>
#include <random>

using namespace granseg;
using Matrix = Multilevel::Matrix;

namespace {

/// c dt as a fraction of the diameter: c dt/h = n/8, the coupling 39, 156, 625 at n = 50, 100, 200.
constexpr double kWaveFraction = 1.0 / 8.0;

struct Disc {
    Matrix A;
    std::vector<std::array<int, 3>> cell;
};

/// The model Jacobian on the disc of diameter n cells (file comment).
Disc disc(int n) {
    std::vector<long> row(static_cast<std::size_t>(n) * n, -1);
    Disc d;
    auto centre = [&](int i) { return (i + 0.5) / n - 0.5; };  // in diameters
    for (int k = 0; k < n; ++k)
        for (int i = 0; i < n; ++i)
            if (centre(i) * centre(i) + centre(k) * centre(k) < 0.25) {
                row[i + n * k] = static_cast<long>(d.cell.size());
                d.cell.push_back({i, 0, k});
            }
    const double coupling = std::pow(kWaveFraction * n, 2);
    auto bed = [&](int k) { return centre(k) < 0.25; };  // fill height 0.75 diameters
    std::vector<Eigen::Triplet<double>> t;
    for (std::size_t r = 0; r < d.cell.size(); ++r) t.emplace_back(r, r, 1.0);
    for (int k = 0; k < n; ++k)
        for (int i = 0; i < n; ++i)
            for (const auto& [di, dk] : {std::pair{1, 0}, std::pair{0, 1}}) {
                if (i + di >= n || k + dk >= n) continue;
                const long a = row[i + n * k], b = row[i + di + n * (k + dk)];
                if (a < 0 || b < 0) continue;
                // A face of weight 0 stays in the pattern, as the pressure solver's faces do.
                const double w = bed(k) && bed(k + dk) ? coupling * (1.0 + 0.2 * std::sin(0.37 * i + 0.91 * k)) : 0.0;
                t.emplace_back(a, a, w), t.emplace_back(b, b, w);
                t.emplace_back(a, b, -w), t.emplace_back(b, a, -w);
            }
    d.A.resize(static_cast<long>(d.cell.size()), static_cast<long>(d.cell.size()));
    d.A.setFromTriplets(t.begin(), t.end());
    d.A.makeCompressed();
    return d;
}

/// A right-hand side like the mass change of the explicit fluxes: smooth plus noise.
Eigen::VectorXd load(const Disc& d, unsigned seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> U(-1.0, 1.0);
    Eigen::VectorXd b(d.A.rows());
    for (long r = 0; r < b.size(); ++r) b[r] = std::cos(0.1 * d.cell[r][0]) + 0.3 * U(rng);
    return b;
}

using MultilevelCG = Eigen::ConjugateGradient<Matrix, Eigen::Lower | Eigen::Upper, Multilevel>;
using JacobiCG = Eigen::ConjugateGradient<Matrix, Eigen::Lower | Eigen::Upper, Eigen::DiagonalPreconditioner<double>>;

/// Conjugate-gradient iterations (Eigen's count plus the first) to the relative residual `tol`.
template <class Solver>
int iterations(Solver& cg, const Disc& d, double tol) {
    cg.setTolerance(tol);
    cg.setMaxIterations(10000);
    cg.compute(d.A);
    const Eigen::VectorXd x = cg.solve(load(d, 1));
    BOOST_REQUIRE(cg.info() == Eigen::Success);
    return static_cast<int>(cg.iterations()) + 1;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(linalg_multilevel_tests)

BOOST_AUTO_TEST_CASE(preconditioned_cg_matches_a_direct_solve) {
    const Disc d = disc(50);
    MultilevelCG cg;
    cg.preconditioner().build(d.A, d.cell, false);
    BOOST_TEST(cg.preconditioner().levels() >= 3);
    const double tol = 1e-10;
    cg.setTolerance(tol);
    cg.compute(d.A);
    const Eigen::VectorXd b = load(d, 2), x = cg.solve(b);
    Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> direct(d.A);
    const Eigen::VectorXd exact = direct.solve(b);
    // CG stops at |A x - b| <= tol |b|; A = I + K with K positive semi-definite has smallest
    // eigenvalue >= 1, so |x - exact| = |A^-1 (A x - b)| <= tol |b|.
    BOOST_TEST((x - exact).norm() <= tol * b.norm());
}

BOOST_AUTO_TEST_CASE(preconditioner_is_symmetric_and_positive) {
    const Disc d = disc(100);
    Multilevel M;
    M.build(d.A, d.cell, false);
    M.factorize(d.A);
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> U(-1.0, 1.0);
    for (int trial = 0; trial < 5; ++trial) {
        Eigen::VectorXd x(d.A.rows()), y(d.A.rows());
        for (long r = 0; r < x.size(); ++r) x[r] = U(rng), y[r] = U(rng);
        const Eigen::VectorXd Mx = M.solve(x), My = M.solve(y);
        // Round-off: the two products sum n terms of size |x| |My| / n, each with relative error
        // ~1e-16 from the cycle's sums over a few neighbours and levels.
        BOOST_TEST(std::fabs(x.dot(My) - y.dot(Mx)) <= 1e-12 * x.norm() * My.norm());
        BOOST_TEST(x.dot(Mx) > 0.0);
    }
}

BOOST_AUTO_TEST_CASE(iterations_do_not_grow_with_the_grid) {
    // Jacobi's iterations grow like c dt/h (like n); the multilevel ones must not. Bound: from
    // n = 50 to 200 at most 1.5 times as many (a cycle independent of h would give 1; the two
    // levels added at the finer grids may each cost a few iterations), while Jacobi's grow at least
    // 3 times (c dt/h grows 4 times).
    int multilevel[3], jacobi[3], q = 0;
    for (int n : {50, 100, 200}) {
        const Disc d = disc(n);
        MultilevelCG ml;
        ml.preconditioner().build(d.A, d.cell, false);
        JacobiCG jc;
        multilevel[q] = iterations(ml, d, 1e-8), jacobi[q] = iterations(jc, d, 1e-8);
        BOOST_TEST_MESSAGE("n = " << n << ": multilevel " << multilevel[q] << ", Jacobi " << jacobi[q] << " iterations");
        ++q;
    }
    BOOST_TEST(multilevel[2] <= 1.5 * multilevel[0]);
    BOOST_TEST(jacobi[2] >= 3.0 * jacobi[0]);
    BOOST_TEST(multilevel[2] < jacobi[2]);
}

BOOST_AUTO_TEST_SUITE_END()
