#include "linalg/supernodal_ldlt.hpp"

#include "core/error.hpp"
#include "core/threads.hpp"
#include "linalg/elimination_tree.hpp"

#include <Eigen/Cholesky>
#include <Eigen/OrderingMethods>

#include <algorithm>
#include <cmath>
#include <limits>

namespace granseg {

namespace {
/// A column joins the supernode of the column before it (its only descendant in the chain) while
/// the explicit zeros this adds stay below this share of the merged supernode's stored entries:
/// a few zeros buy longer dense loops and fewer updates.
constexpr double kRelaxedZeros = 0.1;
/// Updates of at least this many multiply-adds go through Eigen's dense product (blocked, vectorised);
/// smaller ones through plain loops (no set-up cost).
constexpr long kDenseProduct = 1024;
/// Supernodes at least this wide factor their diagonal block by Eigen's dense Cholesky.
constexpr long kDenseBlock = 16;
/// The split into two lanes stops expanding the top after this many supernodes (a balanced split
/// of a minimum-degree tree is found within a few dozen).
constexpr int kSplitExpansions = 256;
}  // namespace

void SupernodalLDLT::analyze(const Matrix& A) {
    const std::vector<std::vector<long>> below = order_rows(A);
    const std::vector<long> parent = elimination_tree(below);
    std::vector<long> super_parent;
    std::vector<std::vector<long>> children;
    form_supernodes(parent, column_counts(below, parent), super_parent, children);
    gather_rows(below, children);
    place_entries(A);
    split(update_work(), super_parent, children);
    const long supers = supernodes();
    for (Lane& lane : lanes_) lane.relative.assign(rows(), 0);
    next_.assign(supers, -1), link_.assign(supers, -1), cursor_.assign(supers, 0);
}

std::vector<std::vector<long>> SupernodalLDLT::order_rows(const Matrix& A) {
    const long n = A.rows();
    // The fill-reducing order, then a postorder of its elimination tree (same fill, and the
    // columns of every subtree, so of every supernode, become consecutive).
    Eigen::PermutationMatrix<Eigen::Dynamic, Eigen::Dynamic, int> minimum_degree;  // k-th eliminated -> row
    Eigen::AMDOrdering<int>()(A, minimum_degree);
    std::vector<long> new_of_old(n);
    for (long k = 0; k < n; ++k) new_of_old[minimum_degree.indices()[k]] = k;
    const std::vector<long> post = postorder(elimination_tree(lower_neighbours(A, new_of_old)));
    order_.resize(n);
    for (long k = 0; k < n; ++k) order_[k] = minimum_degree.indices()[post[k]];
    for (long k = 0; k < n; ++k) new_of_old[order_[k]] = k;
    new_of_old_ = new_of_old;
    return lower_neighbours(A, new_of_old);
}

void SupernodalLDLT::form_supernodes(const std::vector<long>& parent, const std::vector<long>& count,
                                     std::vector<long>& super_parent, std::vector<std::vector<long>>& children) {
    const long n = static_cast<long>(parent.size());
    // Chains j -> j + 1 = parent(j), merged while the padded zeros stay few.
    first_.assign(1, 0);
    for (long j = 0; j + 1 < n; ++j) {
        const long f = first_.back(), next = j + 1;
        bool merge = parent[j] == next;
        if (merge) {  // column c of the merged panel stores (next - c) + count[next] entries below its diagonal
            double stored = 0.0, zeros = 0.0;
            for (long c = f; c <= next; ++c) {
                stored += static_cast<double>(next - c + count[next]);
                zeros += static_cast<double>(next - c + count[next] - count[c]);
            }
            merge = zeros <= kRelaxedZeros * stored;
        }
        if (!merge) first_.push_back(next);
    }
    first_.push_back(n);
    const long supers = supernodes();
    super_of_.resize(n);
    for (long s = 0; s < supers; ++s)
        for (long j = first_[s]; j < first_[s + 1]; ++j) super_of_[j] = s;
    super_parent.assign(supers, -1);
    children.assign(supers, {});
    for (long s = 0; s < supers; ++s) {
        const long p = parent[first_[s + 1] - 1];
        if (p != -1) super_parent[s] = super_of_[p], children[super_of_[p]].push_back(s);
    }
}

void SupernodalLDLT::gather_rows(const std::vector<std::vector<long>>& below, const std::vector<std::vector<long>>& children) {
    // Each supernode's rows: its columns, then below its last column the entries of A in its
    // columns and the rows of its child supernodes.
    const long supers = supernodes();
    row_start_.assign(1, 0);
    row_.clear();
    std::vector<long> mark(below.size(), -1);
    for (long s = 0; s < supers; ++s) {
        const long last = first_[s + 1] - 1;
        std::vector<long> rows;
        for (long j = first_[s]; j <= last; ++j) rows.push_back(j), mark[j] = s;
        auto add = [&](long i) {
            if (i > last && mark[i] != s) mark[i] = s, rows.push_back(i);
        };
        for (long j = first_[s]; j <= last; ++j)
            for (long i : below[j]) add(i);
        for (long t : children[s])
            for (long q = row_start_[t]; q < row_start_[t + 1]; ++q) add(row_[q]);
        std::sort(rows.begin() + (last + 1 - first_[s]), rows.end());
        row_.insert(row_.end(), rows.begin(), rows.end());
        row_start_.push_back(static_cast<long>(row_.size()));
    }
    value_start_.assign(1, 0);
    for (long s = 0; s < supers; ++s) value_start_.push_back(value_start_.back() + width(s) * height(s));
    value_.assign(value_start_.back(), 0.0);
}

void SupernodalLDLT::place_entries(const Matrix& A) {
    // Where each stored entry of A (lower triangle in the new numbering) goes, by supernode.
    entry_start_.assign(1, 0);
    entry_.clear();
    for (long s = 0; s < supernodes(); ++s) {
        const auto begin = row_.begin() + row_start_[s], end = row_.begin() + row_start_[s + 1];
        for (long j = first_[s]; j < first_[s + 1]; ++j)
            for (long p = A.outerIndexPtr()[order_[j]]; p < A.outerIndexPtr()[order_[j] + 1]; ++p) {
                const long i = new_of_old_[A.innerIndexPtr()[p]];
                if (i >= j) entry_.push_back({p, (j - first_[s]) * height(s) + (std::lower_bound(begin, end, i) - begin)});
            }
        entry_start_.push_back(static_cast<long>(entry_.size()));
    }
}

std::vector<double> SupernodalLDLT::update_work() const {
    // factorize() without the arithmetic: each update's multiply-adds (and its scatter) go to the
    // supernode that receives it, each panel's to itself.
    const long supers = supernodes();
    std::vector<long> link(supers, -1), next(supers, -1), cursor(supers, 0);
    std::vector<double> work(supers, 0.0);
    auto wait_for_next_row = [&](long d) {
        const long t = waits_for(d, cursor[d]);
        if (t != -1) next[d] = link[t], link[t] = d;
    };
    for (long s = 0; s < supers; ++s) {
        for (long d = link[s]; d != -1;) {
            const long after = next[d], q = rows_in(d, cursor[d], s);
            work[s] += static_cast<double>(width(d) + 1) * static_cast<double>((height(d) - cursor[d]) * q);
            cursor[d] += q;
            wait_for_next_row(d);
            d = after;
        }
        work[s] += static_cast<double>((width(s) + 1) * width(s) * height(s));
        cursor[s] = width(s);
        wait_for_next_row(s);
    }
    return work;
}

long SupernodalLDLT::supernode_width(long r) const { return width(super_of_[new_of_old_[r]]); }

long SupernodalLDLT::waits_for(long d, long position) const {
    return position == height(d) ? -1 : super_of_[row_[row_start_[d] + position]];
}

long SupernodalLDLT::rows_in(long d, long begin, long s) const {
    const long* R = row_.data() + row_start_[d];
    const long h = height(d), last = first_[s + 1] - 1;
    long q = 0;
    while (begin + q < h && R[begin + q] <= last) ++q;
    return q;
}

void SupernodalLDLT::split(const std::vector<double>& work, const std::vector<long>& parent,
                           const std::vector<std::vector<long>>& children) {
    // Supernodes are in postorder: the subtree of s is the range [s - size[s] + 1, s].
    const long supers = supernodes();
    std::vector<long> size(supers, 1);
    std::vector<double> subtree(work);
    for (long s = 0; s < supers; ++s)
        if (parent[s] != -1) size[parent[s]] += size[s], subtree[parent[s]] += subtree[s];
    // Move the largest subtree's root into the top while that shortens top + the larger lane
    // (subtrees dealt largest first to the lighter lane).
    std::vector<long> front, top;
    for (long s = 0; s < supers; ++s)
        if (parent[s] == -1) front.push_back(s);
    double top_work = 0.0, best = std::numeric_limits<double>::infinity();
    for (int expansion = 0; !front.empty() && expansion <= kSplitExpansions; ++expansion) {
        std::sort(front.begin(), front.end(), [&](long a, long b) { return subtree[a] > subtree[b]; });
        std::array<double, 2> load{};
        std::array<std::vector<long>, 2> roots;
        for (long r : front) {
            const int lane = load[0] <= load[1] ? 0 : 1;
            load[lane] += subtree[r], roots[lane].push_back(r);
        }
        if (top_work + std::max(load[0], load[1]) < best) {
            best = top_work + std::max(load[0], load[1]);
            top_ = top;
            for (int lane = 0; lane < 2; ++lane) {
                std::vector<std::pair<long, long>>& ranges = lanes_[lane].subtrees;
                ranges.clear();
                for (long r : roots[lane]) ranges.emplace_back(r - size[r] + 1, r + 1);
                std::sort(ranges.begin(), ranges.end());
            }
        }
        const long x = front.front();
        front.erase(front.begin());
        top.push_back(x), top_work += work[x];
        front.insert(front.end(), children[x].begin(), children[x].end());
    }
    std::sort(top_.begin(), top_.end());
    in_top_.assign(supers, 0);
    for (long s : top_) in_top_[s] = 1;
}

bool SupernodalLDLT::factorize(const Matrix& A, bool parallel) {
    const double* a = A.valuePtr();
    std::fill(link_.begin(), link_.end(), -1);
    // Left-looking: supernode s takes the updates of every earlier supernode with rows in its
    // columns (the list link_[s]), then factors its panel. The two lanes' subtrees share no
    // supernode and no list: what waits for a top supernode is linked after both.
    std::array<char, 2> ok{1, 1}, eigen_alone{1, 1};
    failed_row_ = -1;
    // Eigen's dense products open their own OpenMP team when the caller's is not active and
    // nbThreads() > 1; a lane keeps them to its own thread (the lanes' bits must not depend on
    // the threads), which parallel_lanes ensures unless Eigen::setNbThreads() overrides it.
    parallel_lanes(parallel, 2, [&](int l) {
        eigen_alone[l] = Eigen::nbThreads() == 1;
        Lane& lane = lanes_[l];
        lane.pending.clear();
        for (const auto& [begin, end] : lane.subtrees)
            for (long s = begin; s < end && ok[l]; ++s) ok[l] = factor_supernode(s, a, lane, true);
    });
    if (!eigen_alone[0] || !eigen_alone[1])
        throw InvariantError(
            "supernodal LDL^T: Eigen::setNbThreads() asks Eigen's dense products for threads of their "
            "own inside a factorisation lane");
    if (!ok[0] || !ok[1]) return false;
    for (Lane& lane : lanes_)
        for (long d : lane.pending) {
            const long t = waits_for(d, cursor_[d]);
            next_[d] = link_[t], link_[t] = d;
        }
    for (long s : top_)
        if (!factor_supernode(s, a, lanes_[0], false)) return false;
    return true;
}

bool SupernodalLDLT::factor_supernode(long s, const double* a, Lane& lane, bool defer) {
    // After an update or its own factorisation, a supernode waits for its next row's supernode.
    auto wait_for_next_row = [&](long d) {
        const long t = waits_for(d, cursor_[d]);
        if (t == -1) return;
        if (defer && in_top_[t])
            lane.pending.push_back(d);
        else
            next_[d] = link_[t], link_[t] = d;
    };
    // The panel starts as s's entries of A (assembled here, on the lane's thread).
    double* P = value_.data() + value_start_[s];
    std::fill(P, P + width(s) * height(s), 0.0);
    for (long e = entry_start_[s]; e < entry_start_[s + 1]; ++e) P[entry_[e].second] += a[entry_[e].first];
    for (long q = 0; q < height(s); ++q) lane.relative[row_[row_start_[s] + q]] = q;
    for (long d = link_[s]; d != -1;) {
        const long after = next_[d];
        update(d, s, lane);
        wait_for_next_row(d);
        d = after;
    }
    if (!factor_panel(s)) return false;
    cursor_[s] = width(s);
    wait_for_next_row(s);
    return true;
}

void SupernodalLDLT::update(long d, long s, Lane& lane) {
    const long* R = row_.data() + row_start_[d];
    const long begin = cursor_[d], h = height(d), w = width(d), m = h - begin, q = rows_in(d, begin, s);
    cursor_[d] = begin + q;
    const double* L = value_.data() + value_start_[d];
    double* P = value_.data() + value_start_[s];
    const long hs = height(s);
    const long* relative = lane.relative.data();
    if (w == 1) {  // one column: its outer product goes straight into the panel
        const double* column = L + begin;
        for (long jj = 0; jj < q; ++jj) {
            const double t = L[0] * column[jj];
            double* target = P + (R[begin + jj] - first_[s]) * hs;
            for (long ii = jj; ii < m; ++ii) target[relative[R[begin + ii]]] -= column[ii] * t;
        }
        return;
    }
    // U = L_d(rows from begin) D_d L_d(the q rows in s)^T, dense m x q (lower part used).
    lane.product.resize(m * q);
    Eigen::Map<Eigen::MatrixXd> U(lane.product.data(), m, q);
    if (w * m * q >= kDenseProduct) {
        const Eigen::Map<const Eigen::MatrixXd, 0, Eigen::OuterStride<>> Ld(L + begin, m, w, Eigen::OuterStride<>(h));
        const Eigen::Map<const Eigen::VectorXd, 0, Eigen::InnerStride<>> D(L, w, Eigen::InnerStride<>(h + 1));
        lane.scaled.resize(w * q);
        Eigen::Map<Eigen::MatrixXd> S(lane.scaled.data(), w, q);
        S.noalias() = D.asDiagonal() * Ld.topRows(q).transpose();
        U.noalias() = Ld * S;
    } else {
        U.setZero();
        for (long k = 0; k < w; ++k) {
            const double* column = L + k * h + begin;
            const double dk = L[k * h + k];
            for (long jj = 0; jj < q; ++jj) {
                const double t = dk * column[jj];
                double* u = lane.product.data() + jj * m;
                for (long ii = jj; ii < m; ++ii) u[ii] += column[ii] * t;
            }
        }
    }
    for (long jj = 0; jj < q; ++jj) {
        double* target = P + (R[begin + jj] - first_[s]) * hs;
        const double* u = lane.product.data() + jj * m;
        for (long ii = jj; ii < m; ++ii) target[relative[R[begin + ii]]] -= u[ii];
    }
}

bool SupernodalLDLT::factor_panel(long s) {
    double* P = value_.data() + value_start_[s];
    const long h = height(s), w = width(s);
    if (w >= kDenseBlock) {
        // Blocked: A11 = C C^T (Cholesky), so L11 = C diag(C)^-1, D = diag(C)^2 and
        // L21 = A21 C^-T diag(C)^-1.
        Eigen::Map<Eigen::MatrixXd> panel(P, h, w);
        Eigen::Ref<Eigen::MatrixXd> top(panel.topRows(w));
        Eigen::LLT<Eigen::Ref<Eigen::MatrixXd>> cholesky(top);
        if (cholesky.info() != Eigen::Success || !top.diagonal().allFinite()) {
            failed_row_ = order_[first_[s]];
            return false;
        }
        const Eigen::VectorXd c = top.diagonal();
        if (h > w) {
            Eigen::Ref<Eigen::MatrixXd> below(panel.bottomRows(h - w));
            top.triangularView<Eigen::Lower>().transpose().solveInPlace<Eigen::OnTheRight>(below);
            below = below * c.cwiseInverse().asDiagonal();
        }
        for (long k = 0; k < w; ++k) {
            top(k, k) = c[k] * c[k];
            for (long i = k + 1; i < w; ++i) top(i, k) /= c[k];
        }
        return true;
    }
    for (long k = 0; k < w; ++k) {
        double* column = P + k * h;
        const double d = column[k];
        if (!(d > 0.0 && std::isfinite(d))) {
            failed_row_ = order_[first_[s] + k];
            return false;
        }
        for (long j = k + 1; j < w; ++j) {  // the panel's later columns: P(i, j) -= L(i, k) d L(j, k)
            const double t = column[j] / d;
            if (t == 0.0) continue;
            double* target = P + j * h;
            for (long i = j; i < h; ++i) target[i] -= column[i] * t;
        }
        for (long i = k + 1; i < h; ++i) column[i] /= d;
    }
    return true;
}

void SupernodalLDLT::solve(double* x) const {
    const long n = rows();
    std::vector<double> y(n);
    for (long k = 0; k < n; ++k) y[k] = x[order_[k]];
    for (long s = 0; s < supernodes(); ++s) {  // L y = P b
        const double* P = value_.data() + value_start_[s];
        const long* R = row_.data() + row_start_[s];
        const long h = height(s);
        for (long k = 0; k < width(s); ++k) {
            const double v = y[first_[s] + k];
            if (v == 0.0) continue;
            for (long i = k + 1; i < h; ++i) y[R[i]] -= P[k * h + i] * v;
        }
    }
    for (long s = 0; s < supernodes(); ++s)  // D
        for (long k = 0; k < width(s); ++k) y[first_[s] + k] /= value_[value_start_[s] + k * height(s) + k];
    for (long s = supernodes() - 1; s >= 0; --s) {  // L^T
        const double* P = value_.data() + value_start_[s];
        const long* R = row_.data() + row_start_[s];
        const long h = height(s);
        for (long k = width(s) - 1; k >= 0; --k) {
            double sum = 0.0;
            for (long i = k + 1; i < h; ++i) sum += P[k * h + i] * y[R[i]];
            y[first_[s] + k] -= sum;
        }
    }
    for (long k = 0; k < n; ++k) x[order_[k]] = y[k];
}

}  // namespace granseg
