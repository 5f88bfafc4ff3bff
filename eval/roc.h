// Receiver operating characteristic of a score (thesis 5.2, fig. 5.5 d): a decision "positive"
// when score ≥ t, swept over every distinct score, gives one (FPR, TPR) point per threshold
//   TPR = TP / (TP + FN)    (eq. 5.8)       FPR = FP / (FP + TN)    (eq. 5.9)
// from (0, 0) (no threshold passes) to (1, 1) (every decision positive). The area under the
// curve is the trapezoid sum, which equals the probability that a random positive scores above
// a random negative, ties counting one half (Mann–Whitney).
#pragma once

#include <optional>
#include <vector>

namespace novelty::eval {

struct RocPoint {
  double threshold;  ///< decisions with score ≥ threshold are positive (+inf: none)
  double fpr, tpr;
};

struct Roc {
  std::vector<RocPoint> points;  ///< FPR and TPR non-decreasing, first (0, 0), last (1, 1)
  int positives = 0, negatives = 0;
  double auc = 0.0;

  /// The highest TPR among the points with FPR ≤ max_fpr (0 if none reaches above 0).
  double TprAtFpr(double max_fpr) const;
  /// The threshold of the operating point TprAtFpr picks: the highest TPR among the points with
  /// FPR ≤ max_fpr, the highest threshold among ties (+inf if none with TPR > 0 qualifies).
  double ThresholdAtFpr(double max_fpr) const;
  /// The smallest FPR among the points with TPR ≥ min_tpr (1 if only the last point does).
  double FprAtTpr(double min_tpr) const;
};

/// Throws std::invalid_argument if the sizes differ, a score is NaN, or either class is empty.
Roc ComputeRoc(const std::vector<double>& scores, const std::vector<bool>& positive);

/// The operating point of deciding "positive" where score > `threshold` (a learnt threshold's
/// rates): fpr and tpr are 0 for a class without samples. Throws std::invalid_argument if the
/// sizes differ.
RocPoint OperatingPoint(const std::vector<double>& scores, const std::vector<bool>& positive,
                        double threshold);

/// Dominance up to an FPR (the thesis's "above the baselines at every FPR up to …"): the first
/// FPR of k / divisions, k = 1, 2, … up to max_fpr, at which `a`'s TprAtFpr is not above every
/// one of `others`' (equal at TPR 1 counts as above: nothing is left to find); none if `a` is
/// above at every one.
std::optional<double> FirstFprNotAbove(const Roc& a, const std::vector<const Roc*>& others,
                                       double max_fpr, int divisions = 1000);

}  // namespace novelty::eval
