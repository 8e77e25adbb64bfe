#include "linalg/conjugate_gradients.hpp"

#include "core/threads.hpp"

#include <omp.h>

#include <cmath>
#include <limits>
#include <vector>

namespace granseg {

namespace {

/// Rows per block of a dot product: its partial sums, added in block order, fix the rounding
/// whatever the number of threads.
constexpr long kDotBlock = 512;

/// Every thread of the team gets sum_r a_r b_r. The blocks are shared (the loop's barrier ends
/// them), then each thread adds the partial sums in order. `partial` is written again only after
/// another barrier of the caller (each use below is followed by a shared loop).
double team_dot(const double* a, const double* b, long n, std::vector<double>& partial) {
    const long blocks = static_cast<long>(partial.size());
#pragma omp for schedule(static)
    for (long k = 0; k < blocks; ++k) {
        double sum = 0.0;
        const long end = std::min(n, (k + 1) * kDotBlock);
        for (long r = k * kDotBlock; r < end; ++r) sum += a[r] * b[r];
        partial[k] = sum;
    }
    double sum = 0.0;
    for (double s : partial) sum += s;
    return sum;
}

}  // namespace

CgResult team_cg(const Multilevel::Matrix& A, const Multilevel& B, const Eigen::VectorXd& b, double tolerance,
                     Eigen::VectorXd& x) {
    const long n = A.rows(), max_iterations = 2 * n;
    x.setZero(n);
    CgResult result;
    const double rhs2 = b.squaredNorm();
    if (rhs2 == 0.0) return result;
    // Eigen::ConjugateGradient's threshold.
    const double threshold = std::max(tolerance * tolerance * rhs2, std::numeric_limits<double>::min());
    Eigen::VectorXd r = b, p(n), q(n);
    std::vector<double> partial((n + kDotBlock - 1) / kDotBlock);
    const int* outer = A.outerIndexPtr();
    const int* inner = A.innerIndexPtr();
    const double* a = A.valuePtr();
    double* xs = x.data();
    double* rs = r.data();
    double* ps = p.data();
    double* qs = q.data();
    const double* z = B.result().data();
    long iterations = 0;
    double residual2 = 0.0;
    // Every thread of the team runs this; its work-shared loops, single blocks and barriers bind
    // to the team, or to this thread alone where it runs outside a parallel region.
    auto team = [&] {
        double r2 = team_dot(rs, rs, n, partial);
        if (r2 >= threshold) {
            B.team_cycle(rs);  // ends with a barrier: z is complete
#pragma omp for schedule(static)
            for (long i = 0; i < n; ++i) ps[i] = z[i];
            double rz = team_dot(rs, ps, n, partial);
            long i = 0;
            while (i < max_iterations) {
#pragma omp for schedule(static)
                for (long row = 0; row < n; ++row) {
                    double sum = 0.0;
                    for (int k = outer[row]; k < outer[row + 1]; ++k) sum += a[k] * ps[inner[k]];
                    qs[row] = sum;
                }
                const double alpha = rz / team_dot(ps, qs, n, partial);
#pragma omp for schedule(static)
                for (long row = 0; row < n; ++row) xs[row] += alpha * ps[row], rs[row] -= alpha * qs[row];
                r2 = team_dot(rs, rs, n, partial);
                if (r2 < threshold) break;  // every thread has the same r2: all leave together
                B.team_cycle(rs);
                const double rz_old = rz;
                rz = team_dot(rs, z, n, partial);
                const double beta = rz / rz_old;
#pragma omp for schedule(static)
                for (long row = 0; row < n; ++row) ps[row] = z[row] + beta * ps[row];
                ++i;
            }
#pragma omp single
            iterations = i;
        }
#pragma omp single
        residual2 = r2;
    };
    if (on_threads(true)) {
#pragma omp parallel
        team();
    } else {
        team();
    }
    result.iterations = iterations;
    result.error = std::sqrt(residual2 / rhs2);
    return result;
}

}  // namespace granseg
