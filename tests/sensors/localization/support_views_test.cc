#include "sensors/localization/support_views.h"

#include <gtest/gtest.h>

#include <stdexcept>

#include "tests/sensors/localization/quarter_circle.h"

namespace novelty::sensors {
namespace {

// The common frame: the direct odometry over frames 1–13 of the stereo scenario, started at the
// true pose. The "second sequence" is the same frames with own poses in a frame moved by Q_true
// (M_j = Q_true⁻¹·T_j, no drift), and a blacked-out frame among them.
TEST(SupportViews, AreLocalizedEveryNthFrameAndAFrameThatDoesNotAlignIsSkipped) {
  QuarterCircle run;
  std::vector<StereoPair> frames;
  std::vector<Eigen::Isometry3d> truth, own;
  Eigen::Isometry3d q_true = Eigen::Isometry3d::Identity();
  q_true.linear() = Eigen::AngleAxisd(0.4, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  q_true.translation() = Eigen::Vector3d(0.3, -0.2, 0.05);
  for (int k = 0; k < 13; ++k) {
    const auto [pair, pose] = run.Frame(k);
    frames.push_back(pair);
    truth.push_back(pose);
    own.push_back(q_true.inverse() * pose);
  }
  DirectOdometry common({}, truth[0]);
  std::string why;
  for (const StereoPair& f : frames) ASSERT_TRUE(common.Track(f, &why)) << why;
  frames[4].reference.setTo(cv::Scalar::all(0));
  frames[4].other.setTo(cv::Scalar::all(0));

  SupportViewOptions every4;
  every4.every = 4;
  const SupportViews s = LocalizeSupportViews(common, frames, own, every4);
  ASSERT_EQ(s.views.size(), 3u);  // frames 0, 8, 12
  EXPECT_EQ(s.views[0].index, 0);
  EXPECT_EQ(s.views[1].index, 8);
  EXPECT_EQ(s.views[2].index, 12);
  ASSERT_EQ(s.skipped.size(), 1u);
  EXPECT_EQ(s.skipped[0].rfind("frame 4: ", 0), 0u) << s.skipped[0];
  // Refused for want of texture: its photometric RMS (the keyframe's own contrast, ~25) is
  // within the bound for support views under another lighting.
  EXPECT_NE(s.skipped[0].find("textured 0.000000"), std::string::npos) << s.skipped[0];
  for (const SupportView& v : s.views) {
    const std::size_t j = std::size_t(v.index);
    EXPECT_LT((v.common_from_camera.translation() - truth[j].translation()).norm(), 0.006) << j;
    EXPECT_LT(AngleBetween(v.common_from_camera, truth[j]), 0.2 * M_PI / 180) << j;
    const Eigen::Isometry3d q = v.common_from_camera * v.own_from_camera.inverse();  // eq. 6.1
    EXPECT_LT(AngleBetween(q, q_true), 0.2 * M_PI / 180) << j;
  }
  // With a prior for the first support view (no ORB needed), the same views.
  const SupportViews p = LocalizeSupportViews(common, frames, own, every4, truth[0]);
  EXPECT_EQ(p.views.size(), 3u);
}

TEST(SupportViews, MismatchedInputIsRejected) {
  const DirectOdometry common;
  const std::vector<StereoPair> frames(2);
  EXPECT_THROW(LocalizeSupportViews(common, frames, {Eigen::Isometry3d::Identity()}),
               std::invalid_argument);
  SupportViewOptions zero;
  zero.every = 0;
  EXPECT_THROW(LocalizeSupportViews(common, frames, std::vector<Eigen::Isometry3d>(2), zero),
               std::invalid_argument);
}

}  // namespace
}  // namespace novelty::sensors
