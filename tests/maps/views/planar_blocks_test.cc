#include "maps/views/planar_blocks.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>

namespace novelty::views {
namespace {

// Depth of a tilted plane: inverse depth affine in the pixel coordinates (exactly planar).
cv::Mat TiltedPlane(int width, int height) {
  cv::Mat depth(height, width, CV_32FC1);
  for (int v = 0; v < height; ++v)
    for (int u = 0; u < width; ++u) depth.at<float>(v, u) = 1.0f / (0.4f + 0.001f * u + 0.0006f * v);
  return depth;
}

TEST(PlanarBlocks, EveryBlockOfATiltedPlaneIsPlanar) {
  const cv::Mat flags = FindPlanarBlocks(TiltedPlane(161, 121), 8, 0.002);
  ASSERT_EQ(flags.cols, 20);  // ⌊160 / 8⌋
  ASSERT_EQ(flags.rows, 15);
  EXPECT_EQ(cv::countNonZero(flags), 20 * 15);
  // One plane: each block row is one run.
  for (int by = 0; by < flags.rows; ++by) {
    for (int bx = 0; bx < 19; ++bx) EXPECT_EQ(flags.at<uchar>(by, bx), kPlanarRunContinues);
    EXPECT_EQ(flags.at<uchar>(by, 19), kPlanar);
  }
}

TEST(PlanarBlocks, RunsStopWhereThePlaneChanges) {
  // Two planes meeting in a crease at u = 80, a block boundary: every block is planar, and each
  // block row splits into two runs there.
  cv::Mat depth(121, 161, CV_32FC1);
  for (int v = 0; v < depth.rows; ++v)
    for (int u = 0; u < depth.cols; ++u)
      depth.at<float>(v, u) = 1.0f / (0.4f + 0.001f * float(std::min(u, 80)) +
                                      0.003f * float(std::max(u - 80, 0)) + 0.0006f * float(v));
  const cv::Mat flags = FindPlanarBlocks(depth, 8, 0.002);
  EXPECT_EQ(cv::countNonZero(flags), 20 * 15);
  for (int by = 0; by < flags.rows; ++by) {
    EXPECT_EQ(flags.at<uchar>(by, 0), kPlanarRunContinues);
    EXPECT_EQ(flags.at<uchar>(by, 9), kPlanar);
    EXPECT_EQ(flags.at<uchar>(by, 10), kPlanarRunContinues);
    EXPECT_EQ(flags.at<uchar>(by, 19), kPlanar);
  }
}

TEST(PlanarBlocks, TheLastColumnAndRowOfBlocksAreNarrower) {
  // 165 × 125 pixels: 164 = 20·8 + 4 quads across, 124 = 15·8 + 4 down; the last block column
  // and row are 4 quads wide and planar alike.
  EXPECT_EQ(PlanarGrid(165, 125, 8), cv::Size(21, 16));
  EXPECT_EQ(PlanarBlockRect(20, 15, 165, 125, 8), cv::Rect(160, 120, 4, 4));
  EXPECT_EQ(PlanarBlockRect(3, 15, 165, 125, 8), cv::Rect(24, 120, 8, 4));
  cv::Mat depth = TiltedPlane(165, 125);
  cv::Mat flags = FindPlanarBlocks(depth, 8, 0.002);
  ASSERT_EQ(flags.size(), cv::Size(21, 16));
  EXPECT_EQ(cv::countNonZero(flags), 21 * 16);
  depth.at<float>(122, 162) *= 1.01f;  // inside the corner block only
  flags = FindPlanarBlocks(depth, 8, 0.002);
  EXPECT_EQ(flags.at<uchar>(15, 20), 0);
  EXPECT_EQ(cv::countNonZero(flags), 21 * 16 - 1);
}

TEST(PlanarBlocks, ACurvedSurfaceHasNone) {
  // A bowl, curved alike everywhere: inverse depth 0.5 + k·r². At a block's centre it lies
  // 2·16·k off the affine function through the corners, ≥ 0.29 % of it for k = 5e-4.
  cv::Mat depth(121, 161, CV_32FC1);
  for (int v = 0; v < depth.rows; ++v)
    for (int u = 0; u < depth.cols; ++u)
      depth.at<float>(v, u) = 1.0f / (0.5f + 5e-4f * float((u - 80) * (u - 80) + (v - 60) * (v - 60)));
  EXPECT_EQ(cv::countNonZero(FindPlanarBlocks(depth, 8, 0.002)), 0);
}

TEST(PlanarBlocks, BlocksAcrossAStepOrWithoutDepthAreNot) {
  cv::Mat depth = TiltedPlane(161, 121);
  depth(cv::Rect(44, 0, 161 - 44, 121)) *= 1.5f;  // a step inside block column 5 (pixels 40–48)
  depth.at<float>(100, 10) = std::numeric_limits<float>::quiet_NaN();  // block (1, 12)
  depth.at<float>(20, 130) = 0.0f;                                      // block (16, 2)
  const cv::Mat flags = FindPlanarBlocks(depth, 8, 0.002);
  for (int by = 0; by < flags.rows; ++by) {
    EXPECT_EQ(flags.at<uchar>(by, 5), kNotPlanar) << by;  // crosses the step
    // Left of it (its right column at u = 40) a run ends; right of it, on the scaled plane
    // (still one), another begins.
    EXPECT_EQ(flags.at<uchar>(by, 4), kPlanar) << by;
    EXPECT_EQ(flags.at<uchar>(by, 6), kPlanarRunContinues) << by;
  }
  EXPECT_EQ(flags.at<uchar>(12, 1), kNotPlanar);
  EXPECT_EQ(flags.at<uchar>(12, 0), kPlanar);  // a run of one before the hole
  EXPECT_EQ(flags.at<uchar>(2, 16), kNotPlanar);
  EXPECT_EQ(cv::countNonZero(flags), 20 * 15 - 15 - 2);
}

TEST(PlanarBlocks, TheToleranceIsARelativeDepthError) {
  cv::Mat depth = TiltedPlane(9, 9);
  depth.at<float>(4, 4) *= 1.0015f;  // the centre 0.15 % off the plane
  EXPECT_EQ(cv::countNonZero(FindPlanarBlocks(depth, 8, 0.002)), 1);
  EXPECT_EQ(cv::countNonZero(FindPlanarBlocks(depth, 8, 0.001)), 0);
}

TEST(PlanarBlocks, BadInputIsRejected) {
  EXPECT_THROW(FindPlanarBlocks(cv::Mat(9, 9, CV_8UC1), 8, 0.002), std::invalid_argument);
  EXPECT_THROW(FindPlanarBlocks(TiltedPlane(9, 9), 0, 0.002), std::invalid_argument);
  // Smaller than a block: one block of what there is; a single pixel or row: no quad, no block.
  EXPECT_EQ(cv::countNonZero(FindPlanarBlocks(TiltedPlane(5, 5), 8, 0.002)), 1);
  EXPECT_EQ(FindPlanarBlocks(TiltedPlane(5, 1), 8, 0.002).total(), 0u);
}

}  // namespace
}  // namespace novelty::views
