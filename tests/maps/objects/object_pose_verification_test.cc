#include "maps/objects/object_pose_verification.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace novelty::objects {
namespace {

const core::PinholeCamera kPoseCamera = core::PinholeCamera::FromFov(320, 240, M_PI / 3);

// A box-shaped object's feature places (object frame, metres) and a camera 0.9 m in front of it,
// turned 20° about the vertical and 5° about its own axis.
struct PointScene {
  std::vector<Eigen::Vector3d> points;
  Eigen::Isometry3d T_cam_object = Eigen::Isometry3d::Identity();
};

PointScene MakeScene(int n, unsigned seed) {
  PointScene s;
  cv::RNG rng(seed);
  for (int i = 0; i < n; ++i)
    s.points.emplace_back(rng.uniform(-0.1, 0.1), rng.uniform(-0.07, 0.07),
                          rng.uniform(-0.05, 0.05));
  s.T_cam_object.linear() = (Eigen::AngleAxisd(0.35, Eigen::Vector3d::UnitY()) *
                             Eigen::AngleAxisd(0.09, Eigen::Vector3d::UnitZ()))
                                .toRotationMatrix();
  s.T_cam_object.translation() = Eigen::Vector3d(0.05, -0.02, 0.9);
  return s;
}

std::vector<cv::Point2f> Project(const PointScene& s, double noise_px, unsigned seed) {
  cv::RNG rng(seed);
  std::vector<cv::Point2f> px;
  for (const Eigen::Vector3d& p : s.points) {
    const Eigen::Vector2d uv = kPoseCamera.Project(s.T_cam_object * p);
    px.emplace_back(float(uv.x() + rng.gaussian(noise_px)), float(uv.y() + rng.gaussian(noise_px)));
  }
  return px;
}

double AngleDeg(const Eigen::Isometry3d& a, const Eigen::Isometry3d& b) {
  return Eigen::AngleAxisd(a.linear().transpose() * b.linear()).angle() * 180.0 / M_PI;
}

TEST(VerifyObjectPose, RecoversThePoseThroughAThirdOfWrongMatches) {
  PointScene s = MakeScene(40, 1);
  std::vector<cv::Point2f> px = Project(s, 0.3, 2);
  cv::RNG rng(3);
  for (int i = 0; i < 13; ++i)  // a third of the matches wrong: anywhere in the image
    px[std::size_t(i)] = cv::Point2f(rng.uniform(0.f, 320.f), rng.uniform(0.f, 240.f));
  const VerifiedPose v = VerifyObjectPose(s.points, px, kPoseCamera);
  ASSERT_TRUE(v.verified);
  EXPECT_EQ(v.pairs, 40);
  EXPECT_GE(v.inliers, 25) << "the 27 right pairs, bar a couple beyond 2 px of 0.3 px noise";
  EXPECT_LE(v.inliers, 29) << "a wrong match lands within 2 px of its point by chance, rarely";
  EXPECT_LT((v.T_cam_object.translation() - s.T_cam_object.translation()).norm(), 0.01);
  EXPECT_LT(AngleDeg(v.T_cam_object, s.T_cam_object), 1.0);
}

TEST(VerifyObjectPose, TheAgreeingPairsAreNamedByTheirIndexAmongThoseGiven) {
  // Every other place unknown: the agreeing pairs are the known ones, by their index in the
  // input (not among the pairs RANSAC was given).
  const PointScene s = MakeScene(20, 7);
  std::vector<Eigen::Vector3d> places = s.points;
  for (std::size_t i = 0; i < places.size(); i += 2)
    places[i] = Eigen::Vector3d::Constant(std::numeric_limits<double>::quiet_NaN());
  const VerifiedPose v = VerifyObjectPose(places, Project(s, 0.0, 8), kPoseCamera);
  ASSERT_TRUE(v.verified);
  EXPECT_EQ(v.pairs, 10);
  std::vector<int> odd;
  for (int i = 1; i < 20; i += 2) odd.push_back(i);
  std::vector<int> got = v.inlier_pairs;
  std::sort(got.begin(), got.end());
  EXPECT_EQ(got, odd);
  EXPECT_EQ(v.inliers, 10);
}

TEST(VerifyObjectPose, WrongMatchesOnlyOrTooFewPlacesVerifyNothing) {
  const PointScene s = MakeScene(30, 4);
  std::vector<cv::Point2f> px(30);
  cv::RNG rng(5);
  for (cv::Point2f& p : px) p = cv::Point2f(rng.uniform(0.f, 320.f), rng.uniform(0.f, 240.f));
  EXPECT_FALSE(VerifyObjectPose(s.points, px, kPoseCamera).verified) << "all matches wrong";
  // Right matches, but only five with a known place.
  std::vector<Eigen::Vector3d> places = s.points;
  for (std::size_t i = 5; i < places.size(); ++i)
    places[i] = Eigen::Vector3d::Constant(std::numeric_limits<double>::quiet_NaN());
  const VerifiedPose few = VerifyObjectPose(places, Project(s, 0.0, 6), kPoseCamera);
  EXPECT_FALSE(few.verified);
  EXPECT_EQ(few.pairs, 5);
  EXPECT_THROW(VerifyObjectPose(s.points, {}, kPoseCamera), std::invalid_argument);
  PoseVerificationOptions bad;
  bad.min_inliers = 3;
  EXPECT_THROW(VerifyObjectPose(s.points, Project(s, 0.0, 6), kPoseCamera, bad),
               std::invalid_argument);
}

}  // namespace
}  // namespace novelty::objects
