#include "harness/time_series.hpp"

#include "core/error.hpp"

#include <cmath>
#include <limits>

namespace granseg::verify {

double batch_mean_error(const std::vector<double>& values, int batches) {
    if (batches < 2) throw InputError("batch means: need at least two batches");
    const std::size_t n = values.size(), length = n / static_cast<std::size_t>(batches);
    if (length < 2) return std::numeric_limits<double>::quiet_NaN();
    const std::size_t first = n - length * static_cast<std::size_t>(batches);
    std::vector<double> means(batches, 0.0);
    double mean = 0.0;
    for (int b = 0; b < batches; ++b) {
        for (std::size_t i = 0; i < length; ++i) means[b] += values[first + b * length + i];
        means[b] /= static_cast<double>(length);
        mean += means[b] / batches;
    }
    double squares = 0.0;
    for (double m : means) squares += (m - mean) * (m - mean);
    return std::sqrt(squares / (batches - 1) / batches);
}

double detrended_spread(const std::vector<double>& t, const std::vector<double>& values) {
    if (t.size() != values.size()) throw InputError("detrended spread: times and values differ in length");
    const std::size_t n = t.size();
    if (n < 3) return std::numeric_limits<double>::quiet_NaN();
    double t_mean = 0.0, v_mean = 0.0;
    for (std::size_t i = 0; i < n; ++i) t_mean += t[i] / n, v_mean += values[i] / n;
    double stt = 0.0, stv = 0.0;
    for (std::size_t i = 0; i < n; ++i) stt += (t[i] - t_mean) * (t[i] - t_mean), stv += (t[i] - t_mean) * (values[i] - v_mean);
    const double slope = stt > 0.0 ? stv / stt : 0.0;
    double squares = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
        const double r = values[i] - v_mean - slope * (t[i] - t_mean);
        squares += r * r;
    }
    return std::sqrt(squares / static_cast<double>(n - 2));
}

}  // namespace granseg::verify
