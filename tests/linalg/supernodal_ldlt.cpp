// The supernodal LDL^T of the coupled viscosity (linalg/supernodal_ldlt.hpp) against Eigen's
// simplicial LDL^T (a different algorithm on the same matrix): viscosity-like matrices
// Phi + dt div(eta grad) on a disc and on a 3-D box, with eta spread over four decades and
// decoupled identity rows (empty cells); factorised again with new values over eight decades (the
// drum's matrix spans about eight) and solved, as every step does; the two lanes on two threads
// or one after the other give the same bits; a matrix that is not positive definite is refused,
// in a wide panel (dense Cholesky) and in a narrow one (column by column); Eigen's products in a
// lane open no threads of their own.
#include "linalg/supernodal_ldlt.hpp"
#include "core/threads.hpp"

#include <boost/test/unit_test.hpp>

#include <Eigen/SparseCholesky>

#include "core/error.hpp"

#include <cmath>
#include <random>

using namespace granseg;

BOOST_AUTO_TEST_SUITE(linalg_supernodal_ldlt_tests)

using Matrix = SupernodalLDLT::Matrix;

namespace {

/// Phi + sum_faces w (e_a - e_b)(e_a - e_b)^T on the cells of an nx x ny x nz box inside the
/// ball of the box's inscribed sphere (a disc when ny = 1); w = 10^U(0, decades); every `empty`-th
/// cell is an empty cell: an identity row without couplings. The pattern depends on the sizes and
/// `empty` only, the values on `seed`.
Matrix viscosity_like(int nx, int ny, int nz, int empty, unsigned seed, double spread = 4.0) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> decades(0.0, spread), mass(0.1, 0.6);
    std::vector<long> row(static_cast<std::size_t>(nx) * ny * nz, -1);
    long rows = 0;
    auto centre = [](int i, int n) { return n == 1 ? 0.0 : (i + 0.5) / n - 0.5; };
    for (int k = 0; k < nz; ++k)
        for (int j = 0; j < ny; ++j)
            for (int i = 0; i < nx; ++i) {
                const double x = centre(i, nx), y = centre(j, ny), z = centre(k, nz);
                if (x * x + y * y + z * z < 0.25) row[i + nx * (j + ny * k)] = rows++;
            }
    std::vector<Eigen::Triplet<double>> entries;
    std::vector<double> diagonal(rows);
    std::vector<char> coupled(rows);
    for (long r = 0; r < rows; ++r) coupled[r] = empty == 0 || r % empty != 0, diagonal[r] = coupled[r] ? mass(rng) : 1.0;
    auto face = [&](long a, long b) {
        if (a < 0 || b < 0) return;
        const double w = std::pow(10.0, decades(rng));
        if (!coupled[a] || !coupled[b]) {  // the pattern keeps the face, with a zero value
            entries.emplace_back(a, b, 0.0), entries.emplace_back(b, a, 0.0);
            return;
        }
        entries.emplace_back(a, b, -w), entries.emplace_back(b, a, -w);
        diagonal[a] += w, diagonal[b] += w;
    };
    for (int k = 0; k < nz; ++k)
        for (int j = 0; j < ny; ++j)
            for (int i = 0; i < nx; ++i) {
                const long c = row[i + nx * (j + ny * k)];
                if (i + 1 < nx) face(c, row[i + 1 + nx * (j + ny * k)]);
                if (j + 1 < ny) face(c, row[i + nx * (j + 1 + ny * k)]);
                if (k + 1 < nz) face(c, row[i + nx * (j + ny * (k + 1))]);
            }
    for (long r = 0; r < rows; ++r) entries.emplace_back(r, r, diagonal[r]);
    Matrix A(rows, rows);
    A.setFromTriplets(entries.begin(), entries.end());
    A.makeCompressed();
    return A;
}

/// max |x_supernodal - x_simplicial| / max |x_simplicial| for a random right-hand side.
double difference_from_simplicial(const Matrix& A, bool parallel) {
    SupernodalLDLT supernodal;
    supernodal.analyze(A);
    BOOST_REQUIRE(supernodal.factorize(A, parallel));
    Eigen::SimplicialLDLT<Matrix> simplicial(A);
    BOOST_REQUIRE(simplicial.info() == Eigen::Success);
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> uniform(-1.0, 1.0);
    Eigen::VectorXd b(A.rows());
    for (long r = 0; r < A.rows(); ++r) b[r] = uniform(rng);
    const Eigen::VectorXd expected = simplicial.solve(b);
    Eigen::VectorXd x = b;
    supernodal.solve(x.data());
    return (x - expected).lpNorm<Eigen::Infinity>() / expected.lpNorm<Eigen::Infinity>();
}

}  // namespace

// Both factorisations are backward stable: the solutions agree to a modest multiple of the unit
// round-off times the condition number, here at most ~1e4 (the decades of w) over Phi ~ 0.1 per
// row sum, so 1e-9 leaves a margin of 10^2 over what was measured (~1e-13).
BOOST_AUTO_TEST_CASE(solves_like_the_simplicial_factorisation) {
    BOOST_TEST(difference_from_simplicial(viscosity_like(100, 1, 100, 0, 1), true) < 1e-9);
    BOOST_TEST(difference_from_simplicial(viscosity_like(60, 1, 60, 7, 2), true) < 1e-9);
    BOOST_TEST(difference_from_simplicial(viscosity_like(14, 14, 14, 5, 3), false) < 1e-9);
    BOOST_TEST(difference_from_simplicial(viscosity_like(3, 1, 3, 0, 4), true) < 1e-9);
    BOOST_TEST(difference_from_simplicial(viscosity_like(1, 1, 1, 0, 5), true) < 1e-9);
}

// Each step sets new values into the same pattern: a factor that kept anything of the last
// values would show here. Coefficients over eight decades make the matrix's condition number up
// to ~1e8/0.1; the backward error of a stable factorisation stays a small multiple of the unit
// round-off whatever the conditioning: |A x - b| <= 1e-13 |A| |x| (measured ~1e-16), and the two
// algorithms' solutions agree to the condition number times that (1e9 * 1e-16 = 1e-7, measured
// ~1e-10).
BOOST_AUTO_TEST_CASE(factorises_again_with_new_values_over_eight_decades) {
    SupernodalLDLT ldlt;
    ldlt.analyze(viscosity_like(90, 1, 90, 7, 11, 8.0));
    for (unsigned seed : {11u, 12u, 13u}) {
        const Matrix A = viscosity_like(90, 1, 90, 7, seed, 8.0);
        BOOST_REQUIRE(ldlt.factorize(A, true));
        Eigen::SimplicialLDLT<Matrix> simplicial(A);
        const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(A.rows(), -1.0, 1.0);
        Eigen::VectorXd x = b;
        ldlt.solve(x.data());
        const Eigen::VectorXd residual = A * x - b;
        double norm = 0.0;  // |A|_inf
        for (long r = 0; r < A.rows(); ++r) norm = std::max(norm, A.row(r).cwiseAbs().sum());
        BOOST_TEST_INFO("values of seed " << seed);
        BOOST_TEST(residual.lpNorm<Eigen::Infinity>() <= 1e-13 * norm * x.lpNorm<Eigen::Infinity>());
        const Eigen::VectorXd expected = simplicial.solve(b);
        BOOST_TEST((x - expected).lpNorm<Eigen::Infinity>() <= 1e-7 * expected.lpNorm<Eigen::Infinity>());
    }
}

// With two threads (whatever OMP_NUM_THREADS says) the lanes run side by side; the bits are those
// of the lanes one after the other.
BOOST_AUTO_TEST_CASE(threads_do_not_change_the_bits) {
    const ThreadScope on_two(2);
    const Matrix A = viscosity_like(80, 1, 80, 11, 6, 8.0);
    SupernodalLDLT one, two;
    one.analyze(A), two.analyze(A);
    BOOST_REQUIRE(one.factorize(A, false));
    BOOST_REQUIRE(region_threads() == 2);
    BOOST_REQUIRE(two.factorize(A, true));
    Eigen::VectorXd x1 = Eigen::VectorXd::LinSpaced(A.rows(), -1.0, 2.0), x2 = x1;
    one.solve(x1.data()), two.solve(x2.data());
    BOOST_TEST((x1.array() == x2.array()).all());
}

// A lane's Eigen products stay on its thread: with the default settings factorize() runs (on any
// number of threads); asked through Eigen::setNbThreads for more, it refuses.
BOOST_AUTO_TEST_CASE(eigen_opens_no_threads_inside_a_lane) {
    const Matrix A = viscosity_like(60, 1, 60, 0, 9);
    SupernodalLDLT ldlt;
    ldlt.analyze(A);
    BOOST_TEST(ldlt.factorize(A, false));
    BOOST_TEST(ldlt.factorize(A, true));
    Eigen::setNbThreads(2);
    BOOST_CHECK_THROW(ldlt.factorize(A, false), InvariantError);
    Eigen::setNbThreads(-1);  // back to OpenMP's setting
}

BOOST_AUTO_TEST_CASE(refuses_a_matrix_that_is_not_positive_definite) {
    Matrix A = viscosity_like(20, 1, 20, 0, 8);
    SupernodalLDLT ldlt;
    ldlt.analyze(A);
    BOOST_REQUIRE(ldlt.factorize(A, true));
    A.coeffRef(37, 37) = -1.0;  // a negative diagonal: no LDL^T with positive D exists
    BOOST_TEST(!ldlt.factorize(A, true));
    A.coeffRef(37, 37) = std::nan("");
    BOOST_TEST(!ldlt.factorize(A, false));
}

// A failing pivot in a wide panel (at least 16 columns: the dense Cholesky of its diagonal block)
// and in a narrow one (column by column): a negative diagonal entry of A makes that row's pivot
// negative (the updates only subtract from it), NaN makes it not finite. The row is chosen by the
// width of its supernode; in the wide panel the failure names the panel's first row.
BOOST_AUTO_TEST_CASE(refuses_in_a_wide_and_in_a_narrow_panel) {
    const Matrix good = viscosity_like(100, 1, 100, 0, 10, 8.0);
    SupernodalLDLT ldlt;
    ldlt.analyze(good);
    long wide = -1, narrow = -1;
    for (long r = 0; r < good.rows(); ++r) {
        if (wide == -1 && ldlt.supernode_width(r) >= 16) wide = r;
        if (narrow == -1 && ldlt.supernode_width(r) <= 2) narrow = r;
    }
    BOOST_REQUIRE(wide != -1);
    BOOST_REQUIRE(narrow != -1);
    for (const double bad : {-1.0, std::nan("")}) {
        Matrix A = good;
        A.coeffRef(wide, wide) = bad;
        BOOST_TEST_INFO("wide panel, diagonal " << bad);
        BOOST_TEST(!ldlt.factorize(A, true));
        BOOST_TEST(ldlt.supernode_width(ldlt.failed_row()) >= 16);
        A = good;
        A.coeffRef(narrow, narrow) = bad;
        BOOST_TEST_INFO("narrow panel, diagonal " << bad);
        BOOST_TEST(!ldlt.factorize(A, true));
        BOOST_TEST(ldlt.failed_row() == narrow);
    }
    BOOST_TEST(ldlt.factorize(good, true));
    BOOST_TEST(ldlt.failed_row() == -1);
}

BOOST_AUTO_TEST_SUITE_END()
