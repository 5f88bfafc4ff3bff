#include "sensors/tracker/pose_trajectory.h"

#include <gtest/gtest.h>

#include <random>

namespace novelty::sensors {
namespace {

// Constant-velocity motion: turning about z at 0.2 rad/s while moving along x at 0.1 m/s.
Eigen::Isometry3d Motion(double t) {
  Eigen::Isometry3d p = Eigen::Isometry3d::Identity();
  p.linear() = Eigen::AngleAxisd(0.2 * t, Eigen::Vector3d::UnitZ()).toRotationMatrix() *
               Eigen::AngleAxisd(0.3, Eigen::Vector3d::UnitX()).toRotationMatrix();
  p.translation() = Eigen::Vector3d(0.1 * t, 1.0, 1.2);
  return p;
}

double AngleBetween(const Eigen::Isometry3d& a, const Eigen::Isometry3d& b) {
  return Eigen::AngleAxisd(a.linear().transpose() * b.linear()).angle();
}

TEST(PoseTrajectory, SlerpFollowsARotationAboutAFixedAxisExactly) {
  std::vector<TimedPose> poses;
  for (int i = 0; i <= 25; ++i) poses.push_back({i * 0.04, Motion(i * 0.04)});
  const PoseTrajectory trajectory(poses);
  std::string why;
  for (double t : {0.0, 0.013, 0.5, 0.77, 1.0}) {
    PoseInterpolationOptions slerp;
    slerp.smoothing_half_window = 0;
    const auto p = trajectory.At(t, slerp, &why);
    ASSERT_TRUE(p) << why;
    EXPECT_LT(AngleBetween(*p, Motion(t)), 1e-12) << t;
    EXPECT_LT((p->translation() - Motion(t).translation()).norm(), 1e-12) << t;
  }
}

TEST(PoseTrajectory, NoPoseOutsideTheSpanOrAcrossAGap) {
  std::vector<TimedPose> poses = {{0.0, Motion(0)}, {0.04, Motion(0.04)}, {1.0, Motion(1.0)}};
  const PoseTrajectory trajectory(poses);
  std::string why;
  EXPECT_FALSE(trajectory.At(-0.1, {}, &why));
  EXPECT_NE(why.find("outside"), std::string::npos) << why;
  EXPECT_FALSE(trajectory.At(0.5, {}, &why));
  EXPECT_NE(why.find("gap"), std::string::npos) << why;
  EXPECT_TRUE(trajectory.At(0.02, {}, &why));
  EXPECT_FALSE(PoseTrajectory({}).At(0.0, {}, &why));
}

TEST(PoseTrajectory, LocalLinearFitKeepsConstantVelocityAndAveragesNoise) {
  std::mt19937_64 rng(3);
  std::normal_distribution<double> n(0, 1.0);
  std::vector<TimedPose> clean, noisy;
  for (int i = 0; i <= 250; ++i) {
    const double t = i * 0.04;
    clean.push_back({t, Motion(t)});
    Eigen::Isometry3d p = Motion(t);
    p.linear() =
        p.linear() *
        Eigen::AngleAxisd(0.005 * n(rng), Eigen::Vector3d(n(rng), n(rng), n(rng)).normalized())
            .toRotationMatrix();
    p.translation() += 0.001 * Eigen::Vector3d(n(rng), n(rng), n(rng));
    noisy.push_back({t, p});
  }
  PoseInterpolationOptions smooth;
  smooth.smoothing_half_window = 0.3;
  const PoseTrajectory exact(clean), measured(noisy);
  double raw_angle = 0, smooth_angle = 0, raw_shift = 0, smooth_shift = 0;
  int count = 0;
  for (double t = 1.0; t <= 9.0; t += 0.1429, ++count) {
    const auto e = exact.At(t, smooth, nullptr);
    ASSERT_TRUE(e);
    EXPECT_LT(AngleBetween(*e, Motion(t)), 1e-9);  // a line in the tangent space is exact here
    EXPECT_LT((e->translation() - Motion(t).translation()).norm(), 1e-12);
    PoseInterpolationOptions slerp;
    slerp.smoothing_half_window = 0;
    const auto r = measured.At(t, slerp, nullptr), s = measured.At(t, smooth, nullptr);
    raw_angle += AngleBetween(*r, Motion(t));
    smooth_angle += AngleBetween(*s, Motion(t));
    raw_shift += (r->translation() - Motion(t).translation()).norm();
    smooth_shift += (s->translation() - Motion(t).translation()).norm();
  }
  // ~10 samples in the tricube window: the errors shrink by well over half.
  EXPECT_LT(smooth_angle, 0.5 * raw_angle);
  EXPECT_LT(smooth_shift, 0.5 * raw_shift);
}

}  // namespace
}  // namespace novelty::sensors
