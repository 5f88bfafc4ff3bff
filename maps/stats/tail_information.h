// Information of exceeding a value, −ln P(X ≥ x), from a sample of X: the empirical tail of the
// sample, kept as the values at K tail probabilities spaced evenly in −ln P from 0 to ln(N + 1)
// (the rarest event N samples can vouch for). Unlike a fitted density's −ln p, it never exceeds
// ln(N + 1): a value beyond everything in the sample is as rare as the sample can tell, not
// rarer the farther it lies — so a cue that saturates cannot outweigh the others it is summed
// with. Tables of one K average entry by entry, for interpolating between viewpoints (quantile
// averaging where the samples have about the same size: entry k is the same tail probability
// only for the same N).
#pragma once

#include <vector>

namespace novelty::stats {

struct TailTable {
  /// values[k]: the sample's value at tail probability exp(−k·max_information / (K − 1)),
  /// non-decreasing; empty when not learnt.
  std::vector<float> values;
  double max_information = 0.0;  ///< ln(N + 1)
  bool empty() const { return values.empty(); }
};

/// The table of `samples` (finite; sorted in place). Throws std::invalid_argument for fewer
/// than 2 samples or entries, or a sample that is not finite.
TailTable LearnTail(std::vector<float>& samples, int entries = 64);

/// −ln P(X ≥ x), interpolated linearly in x between the table's entries: 0 at or below the
/// smallest entry, max_information at or above the largest and for NaN. At a value the sample
/// holds many times (a tie across entries) it is the rarest of them, −ln P(X > x).
double TailInformation(const TailTable& table, double x);

/// The weighted mean of tables of one size (weights ≥ 0, not all 0). Throws
/// std::invalid_argument for empty input, tables of different sizes or bad weights.
TailTable MeanTail(const std::vector<const TailTable*>& tables, const std::vector<double>& weights);

}  // namespace novelty::stats
