#include "sensors/localization/direct_odometry.h"

#include <gtest/gtest.h>

#include <map>
#include <opencv2/imgproc.hpp>
#include <utility>
#include <vector>

#include "sensors/localization/sequence_registration.h"
#include "tests/sensors/localization/quarter_circle.h"

namespace novelty::sensors {
namespace {

using Clip = std::vector<std::pair<StereoPair, Eigen::Isometry3d>>;

// Frames [first, first + count) of the stereo scenario (0-based), rendered once per process.
const Clip& Rendered(int first, int count) {
  static std::map<std::pair<int, int>, Clip> cache;
  Clip& clip = cache[{first, count}];
  if (clip.empty()) {
    QuarterCircle run;
    for (int k = first; k < first + count; ++k) clip.push_back(run.Frame(k));
  }
  return clip;
}
const Clip& PhaseI1() { return Rendered(0, 95); }    // frames 1–95
const Clip& PhaseI2() { return Rendered(200, 95); }  // frames 201–295, after the lamps moved

double AngleDeg(const Eigen::Isometry3d& a, const Eigen::Isometry3d& b) {
  return AngleBetween(a, b) * 180 / M_PI;
}

// Phase I1 of the stereo scenario: frames 1–95, 90° of a 1.5 m circle, 2.3 m of path. The
// sensors issue's budget is < 1 % of the path length; measured: worst 0.33 % (7.7 mm), worst
// angle 0.26°, against 2.0 % / 1.8° for the feature-based odometry on the same frames. Over all
// nine quarter circles I1–I9 (measured outside the tests): mean 0.49 %, worst 0.67 %.
TEST(DirectOdometry, DriftOnAQuarterCircleStaysBelowOnePercentOfThePath) {
  const Clip& clip = PhaseI1();
  DirectOdometry vo({}, clip[0].second);
  double path = 0, worst = 0, worst_angle = 0;
  int keyframes = 0;
  for (size_t k = 0; k < clip.size(); ++k) {
    const auto& [pair, truth] = clip[k];
    std::string why;
    const auto r = vo.Track(pair, &why);
    ASSERT_TRUE(r) << "frame " << k + 1 << ": " << why;
    EXPECT_FALSE(r->relocalized);
    keyframes += r->new_keyframe;
    if (k > 0) path += (truth.translation() - clip[k - 1].second.translation()).norm();
    worst = std::max(worst, (r->world_from_camera.translation() - truth.translation()).norm());
    worst_angle = std::max(worst_angle, AngleDeg(r->world_from_camera, truth));
  }
  std::printf("path %.2f m: worst error %.1f mm (%.2f %%), worst angle %.2f°, %d keyframes\n",
              path, 1000 * worst, 100 * worst / path, worst_angle, keyframes);
  EXPECT_GT(path, 2.0);
  EXPECT_LT(worst, 0.01 * path);
  EXPECT_LT(worst_angle, 0.5);
  EXPECT_GT(keyframes, 5);  // drift is measured across keyframe hand-overs, not within one
}

// The lamps move between frames 200 and 201 (scenario event at 49.81 s): the shading of the
// whole scene changes while the camera drives on. Alignment after local contrast normalization
// keeps tracking (measured: worst 3.2 mm over 0.47 m); with raw grey levels it is lost there.
TEST(DirectOdometry, KeepsTrackingThroughAChangeOfLighting) {
  const Clip& clip = Rendered(190, 25);  // frames 191–215
  auto track = [&](const DirectOdometryOptions& options, double* worst) {
    DirectOdometry vo(options, clip[0].second);
    int relocalized = 0;
    *worst = 0;
    for (const auto& [pair, truth] : clip) {
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

// Registration of a second sequence (6.1.1): phase I2 (frames 201–295, other lighting) is
// localized by its own odometry from the identity; five support views of it are localized
// against the keyframes of I1's odometry (the common frame, started at the true pose), the
// first by ORB matches, the others from the pose the previous support view predicts; eq. 6.1
// gives Q at each, and every I2 pose is registered by eq. 6.3 with Q interpolated (Lagrange,
// three support views) or fitted (Ceres, five). Measured against the ground truth: registered
// poses worst 7.8 mm (Lagrange) and 8.3 mm / 0.28° (Ceres); the support views themselves are
// several millimetres off — the common frame's own drift — so the 5 mm is out of reach
// this way. (I3, I4 as second sequence: Lagrange 8.6 / 9.7 mm, Ceres 7.6 / 7.1 mm.)
TEST(DirectOdometry, RegistersASecondSequenceThroughSupportViews) {
  const Clip& common = PhaseI1();
  const Clip& second = PhaseI2();
  DirectOdometry reference({}, common[0].second);
  std::string why;
  for (const auto& [pair, truth] : common) ASSERT_TRUE(reference.Track(pair, &why)) << why;
  DirectOdometry own_odometry({}, Eigen::Isometry3d::Identity());
  std::vector<Eigen::Isometry3d> own;
  for (const auto& [pair, truth] : second) {
    const auto r = own_odometry.Track(pair, &why);
    ASSERT_TRUE(r) << why;
    own.push_back(r->world_from_camera);
  }
  std::vector<SupportView> five, three;
  for (const int j : {0, 23, 47, 70, 94}) {
    std::optional<Eigen::Isometry3d> prior;
    if (!five.empty())
      prior = five.back().common_from_camera * five.back().own_from_camera.inverse() * own[j];
    const auto support = reference.Localize(second[j].first, &why, prior);
    ASSERT_TRUE(support) << "support view " << j << ": " << why;
    EXPECT_LT((support->translation() - second[j].second.translation()).norm(), 0.012);
    five.push_back({double(j), *support, own[j]});
    if (j % 47 == 0) three.push_back(five.back());
  }
  const FittedFrameTransform fitted(five);
  double lagrange_mm = 0, lagrange_deg = 0, ceres_mm = 0, ceres_deg = 0;
  for (size_t j = 0; j < second.size(); ++j) {
    const Eigen::Isometry3d& truth = second[j].second;
    const Eigen::Matrix4d l = RegisterPose(LagrangeFrameTransform(three, double(j)), own[j]);
    const Eigen::JacobiSVD<Eigen::Matrix3d> svd(l.topLeftCorner<3, 3>(),
                                                Eigen::ComputeFullU | Eigen::ComputeFullV);
    Eigen::Isometry3d lagrange = Eigen::Isometry3d::Identity();  // nearest rotation, to compare
    lagrange.linear() = svd.matrixU() * svd.matrixV().transpose();
    lagrange.translation() = l.topRightCorner<3, 1>();
    const Eigen::Isometry3d ceres = fitted.At(double(j)) * own[j];
    lagrange_mm = std::max(lagrange_mm, 1000 * (lagrange.translation() - truth.translation()).norm());
    lagrange_deg = std::max(lagrange_deg, AngleDeg(lagrange, truth));
    ceres_mm = std::max(ceres_mm, 1000 * (ceres.translation() - truth.translation()).norm());
    ceres_deg = std::max(ceres_deg, AngleDeg(ceres, truth));
  }
  std::printf("registered I2, worst: Lagrange %.1f mm %.2f°, Ceres %.1f mm %.2f°\n", lagrange_mm,
              lagrange_deg, ceres_mm, ceres_deg);
  EXPECT_LT(ceres_mm, 12.0);
  EXPECT_LT(lagrange_mm, 12.0);
  EXPECT_LT(ceres_deg, 0.5);  // the sensors issue's rotation budget
  EXPECT_LT(lagrange_deg, 0.5);
}

// After a blackout (tracking lost) the pose comes back from the keyframes, and tracking goes on.
TEST(DirectOdometry, RelocalizesAfterTrackingIsLost) {
  const Clip& clip = Rendered(0, 23);
  DirectOdometry vo({}, clip[0].second);
  std::string why;
  for (int k = 0; k < 20; ++k) ASSERT_TRUE(vo.Track(clip[k].first, &why)) << why;
  StereoPair dark = clip[0].first;
  dark.reference = cv::Mat::zeros(dark.reference.size(), dark.reference.type());
  dark.other = dark.reference.clone();
  EXPECT_FALSE(vo.Track(dark, &why));
  EXPECT_NE(why.find("lost"), std::string::npos) << why;
  const auto& [pair, truth] = clip[21];
  const auto r = vo.Track(pair, &why);
  ASSERT_TRUE(r) << why;
  EXPECT_TRUE(r->relocalized);
  std::printf("re-localized %.1f mm, %.2f° off\n",
              1000 * (r->world_from_camera.translation() - truth.translation()).norm(),
              AngleDeg(r->world_from_camera, truth));
  EXPECT_LT((r->world_from_camera.translation() - truth.translation()).norm(), 0.01);
  EXPECT_LT(AngleDeg(r->world_from_camera, truth), 0.5);
  const auto& [next_pair, next_truth] = clip[22];
  const auto next = vo.Track(next_pair, &why);
  ASSERT_TRUE(next) << why;
  EXPECT_FALSE(next->relocalized);
  EXPECT_LT((next->world_from_camera.translation() - next_truth.translation()).norm(), 0.01);
}

TEST(DirectOdometry, ImagesOfDifferentSizesAreRejectedWithAReason) {
  StereoPair pair;
  pair.reference = cv::Mat(240, 320, CV_8UC3, cv::Scalar(90, 120, 60));
  pair.other = cv::Mat(120, 160, CV_8UC3, cv::Scalar(90, 120, 60));
  DirectOdometry vo;
  std::string why;
  EXPECT_FALSE(vo.Track(pair, &why));
  EXPECT_NE(why.find("different sizes"), std::string::npos) << why;
  EXPECT_FALSE(vo.Localize(pair, &why));
}

}  // namespace
}  // namespace novelty::sensors
