#include "sensors/stereo/plane_sweep.h"

#include <gtest/gtest.h>

#include <opencv2/imgproc.hpp>
#include <random>

#include "tests/sensors/blurred_noise.h"

namespace novelty::sensors {
namespace {

cv::Mat Texture(int w, int h, std::uint64_t seed) {
  return BlurredNoise(cv::Size(w, h), CV_8UC3, seed, 1.2, 0, 255);
}

TEST(PlaneSweep, LabelsAreEvenInInverseDepth) {
  PlaneSweepOptions o;
  EXPECT_NEAR(DepthOfLabel(o, 0), o.near, 1e-12);
  EXPECT_NEAR(DepthOfLabel(o, o.hypotheses - 1), o.far, 1e-12);
  const double mid = DepthOfLabel(o, (o.hypotheses - 1) / 2.0);
  EXPECT_NEAR(1 / mid, (1 / o.near + 1 / o.far) / 2, 1e-12);
}

// A fronto-parallel textured plane at the depth of label 20, seen by a camera 12 cm to the right:
// its image is the reference shifted by f·B/Z. Interior pixels' costs are lowest at label 20 — or
// a neighbour: labels are 0.47 px apart here, finer than bilinear resampling can separate.
TEST(PlaneSweep, CostIsLowestAtTheTruePlane) {
  const core::PinholeCamera camera = core::PinholeCamera::FromFov(160, 120, M_PI / 3);
  PlaneSweepOptions o;
  const double depth = DepthOfLabel(o, 20);
  const cv::Mat ref = Texture(camera.width, camera.height, 3);
  Eigen::Isometry3d right = Eigen::Isometry3d::Identity();
  right.translation().x() = 0.12;
  const double shift = camera.fx * 0.12 / depth;  // u_right = u_ref − shift
  cv::Mat side;
  const cv::Mat m = (cv::Mat_<double>(2, 3) << 1, 0, -shift, 0, 1, 0);
  cv::warpAffine(ref, side, m, ref.size(), cv::INTER_LINEAR, cv::BORDER_REFLECT);
  const CostVolume v = PlaneSweep(ref, camera, {{side, camera, right}}, o);
  int near = 0, scored = 0;
  double sum = 0;
  for (int y = 5; y < v.height - 5; ++y)
    for (int x = 5 + int(shift); x < v.width - 5; ++x, ++scored) {  // match at u − shift
      int best = 0;
      for (int l = 1; l < v.labels; ++l) best = v(x, y, l) < v(x, y, best) ? l : best;
      near += std::abs(best - 20) <= 1;
      sum += best;
    }
  EXPECT_GT(double(near) / scored, 0.99);
  EXPECT_GT(scored, 10000);
  EXPECT_NEAR(sum / scored, 20.0, 0.1);
  // Pixels whose match lies outside the side image cost the truncation.
  EXPECT_FLOAT_EQ(v(2, 60, 20), o.truncation);
}

TEST(PlaneSweep, RefusesRigsWithImagesOfDifferentSizes) {
  const core::PinholeCamera camera = core::PinholeCamera::FromFov(160, 120, M_PI / 3);
  const cv::Mat ref = Texture(160, 120, 4), small = Texture(80, 60, 5);
  try {
    PlaneSweep(ref, camera, {{small, camera, Eigen::Isometry3d::Identity()}}, {});
    FAIL() << "no exception";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("view 1"), std::string::npos) << e.what();
  }
  EXPECT_THROW(PlaneSweep(ref, camera, {}, {}), std::invalid_argument);
}

// The reliability issue's reproducers: 100 000 hypotheses died of bad_alloc, a 1282×1110 pair
// took 7.5 GB. Both are refused before anything is allocated, saying why.
TEST(PlaneSweep, RefusesVolumesARobotCannotHold) {
  const core::PinholeCamera small = core::PinholeCamera::FromFov(32, 24, M_PI / 3);
  const cv::Mat a = Texture(32, 24, 4);
  PlaneSweepOptions many;
  many.hypotheses = 100000;
  EXPECT_THROW(PlaneSweep(a, small, {{a, small, Eigen::Isometry3d::Identity()}}, many),
               std::invalid_argument);
  const core::PinholeCamera big = core::PinholeCamera::FromFov(1282, 1110, M_PI / 3);
  const cv::Mat b(1110, 1282, CV_8UC3, cv::Scalar::all(0));
  try {
    PlaneSweep(b, big, {{b, big, Eigen::Isometry3d::Identity()}}, {});
    FAIL() << "no exception";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("MB"), std::string::npos) << e.what();
  }
  PlaneSweepOptions window;
  window.window = 0;
  EXPECT_THROW(PlaneSweep(a, small, {{a, small, Eigen::Isometry3d::Identity()}}, window),
               std::invalid_argument);
}

}  // namespace
}  // namespace novelty::sensors
