#include "maps/views/view_blender.h"

#include <gtest/gtest.h>

#include <stdexcept>

namespace novelty::views {
namespace {

// A warp field that maps each virtual pixel of the left `covered` columns to itself at `depth`.
WarpField Field(int width, int height, int covered, float depth) {
  WarpField w;
  w.depth = cv::Mat(height, width, CV_32FC1, cv::Scalar(0));
  w.source_depth = cv::Mat(height, width, CV_32FC1, cv::Scalar(0));
  w.map = cv::Mat(height, width, CV_32FC2, cv::Scalar(-1, -1));
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < covered; ++x) {
      w.depth.at<float>(y, x) = w.source_depth.at<float>(y, x) = depth;
      w.map.at<cv::Vec2f>(y, x) = cv::Vec2f(float(x), float(y));
    }
  }
  w.covered = covered * height;
  return w;
}

TEST(ViewBlender, AveragesValidContributionsAndMarksUncoveredPixels) {
  const std::vector<WarpField> warps = {Field(8, 4, 6, 2.0f), Field(8, 4, 3, 2.0f)};
  const std::vector<cv::Mat> planes = {cv::Mat(4, 8, CV_8UC1, cv::Scalar(10)),
                                       cv::Mat(4, 8, CV_8UC1, cv::Scalar(30))};
  const BlendResult r = BlendPlanes(warps, planes);
  EXPECT_FLOAT_EQ(r.value.at<float>(1, 1), 20.0f);   // both views
  EXPECT_FLOAT_EQ(r.value.at<float>(1, 4), 10.0f);   // first view only
  EXPECT_TRUE(std::isnan(r.value.at<float>(1, 7)));  // nobody: invalid, not zero
  EXPECT_EQ(r.valid.at<uint8_t>(1, 7), 0);
  EXPECT_EQ(r.covered, 6 * 4);
}

TEST(ViewBlender, WeightsAndDepthToleranceChangeTheMix) {
  const std::vector<cv::Mat> planes = {cv::Mat(2, 4, CV_32FC1, cv::Scalar(10)),
                                       cv::Mat(2, 4, CV_32FC1, cv::Scalar(30))};
  BlendOptions weighted;
  weighted.weights = {3.0, 1.0};
  const std::vector<WarpField> same = {Field(4, 2, 4, 2.0f), Field(4, 2, 4, 2.0f)};
  EXPECT_FLOAT_EQ(BlendPlanes(same, planes, weighted).value.at<float>(0, 0), 15.0f);
  // The second view sees a surface 50 % behind the first's: with a tolerance it is left out.
  const std::vector<WarpField> occluded = {Field(4, 2, 4, 2.0f), Field(4, 2, 4, 3.0f)};
  BlendOptions tolerant;
  tolerant.depth_tolerance = 0.05;
  EXPECT_FLOAT_EQ(BlendPlanes(occluded, planes).value.at<float>(0, 0), 20.0f);
  EXPECT_FLOAT_EQ(BlendPlanes(occluded, planes, tolerant).value.at<float>(0, 0), 10.0f);
}

TEST(ViewBlender, MultiChannelPlanesKeepTheirChannels) {
  const std::vector<WarpField> warps = {Field(4, 2, 4, 1.0f)};
  const std::vector<cv::Mat> planes = {cv::Mat(2, 4, CV_8UC3, cv::Scalar(1, 2, 3))};
  const BlendResult r = BlendPlanes(warps, planes);
  ASSERT_EQ(r.value.type(), CV_32FC3);
  EXPECT_EQ(r.value.at<cv::Vec3f>(1, 2), cv::Vec3f(1, 2, 3));
}

TEST(ViewBlender, MismatchedInputIsRejected) {
  const std::vector<WarpField> warps = {Field(4, 2, 4, 1.0f)};
  EXPECT_THROW(BlendPlanes(warps, {}), std::invalid_argument);
  BlendOptions o;
  o.weights = {1.0, 2.0};
  EXPECT_THROW(BlendPlanes(warps, {cv::Mat(2, 4, CV_8UC1)}, o), std::invalid_argument);
}

}  // namespace
}  // namespace novelty::views
