#include "sensors/localization/epipolar_feature_matching.h"

#include <gtest/gtest.h>

namespace novelty::sensors {
namespace {

cv::Mat Unit(cv::RNG& rng) {
  cv::Mat d(1, 64, CV_32F);
  rng.fill(d, cv::RNG::NORMAL, 0.0, 1.0);
  cv::normalize(d, d);
  return d;
}

// A rig with its other camera 0.12 m to the right and turned by 2°; points 0.8–3 m away seen by
// both, with their descriptors slightly changed in the other view.
struct Scene {
  StereoPair pair;
  std::vector<Eigen::Vector3d> points;
  std::vector<cv::KeyPoint> ref_kp, other_kp;
  cv::Mat ref_d, other_d;
};

Scene MakeScene(int n) {
  Scene s;
  s.pair.reference_camera = s.pair.other_camera = core::PinholeCamera::FromFov(320, 240, M_PI / 3);
  s.pair.reference_from_other.translation() = Eigen::Vector3d(0.12, 0.0, 0.0);
  s.pair.reference_from_other.linear() =
      Eigen::AngleAxisd(2.0 * M_PI / 180, Eigen::Vector3d::UnitY()).toRotationMatrix();
  const Eigen::Isometry3d other_from_ref = s.pair.reference_from_other.inverse();
  cv::RNG rng(21);
  while (int(s.points.size()) < n) {
    const Eigen::Vector3d p(rng.uniform(-0.6, 0.6), rng.uniform(-0.4, 0.4), rng.uniform(0.8, 3.0));
    const Eigen::Vector2d a = s.pair.reference_camera.Project(p);
    const Eigen::Vector2d b = s.pair.other_camera.Project(other_from_ref * p);
    if (a.x() < 0 || a.x() > 319 || b.x() < 0 || b.x() > 319 || a.y() < 0 || a.y() > 239 ||
        b.y() < 0 || b.y() > 239)
      continue;
    s.points.push_back(p);
    s.ref_kp.emplace_back(cv::Point2f(float(a.x()), float(a.y())), 20.0f);
    s.other_kp.emplace_back(cv::Point2f(float(b.x()), float(b.y())), 20.0f);
    const cv::Mat d = Unit(rng);
    s.ref_d.push_back(d);
    cv::Mat noise(1, 64, CV_32F);
    rng.fill(noise, cv::RNG::NORMAL, 0.0, 0.01);
    s.other_d.push_back(cv::Mat(d + noise));
  }
  return s;
}

TEST(EpipolarFeatureMatching, RecoversThePointsOfCorrectMatches) {
  const Scene s = MakeScene(60);
  const std::vector<EpipolarFeatureMatch> m =
      MatchAlongEpipolarLines(s.pair, s.ref_kp, s.ref_d, s.other_kp, s.other_d);
  ASSERT_EQ(m.size(), s.points.size());
  for (const EpipolarFeatureMatch& e : m) {
    EXPECT_EQ(e.other, e.reference);
    // Keypoints are floats: 1e-4 px of rounding at 3 m and 0.12 m of baseline is < 1 mm.
    EXPECT_LT((e.p_reference - s.points[std::size_t(e.reference)]).norm(), 1e-3)
        << "feature " << e.reference;
  }
}

TEST(EpipolarFeatureMatching, OffTheLineAndAmbiguousCandidatesAreRejected) {
  Scene s = MakeScene(20);
  // Feature 0's only look-alike moved 5 px below where its match belongs, off the epipolar line:
  // nothing on the line looks like it.
  s.other_kp[0].pt.y += 5.0f;
  // Feature 1 gets a second, near-identical candidate on its epipolar line (the same ray 1 m
  // farther out): the ratio test cannot tell them apart.
  const Eigen::Vector3d farther = s.points[1] * (s.points[1].z() + 1.0) / s.points[1].z();
  const Eigen::Vector2d b =
      s.pair.other_camera.Project(s.pair.reference_from_other.inverse() * farther);
  s.other_kp.emplace_back(cv::Point2f(float(b.x()), float(b.y())), 20.0f);
  s.other_d.push_back(s.other_d.row(1).clone());
  const std::vector<EpipolarFeatureMatch> m =
      MatchAlongEpipolarLines(s.pair, s.ref_kp, s.ref_d, s.other_kp, s.other_d);
  EXPECT_EQ(m.size(), s.points.size() - 2);
  for (const EpipolarFeatureMatch& e : m) {
    EXPECT_NE(e.reference, 0);
    EXPECT_NE(e.reference, 1);
    EXPECT_EQ(e.other, e.reference);
  }
  EXPECT_THROW(MatchAlongEpipolarLines(s.pair, s.ref_kp, s.ref_d.rowRange(0, 3), s.other_kp,
                                       s.other_d),
               std::invalid_argument);
}

}  // namespace
}  // namespace novelty::sensors
