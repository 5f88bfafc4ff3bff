#include "eval/attentional_selectivity.h"

#include <gtest/gtest.h>

#include <cmath>

namespace novelty::eval {
namespace {

TEST(AttentionalSelectivity, KnownAnswer) {
  // 64×64 map of 1s; a 16×16 region (4×4 blocks) with values 4 and one block of 8 in it.
  cv::Mat map(64, 64, CV_32FC1, cv::Scalar(1.0f));
  cv::Mat region(64, 64, CV_8UC1, cv::Scalar(0));
  region(cv::Rect(24, 24, 16, 16)).setTo(255);
  map(cv::Rect(24, 24, 16, 16)).setTo(4.0f);
  map(cv::Rect(24, 24, 4, 4)).setTo(8.0f);
  const Selectivity s = AttentionalSelectivity(map, region);
  EXPECT_EQ(s.region_blocks, 16);
  EXPECT_EQ(s.outside_blocks, 12 * 12 - 16);  // 16×16 blocks minus 2 border rings
  EXPECT_NEAR(s.as_db, 10 * std::log10((15 * 4.0 + 8.0) / 16 / 1.0), 1e-9);
  EXPECT_NEAR(s.pas_db, 10 * std::log10(8.0), 1e-9);
}

TEST(AttentionalSelectivity, BorderBlocksAndNaNsAreLeftOut) {
  cv::Mat map(64, 64, CV_32FC1, cv::Scalar(1.0f));
  cv::Mat region(64, 64, CV_8UC1, cv::Scalar(0));
  region(cv::Rect(24, 24, 8, 8)).setTo(255);
  map(cv::Rect(24, 24, 8, 8)).setTo(2.0f);
  map(cv::Rect(0, 0, 8, 64)).setTo(100.0f);  // hot border: excluded
  map(cv::Rect(40, 40, 4, 4)).setTo(std::nanf(""));
  const Selectivity s = AttentionalSelectivity(map, region);
  EXPECT_NEAR(s.as_db, 10 * std::log10(2.0), 1e-9);
  EXPECT_EQ(s.outside_blocks, 12 * 12 - 4 - 1);                // the all-NaN block counts nowhere
  EXPECT_NEAR(s.coverage, 1.0 - 16.0 / (48.0 * 48.0), 1e-12);  // reported beside AS
  // Without the border rule the hot border dominates: AS < 0 dB.
  SelectivityOptions no_border;
  no_border.border_blocks = 0;
  EXPECT_LT(AttentionalSelectivity(map, region, no_border).as_db, 0.0);
}

// A 10×10 object of surprise 4 on a background of 1: the true ratio is 4 (6.02 dB) wherever the
// object falls in the 4×4 block grid. Blocks the object's edge cuts are neither region nor
// outside (counted as outside they set Ŝ_out; counted as region they dilute S̄).
TEST(AttentionalSelectivity, DoesNotDependOnTheObjectsOffsetInTheBlockGrid) {
  const double truth = 10 * std::log10(4.0);
  for (int dy = 0; dy < 4; ++dy) {
    for (int dx = 0; dx < 4; ++dx) {
      cv::Mat map(64, 64, CV_32FC1, cv::Scalar(1.0f));
      cv::Mat region(64, 64, CV_8UC1, cv::Scalar(0));
      const cv::Rect object(24 + dx, 24 + dy, 10, 10);
      region(object).setTo(255);
      map(object).setTo(4.0f);
      const Selectivity s = AttentionalSelectivity(map, region);
      EXPECT_NEAR(s.as_db, truth, 0.1) << "offset " << dx << "," << dy;
      EXPECT_NEAR(s.pas_db, truth, 0.1) << "offset " << dx << "," << dy;
      EXPECT_GE(s.region_blocks, 1);
      EXPECT_GT(s.border_blocks, 0);
    }
  }
}

// A region thinner than a block has no whole block: its blocks at least half in the mask stand
// for it (a 2-pixel line of 4 over 1 gives blocks of mean 2.5, i.e. 3.98 dB, aligned so).
TEST(AttentionalSelectivity, RegionThinnerThanABlockUsesItsHalfCoveredBlocks) {
  cv::Mat map(64, 64, CV_32FC1, cv::Scalar(1.0f));
  cv::Mat region(64, 64, CV_8UC1, cv::Scalar(0));
  region(cv::Rect(24, 24, 16, 2)).setTo(255);
  map(cv::Rect(24, 24, 16, 2)).setTo(4.0f);
  const Selectivity s = AttentionalSelectivity(map, region);
  EXPECT_EQ(s.region_blocks, 4);
  EXPECT_NEAR(s.as_db, 10 * std::log10(2.5), 1e-9);
}

TEST(AttentionalSelectivity, EmptyRegionGivesNaN) {
  const cv::Mat map(32, 32, CV_32FC1, cv::Scalar(1.0f));
  const Selectivity s = AttentionalSelectivity(map, cv::Mat::zeros(32, 32, CV_8UC1));
  EXPECT_TRUE(std::isnan(s.as_db));
  EXPECT_THROW(AttentionalSelectivity(map, cv::Mat::zeros(31, 32, CV_8UC1)), std::invalid_argument);
}

}  // namespace
}  // namespace novelty::eval
