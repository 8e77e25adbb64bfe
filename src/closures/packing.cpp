#include "closures/packing.hpp"

#include "core/error.hpp"
#include "run/embedded.hpp"

#include <gsl/gsl_multifit.h>

#include <cmath>
#include <memory>
#include <sstream>

namespace granseg {

PackingTable parse_packing_table(const std::string& text, const std::string& name) {
    PackingTable table;
    std::istringstream in(text);
    std::string line;
    int number = 0;
    while (std::getline(in, line)) {
        ++number;
        if (number == 1) {
            std::istringstream head(line);
            std::string hash, a, b, c;
            head >> hash >> a >> b >> c;
            if (hash != "#" || a != "phi_hat" || b != "Phi_rcp" || c != "Phi_co")
                throw InputError(name + ": line 1 must be '# phi_hat Phi_rcp Phi_co'");
            continue;
        }
        if (line.rfind("#", 0) == 0) {
            table.comments.push_back(line.size() > 2 ? line.substr(2) : "");
            continue;
        }
        std::istringstream row(line);
        double x, rcp, co;
        if (!(row >> x)) continue;  // blank line
        std::string rest;
        if (!(row >> rcp >> co) || (row >> rest))
            throw InputError(name + ": line " + std::to_string(number) + ": expected three numbers");
        if (!(x >= 0 && x <= 1 && co > 0 && co < rcp && rcp < 1))
            throw InputError(name + ": line " + std::to_string(number) + ": need 0 <= phi_hat <= 1 and 0 < Phi_co < Phi_rcp < 1");
        table.phi_hat.push_back(x);
        table.Phi_rcp.push_back(rcp);
        table.Phi_co.push_back(co);
    }
    return table;
}

PackingTable builtin_packing_table() {
    return parse_packing_table(std::string(embedded_file("closures/packing_binary_r2.dat")), "closures/packing_binary_r2.dat");
}

Polynomial fit_polynomial(const std::vector<double>& x, const std::vector<double>& y, int degree) {
    const std::size_t n = x.size(), p = static_cast<std::size_t>(degree) + 1;
    if (degree < 0 || y.size() != n || n < p) throw InputError("fit_polynomial: need at least degree + 1 points");
    // Design matrix X_ik = x_i^k; GSL solves min |X c - y|_2 by an SVD of X.
    std::unique_ptr<gsl_matrix, decltype(&gsl_matrix_free)> X(gsl_matrix_alloc(n, p), gsl_matrix_free);
    std::unique_ptr<gsl_matrix, decltype(&gsl_matrix_free)> cov(gsl_matrix_alloc(p, p), gsl_matrix_free);
    std::unique_ptr<gsl_vector, decltype(&gsl_vector_free)> Y(gsl_vector_alloc(n), gsl_vector_free);
    std::unique_ptr<gsl_vector, decltype(&gsl_vector_free)> C(gsl_vector_alloc(p), gsl_vector_free);
    std::unique_ptr<gsl_multifit_linear_workspace, decltype(&gsl_multifit_linear_free)> work(gsl_multifit_linear_alloc(n, p),
                                                                                             gsl_multifit_linear_free);
    for (std::size_t i = 0; i < n; ++i) {
        gsl_vector_set(Y.get(), i, y[i]);
        for (std::size_t k = 0; k < p; ++k) gsl_matrix_set(X.get(), i, k, std::pow(x[i], static_cast<double>(k)));
    }
    double chisq = 0.0;
    if (gsl_multifit_linear(X.get(), Y.get(), C.get(), cov.get(), &chisq, work.get()) != 0)
        throw InputError("fit_polynomial: gsl_multifit_linear failed");
    Polynomial poly;
    for (std::size_t k = 0; k < p; ++k) poly.c.push_back(gsl_vector_get(C.get(), k));
    return poly;
}

PackingFit::PackingFit(PackingTable table, int degree) : table_(std::move(table)) {
    if (table_.phi_hat.size() < static_cast<std::size_t>(degree) + 1)
        throw InputError("packing table has " + std::to_string(table_.phi_hat.size()) + " points, too few for a degree-" +
                         std::to_string(degree) + " fit");
    rcp_ = fit_polynomial(table_.phi_hat, table_.Phi_rcp, degree);
    co_ = fit_polynomial(table_.phi_hat, table_.Phi_co, degree);
    // The model needs Phi_co < Phi_rcp < 1 for every mixture, not only at the data points.
    for (int i = 0; i <= 1000; ++i) {
        const double x = i / 1000.0;
        if (!(rcp_(x) < 1.0 && co_(x) > 0.0 && co_(x) < rcp_(x)))
            throw InputError("packing fit violates 0 < Phi_co < Phi_rcp < 1 at phi_hat = " + std::to_string(x));
    }
}

}  // namespace granseg
