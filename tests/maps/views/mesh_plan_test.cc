#include "maps/views/mesh_plan.h"

#include <gtest/gtest.h>

#include <limits>
#include <stdexcept>

#include "maps/views/planar_blocks.h"

namespace novelty::views {
namespace {

// 41 × 33 pixels: 40 × 32 quads, blocks of 8 quads in a 5 × 4 grid.
constexpr int kCols = 41, kRows = 33, kBlock = 8;

int Skip(const MeshPlan& p, int u, int r) {
  return p.skip[std::size_t(r) * kCols + u];
}

TEST(MeshPlan, APlaneIsDrawnAsOneRunPerBlockRowWithNoQuadOnItsOwn) {
  const cv::Mat depth(kRows, kCols, CV_32FC1, cv::Scalar(2.0));
  const MeshPlan p = PlanMesh(depth, kBlock, 0.002);
  ASSERT_EQ(p.runs.size(), 4u);
  for (std::size_t k = 0; k < p.runs.size(); ++k)
    EXPECT_EQ(p.runs[k], cv::Rect(0, 8 * int(k), 40, 8)) << k;
  for (int r = 0; r + 1 < kRows; ++r)  // at the image's border no neighbour needs the quads
    for (int u = 0; u + 1 < kCols; ++u) ASSERT_EQ(Skip(p, u, r), -1) << u << "," << r;
  EXPECT_EQ(p.skip.size(), std::size_t(kCols * kRows) + MeshPlan::kPadding);
  // No quad starts in the last column or row, nor in the padding: never drawn.
  const MeshPlan none = PlanMesh(depth, 0, 0.002);
  for (int r = 0; r < kRows; ++r) EXPECT_EQ(Skip(none, kCols - 1, r), -1) << r;
  for (int u = 0; u < kCols; ++u) EXPECT_EQ(Skip(none, u, kRows - 1), -1) << u;
  EXPECT_EQ(none.skip.back(), -1);
  EXPECT_EQ(Skip(none, kCols - 2, kRows - 2), 0);
}

TEST(MeshPlan, AHoleLeavesItsQuadsOutAndItsBlockAndTheNeighboursEdgesQuadByQuad) {
  cv::Mat depth(kRows, kCols, CV_32FC1, cv::Scalar(2.0));
  depth.at<float>(12, 20) = 0.0f;  // in block (2, 1): quads 16…23 × 8…15
  const MeshPlan p = PlanMesh(depth, kBlock, 0.002);
  // The four quads around the hole are not drawn at all; the rest of its block quad by quad.
  for (int r : {11, 12})
    for (int u : {19, 20}) EXPECT_EQ(Skip(p, u, r), -1) << u << "," << r;
  EXPECT_EQ(Skip(p, 17, 10), 0);
  EXPECT_EQ(Skip(p, 23, 15), 0);
  // Neighbouring blocks draw their edge towards it too (no crack), not their inside.
  EXPECT_EQ(Skip(p, 15, 10), 0);  // left neighbour, right column
  EXPECT_EQ(Skip(p, 14, 10), -1);
  EXPECT_EQ(Skip(p, 24, 10), 0);  // right neighbour, left column
  EXPECT_EQ(Skip(p, 20, 7), 0);   // block above, bottom row
  EXPECT_EQ(Skip(p, 20, 6), -1);
  EXPECT_EQ(Skip(p, 20, 16), 0);  // block below, top row
  EXPECT_EQ(Skip(p, 15, 7), -1);  // a diagonal neighbour's corner quad needs no redraw
  // Block row 1 is two runs, around the hole's block.
  int row1 = 0;
  for (const cv::Rect& run : p.runs) row1 += run.y == 8;
  EXPECT_EQ(row1, 2);
}

TEST(MeshPlan, WithoutBlocksOnlyQuadsWithoutDepthAreLeftOut) {
  cv::Mat depth(kRows, kCols, CV_32FC1, cv::Scalar(2.0));
  depth.at<float>(12, 20) = std::numeric_limits<float>::quiet_NaN();
  depth.at<float>(32, 40) = -1.0f;  // the last pixel: one quad
  const MeshPlan p = PlanMesh(depth, 0, 0.002);
  EXPECT_TRUE(p.runs.empty());
  int left_out = 0;
  for (int r = 0; r + 1 < kRows; ++r)
    for (int u = 0; u + 1 < kCols; ++u) left_out += Skip(p, u, r) != 0;
  EXPECT_EQ(left_out, 4 + 1);
  EXPECT_EQ(Skip(p, 39, 31), -1);
}

TEST(MeshPlan, FitsOnlyTheSizeAndOptionsItWasMadeFor) {
  const cv::Mat depth(kRows, kCols, CV_32FC1, cv::Scalar(2.0));
  const MeshPlan p = PlanMesh(depth, kBlock, 0.002);
  EXPECT_TRUE(p.Fits(depth.size(), kBlock, 0.002));
  EXPECT_FALSE(p.Fits(depth.size(), 4, 0.002));
  EXPECT_FALSE(p.Fits(depth.size(), kBlock, 0.01));
  EXPECT_FALSE(p.Fits(cv::Size(kCols, kRows + 1), kBlock, 0.002));
  EXPECT_FALSE(MeshPlan().Fits(depth.size(), kBlock, 0.002));
  const MeshPlan none = PlanMesh(depth, 0, 0.002);
  EXPECT_TRUE(none.Fits(depth.size(), 0, 0.5));  // without blocks the tolerance does not matter
  EXPECT_THROW(PlanMesh(cv::Mat(4, 4, CV_64FC1, cv::Scalar(1)), kBlock, 0.002),
               std::invalid_argument);
}

}  // namespace
}  // namespace novelty::views
