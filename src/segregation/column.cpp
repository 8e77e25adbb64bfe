#include "segregation/column.hpp"

#include <cmath>

namespace granseg {

Column make_column(const ColumnSetup& setup) {
    Column c;
    c.grid = Grid::column(setup.cells, setup.length);
    const int n = setup.cells;
    const double h = c.grid.h[2];
    const auto coefficient = [&](double T) {
        if (!(T >= 0.0)) throw InputError("column: T < 0");
        return setup.S * std::sqrt(T);  // a = S sqrt(T) (eq. 66)
    };
    c.fields.Phi.resize(n);
    c.fields.a[2].resize(n);
    c.z.resize(n);
    c.T.resize(n);
    for (int k = 0; k < n; ++k) {
        c.z[k] = c.grid.center(2, k);
        c.fields.Phi[k] = setup.Phi(c.z[k]);
        c.T[k] = setup.T(c.z[k]);
        c.fields.a[2][k] = coefficient(c.T[k]);
    }
    // Interface values (read by the classic schemes only); face k is the lower face of cell k.
    std::vector<double>& Phi_face = c.fields.Phi_face[2];
    std::vector<double>& a_face = c.fields.a_face[2];
    Phi_face.resize(n + 1);
    a_face.resize(n + 1);
    // The end faces are walls of the column; they get values too, so a caller who makes the
    // axis periodic finds the wrap face filled (the mean then wraps around: cells n-1 and 0).
    for (int k = 0; k <= n; ++k) {
        if (setup.interface == InterfaceRule::exact) {
            Phi_face[k] = setup.Phi(k * h);
            a_face[k] = coefficient(setup.T(k * h));
        } else {
            const int below = (k + n - 1) % n, above = k % n;
            Phi_face[k] = 0.5 * (c.fields.Phi[below] + c.fields.Phi[above]);
            a_face[k] = coefficient(0.5 * (c.T[below] + c.T[above]));
        }
    }
    c.fields.D = setup.D;
    check_frozen_fields(c.grid, c.fields);
    return c;
}

std::vector<double> column_profile(const Column& column, const std::function<double(double)>& phi0) {
    std::vector<double> phi(column.z.size());
    for (std::size_t k = 0; k < phi.size(); ++k) phi[k] = phi0(column.z[k]);
    return phi;
}

}  // namespace granseg
