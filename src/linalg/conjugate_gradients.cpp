#include "linalg/conjugate_gradients.hpp"

#include "core/threads.hpp"

#include <cmath>
#include <limits>
#include <vector>

namespace granseg {

namespace {

/// q = A p, the rows shared among the team.
void team_product(Team& team, const Multilevel::Matrix& A, const double* p, double* q) {
    const int* outer = A.outerIndexPtr();
    const int* inner = A.innerIndexPtr();
    const double* a = A.valuePtr();
    team.share(A.rows(), [&](long begin, long end) {
        for (long row = begin; row < end; ++row) {
            double sum = 0.0;
            for (int k = outer[row]; k < outer[row + 1]; ++k) sum += a[k] * p[inner[k]];
            q[row] = sum;
        }
    });
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
    double* xs = x.data();
    double* rs = r.data();
    double* ps = p.data();
    double* qs = q.data();
    const double* z = B.result().data();
    long iterations = 0;
    double residual2 = 0.0;
    // Every thread of the team runs this; each shared loop, dot product and cycle ends with the
    // team's barrier (core/threads.hpp, Team).
    run_as_team(true, n, [&](Team& team) {
        double r2 = team.dot(rs, rs, n);
        if (r2 >= threshold) {
            B.team_cycle(team, rs);
            team.share(n, [&](long begin, long end) {
                for (long i = begin; i < end; ++i) ps[i] = z[i];
            });
            double rz = team.dot(rs, ps, n);
            long i = 0;
            while (i < max_iterations) {
                team_product(team, A, ps, qs);
                const double alpha = rz / team.dot(ps, qs, n);
                team.share(n, [&](long begin, long end) {
                    for (long row = begin; row < end; ++row) xs[row] += alpha * ps[row], rs[row] -= alpha * qs[row];
                });
                r2 = team.dot(rs, rs, n);
                if (r2 < threshold) break;  // every thread has the same r2: all leave together
                B.team_cycle(team, rs);
                const double rz_old = rz;
                rz = team.dot(rs, z, n);
                const double beta = rz / rz_old;
                team.share(n, [&](long begin, long end) {
                    for (long row = begin; row < end; ++row) ps[row] = z[row] + beta * ps[row];
                });
                ++i;
            }
            team.single([&] { iterations = i; });
        }
        team.single([&] { residual2 = r2; });
    });
    result.iterations = iterations;
    result.error = std::sqrt(residual2 / rhs2);
    return result;
}

}  // namespace granseg
