#include "linalg/elimination_tree.hpp"

namespace granseg {

std::vector<std::vector<long>> lower_neighbours(const Eigen::SparseMatrix<double>& A, const std::vector<long>& new_of_old) {
    std::vector<std::vector<long>> below(A.cols());
    for (long c = 0; c < A.outerSize(); ++c)
        for (Eigen::SparseMatrix<double>::InnerIterator it(A, c); it; ++it) {
            const long i = new_of_old[it.row()], j = new_of_old[c];
            if (i > j) below[j].push_back(i);
        }
    return below;
}

std::vector<long> elimination_tree(const std::vector<std::vector<long>>& below) {
    const long n = static_cast<long>(below.size());
    std::vector<long> parent(n, -1), ancestor(n, -1);
    std::vector<std::vector<long>> above(n);  // row k's entries left of the diagonal
    for (long j = 0; j < n; ++j)
        for (long i : below[j]) above[i].push_back(j);
    for (long k = 0; k < n; ++k)
        for (long i : above[k])
            while (i != -1 && i < k) {
                const long next = ancestor[i];
                ancestor[i] = k;
                if (next == -1) parent[i] = k;
                i = next;
            }
    return parent;
}

std::vector<long> postorder(const std::vector<long>& parent) {
    const long n = static_cast<long>(parent.size());
    std::vector<long> head(n, -1), next(n, -1), order, stack;
    for (long j = n - 1; j >= 0; --j)  // children lists in ascending order
        if (parent[j] != -1) next[j] = head[parent[j]], head[parent[j]] = j;
    for (long root = 0; root < n; ++root) {
        if (parent[root] != -1) continue;
        stack.push_back(root);
        while (!stack.empty()) {
            const long j = stack.back();
            if (head[j] != -1) {  // descend into the next unvisited child
                const long child = head[j];
                head[j] = next[child];
                stack.push_back(child);
            } else {
                order.push_back(j);
                stack.pop_back();
            }
        }
    }
    return order;
}

std::vector<long> column_counts(const std::vector<std::vector<long>>& below, const std::vector<long>& parent) {
    const long n = static_cast<long>(below.size());
    std::vector<long> count(n, 0), mark(n, -1);
    for (long j = 0; j < n; ++j)
        for (long k : below[j])
            for (long i = j; mark[i] != k && i != k; i = parent[i]) mark[i] = k, ++count[i];
    return count;
}

}  // namespace granseg
