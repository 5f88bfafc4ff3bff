#include "sensors/localization/direct_odometry.h"

#include <gtest/gtest.h>

#include <opencv2/imgproc.hpp>
#include <utility>
#include <vector>

#include "tests/sensors/localization/quarter_circle.h"

namespace novelty::sensors {
namespace {

// Phase I1 of the stereo scenario: frames 1–95, 90° of a 1.5 m circle, 2.3 m of path. The
// sensors issue's budget is < 1 % of the path length; measured: worst 0.31 % (7 mm), worst
// angle 0.24°, against 2.0 % / 1.8° for the feature-based odometry on the same frames. Over all
// nine quarter circles I1–I9 (measured outside the tests): mean 0.54 %, worst 0.83 %.
TEST(DirectOdometry, DriftOnAQuarterCircleStaysBelowOnePercentOfThePath) {
  QuarterCircle run;
  auto [first, first_truth] = run.Frame(0);
  DirectOdometry vo({}, first_truth);
  std::string why;
  ASSERT_TRUE(vo.Track(first, &why)) << why;
  double path = 0, worst = 0, worst_angle = 0;
  int keyframes = 1;
  Eigen::Isometry3d previous = first_truth;
  for (int k = 1; k < 95; ++k) {
    auto [pair, truth] = run.Frame(k);
    const auto r = vo.Track(pair, &why);
    ASSERT_TRUE(r) << "frame " << k + 1 << ": " << why;
    EXPECT_FALSE(r->relocalized);
    keyframes += r->new_keyframe;
    path += (truth.translation() - previous.translation()).norm();
    previous = truth;
    worst = std::max(worst, (r->world_from_camera.translation() - truth.translation()).norm());
    worst_angle = std::max(worst_angle, AngleBetween(r->world_from_camera, truth));
  }
  std::printf("path %.2f m: worst error %.1f mm (%.2f %%), worst angle %.2f°, %d keyframes\n",
              path, 1000 * worst, 100 * worst / path, worst_angle * 180 / M_PI, keyframes);
  EXPECT_GT(path, 2.0);
  EXPECT_LT(worst, 0.01 * path);
  EXPECT_LT(worst_angle * 180 / M_PI, 0.5);
  EXPECT_GT(keyframes, 5);  // drift is measured across keyframe hand-overs, not within one
}

// The lamps move between frames 200 and 201 (scenario event at 49.81 s): the shading of the
// whole scene changes while the camera drives on. Alignment after local contrast normalization
// keeps tracking (measured: worst 5.5 mm over 0.47 m); with raw grey levels it is lost there.
TEST(DirectOdometry, KeepsTrackingThroughAChangeOfLighting) {
  QuarterCircle run;
  std::vector<std::pair<StereoPair, Eigen::Isometry3d>> frames;
  for (int k = 190; k < 215; ++k) frames.push_back(run.Frame(k));
  auto track = [&](const DirectOdometryOptions& options, double* worst) {
    DirectOdometry vo(options, frames[0].second);
    int relocalized = 0;
    *worst = 0;
    for (const auto& [pair, truth] : frames) {
      std::string why;
      const auto r = vo.Track(pair, &why);
      if (!r) return -1;
      relocalized += r->relocalized;
      *worst = std::max(*worst, (r->world_from_camera.translation() - truth.translation()).norm());
    }
    return relocalized;
  };
  double worst = 0, worst_raw = 0;
  EXPECT_EQ(track({}, &worst), 0);
  EXPECT_LT(worst, 0.01);  // m
  DirectOdometryOptions raw;
  raw.normalization.window = 0;
  EXPECT_NE(track(raw, &worst_raw), 0);  // lost: failed or re-localized
  std::printf("across the lamp move: worst error %.1f mm normalized, %.1f mm raw\n", 1000 * worst,
              1000 * worst_raw);
}

// After a blackout (tracking lost) the pose comes back from the keyframes, and tracking goes on.
TEST(DirectOdometry, RelocalizesAfterTrackingIsLost) {
  QuarterCircle run;
  auto [first, first_truth] = run.Frame(0);
  DirectOdometry vo({}, first_truth);
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
  EXPECT_LT(AngleBetween(r->world_from_camera, truth) * 180 / M_PI, 1.0);
  auto [next_pair, next_truth] = run.Frame(22);
  const auto next = vo.Track(next_pair, &why);
  ASSERT_TRUE(next) << why;
  EXPECT_FALSE(next->relocalized);
  EXPECT_LT((next->world_from_camera.translation() - next_truth.translation()).norm(), 0.03);
}

TEST(DirectOdometry, ImagesOfDifferentSizesAreRejectedWithAReason) {
  QuarterCircle run;
  StereoPair pair = run.Frame(0).first;
  cv::resize(pair.other, pair.other, cv::Size(160, 120));
  DirectOdometry vo;
  std::string why;
  EXPECT_FALSE(vo.Track(pair, &why));
  EXPECT_NE(why.find("different sizes"), std::string::npos) << why;
}

}  // namespace
}  // namespace novelty::sensors
