#include "eval/roc_plot.h"

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <opencv2/core.hpp>
#include <stdexcept>

namespace novelty::eval {
namespace {

// Scores 4 3 3 2 1, labels + + - + -: points (FPR, TPR) (0,0) (0,1/3) (0.5,2/3) (0.5,1) (1,1).
Roc SmallRoc() {
  return ComputeRoc({4, 3, 3, 2, 1}, {true, true, false, true, false});
}

TEST(RocPlotSeries, KeepsTheHighestPointOfEachFprInPercent) {
  const PlotSeries s = RocPlotSeries(SmallRoc(), "surprise", "#123456");
  EXPECT_EQ(s.name, "surprise");
  EXPECT_EQ(s.color, "#123456");
  // (50, 66.7) shares its FPR with (50, 100) and is dropped: the step keeps its height.
  const std::vector<std::pair<double, double>> expected = {
      {0, 0}, {0, 100.0 / 3}, {50, 100}, {100, 100}};
  ASSERT_EQ(s.points.size(), expected.size());
  for (std::size_t i = 0; i < expected.size(); ++i) {
    EXPECT_DOUBLE_EQ(s.points[i].first, expected[i].first) << i;
    EXPECT_DOUBLE_EQ(s.points[i].second, expected[i].second) << i;
  }
}

TEST(RocPlotSeries, AZoomEndsAtItsLimitOnTheInterpolatedCurve) {
  // Between (0, 1/3) and (0.5, 2/3), FPR 0.25 lies halfway: TPR 1/2.
  const PlotSeries s = RocPlotSeries(SmallRoc(), "s", "#000", {0.25, 400});
  ASSERT_EQ(s.points.size(), 3u);
  EXPECT_DOUBLE_EQ(s.points.back().first, 25.0);
  EXPECT_DOUBLE_EQ(s.points.back().second, 50.0);
  for (const auto& p : s.points) EXPECT_LE(p.first, 25.0);
}

// A large ROC binned coarsely: one point per occupied bin (and the first), each bin's point the
// highest TPR any ROC point in that bin reaches, computed here independently.
TEST(RocPlotSeries, BinsKeepTheirHighestTpr) {
  cv::RNG rng(11);
  std::vector<double> scores;
  std::vector<bool> labels;
  for (int i = 0; i < 3000; ++i) {
    const bool p = rng.uniform(0, 2) == 0;
    labels.push_back(p);
    scores.push_back(rng.gaussian(1.0) + (p ? 1.0 : 0.0));
  }
  const Roc roc = ComputeRoc(scores, labels);
  const int bins = 10;
  const PlotSeries s = RocPlotSeries(roc, "s", "#000", {1.0, bins});
  std::map<int, double> highest;
  for (const RocPoint& p : roc.points) {
    const int b = int(std::floor(p.fpr / (1.0 / bins)));  // the width RocPlotSeries uses
    highest[b] = std::max(highest.count(b) ? highest[b] : 0.0, 100 * p.tpr);
  }
  ASSERT_EQ(s.points.size(), highest.size() + 1);  // + the first point (0, 0)
  std::size_t i = 1;
  for (const auto& [b, tpr] : highest) {
    EXPECT_EQ(int(std::floor(s.points[i].first / 100 / (1.0 / bins))), b);
    EXPECT_DOUBLE_EQ(s.points[i].second, tpr) << "bin " << b;
    ++i;
  }
}

TEST(RocPlotSeries, RefusesBadOptions) {
  EXPECT_THROW(RocPlotSeries(SmallRoc(), "s", "#000", {0.0, 400}), std::invalid_argument);
  EXPECT_THROW(RocPlotSeries(SmallRoc(), "s", "#000", {1.5, 400}), std::invalid_argument);
  EXPECT_THROW(RocPlotSeries(SmallRoc(), "s", "#000", {0.05, 0}), std::invalid_argument);
}

}  // namespace
}  // namespace novelty::eval
