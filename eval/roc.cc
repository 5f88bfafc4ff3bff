#include "eval/roc.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <stdexcept>
#include <string>

namespace novelty::eval {

double Roc::TprAtFpr(double max_fpr) const {
  double best = 0.0;
  for (const RocPoint& p : points)
    if (p.fpr <= max_fpr) best = std::max(best, p.tpr);
  return best;
}

double Roc::ThresholdAtFpr(double max_fpr) const {
  const RocPoint* best = nullptr;
  for (const RocPoint& p : points)
    if (p.fpr <= max_fpr && (!best || p.tpr > best->tpr)) best = &p;
  return best ? best->threshold : std::numeric_limits<double>::infinity();
}

double Roc::FprAtTpr(double min_tpr) const {
  double best = 1.0;
  for (const RocPoint& p : points)
    if (p.tpr >= min_tpr) best = std::min(best, p.fpr);
  return best;
}

RocPoint OperatingPoint(const std::vector<double>& scores, const std::vector<bool>& positive,
                        double threshold) {
  if (scores.size() != positive.size())
    throw std::invalid_argument("OperatingPoint: scores and labels differ in size");
  long negatives = 0, false_alarms = 0, positives = 0, hits = 0;
  for (std::size_t k = 0; k < scores.size(); ++k) {
    const bool above = scores[k] > threshold;
    (positive[k] ? positives : negatives) += 1;
    (positive[k] ? hits : false_alarms) += above;
  }
  return {threshold, negatives ? double(false_alarms) / double(negatives) : 0.0,
          positives ? double(hits) / double(positives) : 0.0};
}

Roc ComputeRoc(const std::vector<double>& scores, const std::vector<bool>& positive) {
  if (scores.size() != positive.size())
    throw std::invalid_argument("ComputeRoc: " + std::to_string(scores.size()) + " scores, " +
                                std::to_string(positive.size()) + " labels");
  Roc roc;
  for (std::size_t i = 0; i < scores.size(); ++i) {
    if (std::isnan(scores[i]))
      throw std::invalid_argument("ComputeRoc: score " + std::to_string(i) + " is NaN");
    (positive[i] ? roc.positives : roc.negatives)++;
  }
  if (roc.positives == 0 || roc.negatives == 0)
    throw std::invalid_argument("ComputeRoc: " + std::to_string(roc.positives) + " positives and " +
                                std::to_string(roc.negatives) + " negatives; both are needed");
  std::vector<std::size_t> order(scores.size());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(),
            [&](std::size_t a, std::size_t b) { return scores[a] > scores[b]; });
  roc.points.push_back({std::numeric_limits<double>::infinity(), 0.0, 0.0});
  int tp = 0, fp = 0;
  for (std::size_t i = 0; i < order.size();) {
    const double t = scores[order[i]];
    for (; i < order.size() && scores[order[i]] == t; ++i) (positive[order[i]] ? tp : fp)++;
    const RocPoint p{t, double(fp) / roc.negatives, double(tp) / roc.positives};
    const RocPoint& q = roc.points.back();
    roc.auc += (p.fpr - q.fpr) * 0.5 * (p.tpr + q.tpr);
    roc.points.push_back(p);
  }
  return roc;
}

std::optional<double> FirstFprNotAbove(const Roc& a, const std::vector<const Roc*>& others,
                                       double max_fpr, int divisions) {
  const int steps = int(std::lround(max_fpr * divisions));
  for (int k = 1; k <= steps; ++k) {
    const double fpr = k / double(divisions);
    const double mine = a.TprAtFpr(fpr);
    for (const Roc* other : others) {
      const double theirs = other->TprAtFpr(fpr);
      if (!(mine > theirs || (mine == 1.0 && theirs == 1.0))) return fpr;
    }
  }
  return std::nullopt;
}

}  // namespace novelty::eval
