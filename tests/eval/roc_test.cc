#include "eval/roc.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <utility>

#include <opencv2/core.hpp>

namespace novelty::eval {
namespace {

// `n` decisions, a third of them positive, with integer scores in [0, range) and positives
// shifted up by `shift`: many ties.
std::pair<std::vector<double>, std::vector<bool>> RandomIntegerDecisions(std::uint64_t seed, int n,
                                                                         int range, int shift) {
  cv::RNG rng(seed);
  std::vector<double> scores;
  std::vector<bool> labels;
  for (int i = 0; i < n; ++i) {
    const bool p = rng.uniform(0, 3) == 0;
    labels.push_back(p);
    scores.push_back(double(rng.uniform(0, range) + (p ? shift : 0)));
  }
  return {scores, labels};
}

TEST(Roc, KnownSmallCase) {
  // Scores 4 3 3 2 1 with labels + + - + -: thresholds 4, 3, 2, 1.
  const Roc roc = ComputeRoc({4, 3, 3, 2, 1}, {true, true, false, true, false});
  ASSERT_EQ(roc.points.size(), 5u);
  EXPECT_EQ(roc.positives, 3);
  EXPECT_EQ(roc.negatives, 2);
  const double fpr[] = {0, 0, 0.5, 0.5, 1}, tpr[] = {0, 1.0 / 3, 2.0 / 3, 1, 1};
  for (int i = 0; i < 5; ++i) {
    EXPECT_DOUBLE_EQ(roc.points[std::size_t(i)].fpr, fpr[i]) << i;
    EXPECT_DOUBLE_EQ(roc.points[std::size_t(i)].tpr, tpr[i]) << i;
  }
  // Positives 4 3 2 against negatives 3 1: 4>3, 4>1, 3=3 (half), 3>1, 2<3, 2>1 → 4.5 of 6.
  EXPECT_DOUBLE_EQ(roc.auc, 4.5 / 6.0);
  EXPECT_DOUBLE_EQ(roc.TprAtFpr(0.0), 1.0 / 3);
  EXPECT_DOUBLE_EQ(roc.TprAtFpr(0.5), 1.0);
  EXPECT_DOUBLE_EQ(roc.FprAtTpr(0.9), 0.5);
  // Thresholds 4, 3, 2, 1 give (0, 1/3), (0.5, 2/3), (0.5, 1), (1, 1): at FPR ≤ 0 the point of
  // threshold 4; at ≤ 0.5 and ≤ 1 TPR 1 first at threshold 2 (1 ties it at FPR 1).
  EXPECT_DOUBLE_EQ(roc.ThresholdAtFpr(0.0), 4.0);
  EXPECT_DOUBLE_EQ(roc.ThresholdAtFpr(0.4), 4.0);
  EXPECT_DOUBLE_EQ(roc.ThresholdAtFpr(0.5), 2.0);
  EXPECT_DOUBLE_EQ(roc.ThresholdAtFpr(1.0), 2.0);
}

// Deciding by score ≥ ThresholdAtFpr(f), recounted here decision by decision, gives TprAtFpr(f)
// at an FPR within f, on random integer scores (many ties).
TEST(Roc, ThresholdAtFprReproducesTprAtFpr) {
  const auto [scores, labels] = RandomIntegerDecisions(17, 600, 20, 5);
  const Roc roc = ComputeRoc(scores, labels);
  for (double f : {0.0, 0.003, 0.01, 0.05, 0.2, 1.0}) {
    const double t = roc.ThresholdAtFpr(f);
    int tp = 0, fp = 0;
    for (std::size_t i = 0; i < scores.size(); ++i)
      if (scores[i] >= t) (labels[i] ? tp : fp) += 1;
    EXPECT_DOUBLE_EQ(double(tp) / roc.positives, roc.TprAtFpr(f)) << f;
    EXPECT_LE(double(fp) / roc.negatives, f) << f;
  }
}

TEST(Roc, NoOperatingPointAboveZeroHasAnInfiniteThreshold) {
  // The negative scores highest: at FPR 0 only (0, 0), which no finite threshold gives.
  const Roc roc = ComputeRoc({5, 1}, {false, true});
  EXPECT_DOUBLE_EQ(roc.TprAtFpr(0.0), 0.0);
  EXPECT_TRUE(std::isinf(roc.ThresholdAtFpr(0.0)));
}

// The area equals the Mann–Whitney probability counted pair by pair, on random integer scores
// (many ties).
TEST(Roc, AreaIsTheMannWhitneyProbability) {
  const auto [scores, labels] = RandomIntegerDecisions(3, 400, 12, 4);
  double wins = 0.0, pairs = 0.0;
  for (std::size_t i = 0; i < scores.size(); ++i)
    for (std::size_t j = 0; j < scores.size(); ++j)
      if (labels[i] && !labels[j]) {
        pairs += 1.0;
        wins += scores[i] > scores[j] ? 1.0 : scores[i] == scores[j] ? 0.5 : 0.0;
      }
  EXPECT_NEAR(ComputeRoc(scores, labels).auc, wins / pairs, 1e-12);
}

TEST(Roc, PerfectAndBadInputs) {
  const Roc perfect = ComputeRoc({5, 6, 1, 0}, {true, true, false, false});
  EXPECT_DOUBLE_EQ(perfect.auc, 1.0);
  EXPECT_DOUBLE_EQ(perfect.TprAtFpr(0.0), 1.0);
  EXPECT_THROW(ComputeRoc({1, 2}, {true}), std::invalid_argument);
  EXPECT_THROW(ComputeRoc({1, 2}, {true, true}), std::invalid_argument);
  EXPECT_THROW(ComputeRoc({1, std::nan("")}, {true, false}), std::invalid_argument);
}

Roc FromPoints(std::vector<RocPoint> points) {
  Roc r;
  r.points = std::move(points);
  return r;
}

// a: TPR 0.5 from FPR 0, 0.9 from 2 %; b: 0.4 from 0.1 %, 0.95 from 1 %. a is above on 0.1 %
// to 0.9 %, and at FPR 0.1 % steps first not above at 1.0 %.
TEST(FirstFprNotAbove, TheFirstGridFprWhereAnotherCurveCatchesUp) {
  const Roc a = FromPoints({{INFINITY, 0, 0}, {3, 0, 0.5}, {2, 0.02, 0.9}, {1, 1, 1}});
  const Roc b = FromPoints({{INFINITY, 0, 0}, {3, 0.001, 0.4}, {2, 0.01, 0.95}, {1, 1, 1}});
  const Roc low = FromPoints({{INFINITY, 0, 0}, {1, 1, 1}});
  ASSERT_TRUE(FirstFprNotAbove(a, {&b}, 0.1).has_value());
  EXPECT_DOUBLE_EQ(*FirstFprNotAbove(a, {&b}, 0.1), 0.01);
  EXPECT_FALSE(FirstFprNotAbove(a, {&b}, 0.005).has_value());
  EXPECT_FALSE(FirstFprNotAbove(a, {&low}, 0.1).has_value());
  EXPECT_DOUBLE_EQ(*FirstFprNotAbove(a, {&low, &b}, 0.1), 0.01) << "above every one of them";
  EXPECT_DOUBLE_EQ(*FirstFprNotAbove(b, {&a}, 0.1), 0.001) << "equal is not above";
  // Both at TPR 1: nothing is left to find, which counts as above.
  const Roc perfect = FromPoints({{INFINITY, 0, 0}, {1, 0, 1}, {0, 1, 1}});
  EXPECT_FALSE(FirstFprNotAbove(perfect, {&perfect}, 0.1).has_value());
}

// Deciding score > 2: of the negatives {1, 2, 3} one is above (2 is not), of the positives
// {2.5, 4} both.
TEST(OperatingPoint, CountsStrictlyAboveTheThreshold) {
  const RocPoint p =
      OperatingPoint({1.0, 2.0, 3.0, 2.5, 4.0}, {false, false, false, true, true}, 2.0);
  EXPECT_DOUBLE_EQ(p.fpr, 1.0 / 3.0);
  EXPECT_DOUBLE_EQ(p.tpr, 1.0);
  EXPECT_EQ(OperatingPoint({1.0}, {false}, 0.0).tpr, 0.0);  // no positives: 0
  EXPECT_THROW(OperatingPoint({1.0}, {}, 0.0), std::invalid_argument);
}

}  // namespace
}  // namespace novelty::eval
