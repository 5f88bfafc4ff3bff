#include "core/interleave.h"

#include <gtest/gtest.h>

#include <stdexcept>
#include <vector>

namespace novelty::core {
namespace {

// Every depth and channel count the map uses (and more), rows that end inside a sixteen-pixel
// group, a view into a larger image: the planes equal cv::split of the float image, and merging
// them back equals convertTo of that image (half floats rounded alike).
TEST(Interleave, SplitAndMergeEqualOpenCVs) {
  cv::RNG rng(3);
  for (const int depth : {CV_8U, CV_16F, CV_32F}) {
    for (const int channels : {1, 3, 7, 10}) {
      cv::Mat larger(9, 45, CV_32FC(channels));
      rng.fill(larger, cv::RNG::UNIFORM, 0.0, 255.0);
      cv::Mat typed;
      larger.convertTo(typed, depth);
      const cv::Mat rows = typed(cv::Rect(3, 2, 37, 6));  // not continuous
      std::vector<cv::Mat> planes, expected;
      SplitToFloat(rows, planes);
      cv::Mat as_float;
      rows.convertTo(as_float, CV_32F);
      cv::split(as_float, expected);
      ASSERT_EQ(planes.size(), std::size_t(channels));
      for (int c = 0; c < channels; ++c) {
        ASSERT_EQ(cv::norm(planes[std::size_t(c)], expected[std::size_t(c)], cv::NORM_INF), 0.0)
            << "depth " << depth << ", " << channels << " channels, channel " << c;
      }
      if (depth == CV_8U) continue;  // merging writes half or float only
      cv::Mat merged_larger(typed.size(), typed.type(), cv::Scalar::all(0));
      cv::Mat merged = merged_larger(cv::Rect(3, 2, 37, 6));
      MergeInto(planes, merged);
      EXPECT_EQ(cv::norm(merged, rows, cv::NORM_INF), 0.0) << depth << ", " << channels;
      EXPECT_EQ(cv::norm(merged_larger.col(0), cv::NORM_INF), 0.0);  // outside: untouched
    }
  }
}

TEST(Interleave, HalfRoundingEqualsConvertTo) {
  cv::Mat values(1, 40, CV_32FC3);
  cv::RNG(4).fill(values, cv::RNG::UNIFORM, -1000.0, 1000.0);
  std::vector<cv::Mat> planes;
  cv::split(values, planes);
  cv::Mat ours(values.size(), CV_16FC3), opencv;
  MergeInto(planes, ours);
  values.convertTo(opencv, CV_16F);
  EXPECT_EQ(cv::norm(ours, opencv, cv::NORM_INF), 0.0);
}

TEST(Interleave, BadInputIsRejected) {
  std::vector<cv::Mat> planes;
  EXPECT_THROW(SplitToFloat(cv::Mat(2, 2, CV_64FC3), planes), std::invalid_argument);
  planes = {cv::Mat(2, 2, CV_32FC1), cv::Mat(2, 2, CV_32FC1)};
  cv::Mat three(2, 2, CV_32FC3), bytes(2, 2, CV_8UC2);
  EXPECT_THROW(MergeInto(planes, three), std::invalid_argument);
  EXPECT_THROW(MergeInto(planes, bytes), std::invalid_argument);
  const std::vector<cv::Mat> many(40, cv::Mat(2, 2, CV_32FC1, cv::Scalar(1)));
  cv::Mat forty(2, 2, CV_32FC(40));
  EXPECT_THROW(MergeInto(many, forty), std::invalid_argument);  // more channels than it handles
}

}  // namespace
}  // namespace novelty::core
