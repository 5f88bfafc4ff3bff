#include "sensors/localization/epipolar_depth.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>

#include "tests/sensors/blurred_noise.h"

namespace novelty::sensors {
namespace {

// A rectified pair (the other camera `baseline` to the right) seeing a fronto-parallel textured
// plane at depth z: the other image is the reference shifted left by the disparity f·b/z.
StereoPair PlanePair(const cv::Mat& texture, double z, double baseline = 0.12) {
  StereoPair pair;
  pair.reference_camera = pair.other_camera = core::PinholeCamera::FromFov(320, 240, M_PI / 3);
  pair.reference_from_other.translation() = Eigen::Vector3d(baseline, 0, 0);
  const double disparity = pair.reference_camera.fx * baseline / z;
  const cv::Mat shift = (cv::Mat_<double>(2, 3) << 1, 0, disparity, 0, 1, 0);
  pair.reference = texture;
  cv::warpAffine(texture, pair.other, shift, texture.size(), cv::INTER_CUBIC | cv::WARP_INVERSE_MAP,
                 cv::BORDER_REFLECT);
  return pair;
}

cv::Mat Texture(int seed = 7) {
  return BlurredNoise({320, 240}, CV_32F, seed, 1.5, 20, 235);
}

TEST(EpipolarDepths, RecoverTheDepthOfATexturedPlaneToSubPixelDisparity) {
  const double z = 1.5;
  const StereoPair pair = PlanePair(Texture(), z);
  const double disparity = pair.reference_camera.fx * 0.12 / z;  // 22.2 px: not whole
  const auto points = EpipolarDepths(pair, pair.reference, pair.other);
  std::vector<double> errors;
  for (const EpipolarPoint& p : points)
    if (p.px.x > disparity + 4) errors.push_back(std::abs(p.depth / z - 1));  // match in view
  ASSERT_GT(errors.size(), 2000u);  // of 4600 blocks of 4×4
  std::sort(errors.begin(), errors.end());
  std::printf("%zu points: median %.4f, 95 %% %.4f\n", errors.size(), errors[errors.size() / 2],
              errors[errors.size() * 95 / 100]);
  EXPECT_LT(errors[errors.size() / 2], 0.003);        // median: 0.07 px of disparity
  EXPECT_LT(errors[errors.size() * 95 / 100], 0.01);  // 95 %
}

TEST(EpipolarDepths, SelectNoPixelWhoseGradientIsAcrossTheBaseline) {
  // Horizontal stripes: the gradient is vertical, along no horizontal epipolar line, so no
  // disparity can be measured and no pixel is selected.
  cv::Mat stripes(240, 320, CV_32F);
  for (int y = 0; y < stripes.rows; ++y) stripes.row(y).setTo(128 + 100 * std::sin(y * 0.7));
  const StereoPair pair = PlanePair(stripes, 1.5);
  EXPECT_TRUE(EpipolarDepths(pair, pair.reference, pair.other).empty());
}

TEST(EpipolarDepths, RejectAPlaneOutsideTheDepthRange) {
  const StereoPair pair = PlanePair(Texture(), 1.5);
  EpipolarDepthOptions o;
  o.range.min_depth = 2.0;  // the plane is nearer: its matches lie off the searched segment
  const auto points = EpipolarDepths(pair, pair.reference, pair.other, o);
  int in_range_wrong = 0;
  for (const EpipolarPoint& p : points) in_range_wrong += std::abs(p.depth / 1.5 - 1) < 0.02;
  EXPECT_EQ(in_range_wrong, 0);
  // Of 4600 blocks 221 find a chance match on this texture (5 %); the thresholds reject the rest.
  EXPECT_LT(points.size(), 460u);
}

// A textured box 1 m away in front of a textured wall 3 m away: near the box's edges the
// reference sees wall the other camera does not (occlusion). Returns the share of measured
// pixels whose depth is more than 5 % off.
double ShareOffAtOcclusions(const EpipolarDepthOptions& options) {
  StereoPair pair = PlanePair(Texture(1), 3.0);  // the wall in both images
  const double f = pair.reference_camera.fx, near = 1.0;
  const cv::Rect box(100, 60, 120, 120);  // in the reference image
  const cv::Mat front = Texture(2);
  front(box).copyTo(pair.reference(box));
  const int shift = int(std::lround(f * 0.12 / near));  // whole pixels: exact copy
  front(box).copyTo(pair.other(box - cv::Point(shift, 0)));
  const auto points = EpipolarDepths(pair, pair.reference, pair.other, options);
  int off = 0;
  for (const EpipolarPoint& p : points) {
    const double truth =
        box.contains(cv::Point(int(p.px.x + 0.5f), int(p.px.y + 0.5f))) ? f * 0.12 / shift : 3.0;
    off += std::abs(p.depth / truth - 1) > 0.05;
  }
  return double(off) / points.size();
}

TEST(EpipolarDepths, LeftRightCheckRejectsMatchesOfOccludedPixels) {
  EpipolarDepthOptions without;
  without.max_left_right_px = 0;
  const double before = ShareOffAtOcclusions(without), after = ShareOffAtOcclusions({});
  std::printf("more than 5 %% off: %.1f %% of pixels without the check, %.1f %% with\n",
              100 * before, 100 * after);
  EXPECT_LT(after, 0.5 * before);
  EXPECT_LT(after, 0.01);
}

}  // namespace
}  // namespace novelty::sensors
