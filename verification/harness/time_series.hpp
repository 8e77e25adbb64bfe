// The sampling error of a drum diagnostic recorded over time (history.dat): a difference between
// two runs smaller than it is noise, not a trend of the grid (docs/sect4.2_tumbler.md,
// section "Results").
#pragma once

#include <vector>

namespace granseg::verify {

/// Standard error of the mean of a correlated series by batch means: the samples (in time order)
/// split into `batches` consecutive batches of equal length (the first n mod batches samples left
/// out), the standard deviation of the batch means over sqrt(batches). Batches much longer than the
/// correlation time make the batch means independent. NaN with fewer than two samples per batch.
double batch_mean_error(const std::vector<double>& values, int batches = 10);

/// Standard deviation of the samples about their least-squares straight line in t (n - 2 degrees
/// of freedom): the jitter of a value read at one instant, with a slow drift taken out. NaN with
/// fewer than three samples.
double detrended_spread(const std::vector<double>& t, const std::vector<double>& values);

}  // namespace granseg::verify
