#include "sensors/localization/visual_odometry.h"

#include <gtest/gtest.h>

#include "tests/sensors/localization/quarter_circle.h"

namespace novelty::sensors {
namespace {

// Phase I1 of the stereo scenario: frames 1–95, 90° of a 1.5 m circle, 2.3 m. The sensors
// issue's budget is < 1 % of the path; measured: final 1.5 % (35 mm), worst 2.0 % (46 mm,
// 1.8°); the error grows by 0.035° a frame already before any feature is replaced. The direct
// odometry meets the budget on the same frames (direct_odometry_test); this test holds what the
// feature-based one reaches so it cannot silently get worse. What it reaches depends on the
// machine, with the same code and packages: the numbers above on the AMD VMs, final 2.6 % and
// worst 2.7 % (63 mm, 2.58°) on an Intel Xeon VM with AVX-512 (2026-11-28; not OpenCV's SIMD
// dispatch nor Embree's ISA, both tried). The guard lies above both.
TEST(VisualOdometry, DriftOnAQuarterCircleStaysWithinThreePercentOfThePath) {
  QuarterCircle run;
  auto [first, first_truth] = run.Frame(0);
  VisualOdometry vo({}, first_truth);
  std::string why;
  ASSERT_TRUE(vo.Track(first, &why)) << why;
  double path = 0, worst = 0, worst_angle = 0;
  Eigen::Isometry3d previous = first_truth;
  for (int k = 1; k < 95; ++k) {
    auto [pair, truth] = run.Frame(k);
    const auto r = vo.Track(pair, &why);
    ASSERT_TRUE(r) << "frame " << k + 1 << ": " << why;
    EXPECT_FALSE(r->relocalized);
    path += (truth.translation() - previous.translation()).norm();
    previous = truth;
    worst = std::max(worst, (r->world_from_camera.translation() - truth.translation()).norm());
    worst_angle = std::max(worst_angle, AngleBetween(r->world_from_camera, truth));
    if (k == 94)
      std::printf(
          "path %.2f m: final error %.1f mm (%.2f %%), worst %.1f mm, worst angle %.2f°, "
          "%d inliers\n",
          path, 1000 * (r->world_from_camera.translation() - truth.translation()).norm(),
          100 * (r->world_from_camera.translation() - truth.translation()).norm() / path,
          1000 * worst, worst_angle * 180 / M_PI, r->inliers);
  }
  EXPECT_GT(path, 2.0);
  EXPECT_LT(worst, 0.03 * path);
  EXPECT_LT(worst_angle * 180 / M_PI, 3.0);
}

// After a blackout (tracking lost) the pose comes back from the keyframes.
TEST(VisualOdometry, RelocalizesAgainstKeyframesAfterTrackingIsLost) {
  QuarterCircle run;
  auto [first, first_truth] = run.Frame(0);
  VisualOdometry vo({}, first_truth);
  std::string why;
  ASSERT_TRUE(vo.Track(first, &why)) << why;
  for (int k = 1; k < 20; ++k) ASSERT_TRUE(vo.Track(run.Frame(k).first, &why)) << why;
  StereoPair dark = first;
  dark.reference = cv::Mat::zeros(first.reference.size(), first.reference.type());
  dark.other = dark.reference.clone();
  EXPECT_FALSE(vo.Track(dark, &why));
  EXPECT_NE(why.find("lost"), std::string::npos) << why;
  auto [pair, truth] = run.Frame(21);
  const auto r = vo.Track(pair, &why);
  ASSERT_TRUE(r) << why;
  EXPECT_TRUE(r->relocalized);
  EXPECT_LT((r->world_from_camera.translation() - truth.translation()).norm(), 0.03);
  EXPECT_LT(AngleBetween(r->world_from_camera, truth) * 180 / M_PI, 1.5);  // keyframes carry drift
  // and tracking goes on from there
  const auto next = vo.Track(run.Frame(22).first, &why);
  ASSERT_TRUE(next) << why;
  EXPECT_FALSE(next->relocalized);
}

}  // namespace
}  // namespace novelty::sensors
