#include "maps/stats/tail_information.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace novelty::stats {

TailTable LearnTail(std::vector<float>& samples, int entries) {
  if (samples.size() < 2 || entries < 2)
    throw std::invalid_argument("LearnTail: " + std::to_string(samples.size()) + " samples and " +
                                std::to_string(entries) + " entries; at least 2 of each");
  for (std::size_t i = 0; i < samples.size(); ++i)
    if (!std::isfinite(samples[i]))
      throw std::invalid_argument("LearnTail: sample " + std::to_string(i) + " is not finite");
  std::sort(samples.begin(), samples.end());
  const double n = double(samples.size());
  TailTable t;
  t.max_information = std::log(n + 1.0);
  for (int k = 0; k < entries; ++k) {
    // The value exceeded (≥) by a share P of the sample: the (1 − P)-quantile.
    const double p = std::exp(-k * t.max_information / (entries - 1));
    const double rank = std::ceil(n * (1.0 - p) - 1e-9);
    t.values.push_back(samples[std::size_t(std::clamp(rank, 0.0, n - 1.0))]);
  }
  return t;
}

double TailInformation(const TailTable& t, double x) {
  const std::vector<float>& v = t.values;
  if (v.empty()) return 0.0;
  // Compared in double throughout: a value just below the last entry must not round onto it.
  if (std::isnan(x) || x >= double(v.back())) return t.max_information;
  if (x <= double(v.front())) return 0.0;
  const double step = t.max_information / double(v.size() - 1);
  // The last entry at or below x (x < v.back(), so k + 1 is an entry); ties take the rarest.
  const std::size_t k =
      std::size_t(
          std::upper_bound(v.begin(), v.end(), x, [](double a, float b) { return a < double(b); }) -
          v.begin()) -
      1;
  const double span = double(v[k + 1]) - double(v[k]);
  const double f = span > 0.0 ? (x - v[k]) / span : 0.0;
  return step * (double(k) + f);
}

TailTable MeanTail(const std::vector<const TailTable*>& tables,
                   const std::vector<double>& weights) {
  if (tables.empty() || tables.size() != weights.size())
    throw std::invalid_argument("MeanTail: one weight per table, at least one table");
  TailTable mean;
  mean.values.assign(tables.front()->values.size(), 0.0f);
  double total = 0.0;
  for (std::size_t i = 0; i < tables.size(); ++i) {
    if (tables[i]->values.size() != mean.values.size() || !(weights[i] >= 0.0))
      throw std::invalid_argument("MeanTail: table " + std::to_string(i) +
                                  " has another size or a negative weight");
    total += weights[i];
    mean.max_information += weights[i] * tables[i]->max_information;
    for (std::size_t k = 0; k < mean.values.size(); ++k)
      mean.values[k] += float(weights[i] * tables[i]->values[k]);
  }
  if (!(total > 0.0)) throw std::invalid_argument("MeanTail: the weights sum to 0");
  mean.max_information /= total;
  for (float& v : mean.values) v = float(v / total);
  return mean;
}

}  // namespace novelty::stats
