// Packing limits of the binary mixture (Sect. 2.1): the random close packing Phi_rcp(phi_hat)
// and the cross-over volume fraction Phi_co(phi_hat), as polynomial least-squares fits (GSL) to a
// tabulated data file. The paper fits the data of its ref. [24], lost in the OCR; the built-in
// table src/closures/packing_binary_r2.dat names the substitute source (docs/assumptions.md).
#pragma once

#include <string>
#include <vector>

namespace granseg {

/// Tabulated packing data: at each phi_hat the values of Phi_rcp and Phi_co.
struct PackingTable {
    std::vector<double> phi_hat, Phi_rcp, Phi_co;
    std::vector<std::string> comments;  // the file's "# " lines after the column line (its source)
};

/// Parses a table with columns "phi_hat Phi_rcp Phi_co" ("# " comment lines allowed);
/// throws InputError with a one-line reason, naming `name` and the line.
PackingTable parse_packing_table(const std::string& text, const std::string& name);

/// The built-in table (size ratio 2, Desmond-Weeks formula; see the file header).
PackingTable builtin_packing_table();

/// The polynomial sum_k c[k] x^k.
struct Polynomial {
    std::vector<double> c;
    double operator()(double x) const {
        double v = 0.0;
        for (auto it = c.rbegin(); it != c.rend(); ++it) v = v * x + *it;  // Horner
        return v;
    }
};

/// Least-squares polynomial of `degree` through the points (x, y) (GSL gsl_multifit_linear).
Polynomial fit_polynomial(const std::vector<double>& x, const std::vector<double>& y, int degree);

/// Phi_rcp(phi_hat) and Phi_co(phi_hat) fitted to a packing table.
class PackingFit {
public:
    /// Fits both columns with polynomials of `degree`; throws InputError if the table
    /// has too few points or the fits give Phi_co >= Phi_rcp or Phi_rcp >= 1 somewhere in [0, 1].
    PackingFit(PackingTable table, int degree);

    /// Random close packing at the small-particle fraction phi_hat (clamped to [0, 1]).
    double Phi_rcp(double phi_hat) const { return rcp_(clamp01(phi_hat)); }
    /// Cross-over volume fraction (onset of the yield pressure, eq. 19) at phi_hat.
    double Phi_co(double phi_hat) const { return co_(clamp01(phi_hat)); }

    const PackingTable& table() const { return table_; }
    const Polynomial& rcp_polynomial() const { return rcp_; }
    const Polynomial& co_polynomial() const { return co_; }
    int degree() const { return static_cast<int>(rcp_.c.size()) - 1; }

private:
    static double clamp01(double x) { return x < 0.0 ? 0.0 : (x > 1.0 ? 1.0 : x); }
    PackingTable table_;
    Polynomial rcp_, co_;
};

}  // namespace granseg
