#include "maps/objects/planar_object_verification.h"

#include <gtest/gtest.h>

#include <opencv2/core.hpp>

namespace novelty::objects {
namespace {

// A photo's plane 0.2 × 0.15 m and a homography that views it tilted and turned: the image of
// a camera 0.6 m away, 25° off the plane's normal (as H = K [r1 r2 t], composed by hand).
Eigen::Matrix3d ViewOfPlane() {
  const Eigen::Matrix3d k = (Eigen::Matrix3d() << 500, 0, 320, 0, 500, 240, 0, 0, 1).finished();
  const Eigen::Matrix3d r = (Eigen::AngleAxisd(0.44, Eigen::Vector3d::UnitY()) *
                             Eigen::AngleAxisd(0.2, Eigen::Vector3d::UnitZ()))
                                .toRotationMatrix();
  Eigen::Matrix3d rt;
  rt << r.col(0), r.col(1), Eigen::Vector3d(-0.1, -0.07, 0.6);
  return k * rt;
}

const std::vector<Eigen::Vector2d> kOutline = {{0, 0}, {0.2, 0}, {0.2, 0.15}, {0, 0.15}};

std::vector<Eigen::Vector2d> PlanePoints(int n, unsigned seed) {
  cv::RNG rng(seed);
  std::vector<Eigen::Vector2d> p;
  for (int i = 0; i < n; ++i) p.emplace_back(rng.uniform(0.0, 0.2), rng.uniform(0.0, 0.15));
  return p;
}

std::vector<cv::Point2f> Image(const Eigen::Matrix3d& h, const std::vector<Eigen::Vector2d>& p,
                               double noise_px, unsigned seed) {
  cv::RNG rng(seed);
  std::vector<cv::Point2f> px;
  for (const Eigen::Vector2d& q : p) {
    const Eigen::Vector2d uv = (h * q.homogeneous()).hnormalized();
    px.emplace_back(float(uv.x() + rng.gaussian(noise_px)), float(uv.y() + rng.gaussian(noise_px)));
  }
  return px;
}

TEST(VerifyPlanarObject, RecoversTheHomographyThroughAThirdOfWrongMatches) {
  const Eigen::Matrix3d h = ViewOfPlane();
  const std::vector<Eigen::Vector2d> plane = PlanePoints(60, 1);
  std::vector<cv::Point2f> px = Image(h, plane, 0.3, 2);
  cv::RNG rng(3);
  for (int i = 0; i < 20; ++i)
    px[std::size_t(i)] = cv::Point2f(rng.uniform(0.f, 640.f), rng.uniform(0.f, 480.f));
  const VerifiedHomography v = VerifyPlanarObject(plane, px, kOutline);
  ASSERT_TRUE(v.verified);
  EXPECT_EQ(v.pairs, 60);
  EXPECT_GE(v.inliers, 38) << "the 40 right pairs, bar a couple beyond 2 px of 0.3 px noise";
  EXPECT_LE(v.inliers, 42);
  for (int i : v.inlier_pairs) EXPECT_GE(i, 0);
  // The outline's corners where the true homography puts them, within a pixel.
  const std::vector<cv::Point2f> got = MapOutline(v.image_from_plane, kOutline),
                                 truth = MapOutline(h, kOutline);
  for (std::size_t c = 0; c < truth.size(); ++c)
    EXPECT_LT(cv::norm(got[c] - truth[c]), 1.0) << "corner " << c;
}

TEST(VerifyPlanarObject, AMirroredViewIsNoViewOfThePhoto) {
  // The photo seen through from its back: every pair agrees with H·M, M = (x, y) → (0.2 − x, y),
  // which keeps the image where it was but reverses the outline's orientation — whichever order
  // the outline is listed in.
  Eigen::Matrix3d m = Eigen::Matrix3d::Identity();
  m(0, 0) = -1;
  m(0, 2) = 0.2;
  const std::vector<Eigen::Vector2d> plane = PlanePoints(40, 4);
  const std::vector<cv::Point2f> px = Image(ViewOfPlane() * m, plane, 0.2, 5);
  const VerifiedHomography flipped = VerifyPlanarObject(plane, px, kOutline);
  EXPECT_GE(flipped.inliers, 36) << "RANSAC finds the mirrored homography";
  EXPECT_FALSE(flipped.verified);
  const std::vector<Eigen::Vector2d> reversed(kOutline.rbegin(), kOutline.rend());
  EXPECT_FALSE(VerifyPlanarObject(plane, px, reversed).verified);
  EXPECT_TRUE(VerifyPlanarObject(plane, Image(ViewOfPlane(), plane, 0.2, 5), reversed).verified);
}

TEST(VerifyPlanarObject, RandomPairsAreNotVerified) {
  cv::RNG rng(6);
  const std::vector<Eigen::Vector2d> plane = PlanePoints(30, 7);
  std::vector<cv::Point2f> px;
  for (int i = 0; i < 30; ++i) px.emplace_back(rng.uniform(0.f, 640.f), rng.uniform(0.f, 480.f));
  const VerifiedHomography v = VerifyPlanarObject(plane, px, kOutline);
  EXPECT_FALSE(v.verified);
  EXPECT_LT(v.inliers, 6) << "four pairs fit any homography; a fifth and sixth agree by chance "
                             "within 2 px rarely";
}

TEST(VerifyPlanarObject, TooFewPairsOrBadInputs) {
  const std::vector<Eigen::Vector2d> plane = PlanePoints(5, 8);
  const VerifiedHomography v =
      VerifyPlanarObject(plane, Image(ViewOfPlane(), plane, 0, 9), kOutline);
  EXPECT_FALSE(v.verified);
  EXPECT_EQ(v.pairs, 5);
  EXPECT_THROW(VerifyPlanarObject(plane, {}, kOutline), std::invalid_argument);
  EXPECT_THROW(VerifyPlanarObject(plane, Image(ViewOfPlane(), plane, 0, 9), {{0, 0}, {1, 1}}),
               std::invalid_argument);
  PoseVerificationOptions o;
  o.min_inliers = 3;
  EXPECT_THROW(VerifyPlanarObject(plane, Image(ViewOfPlane(), plane, 0, 9), kOutline, o),
               std::invalid_argument);
}

}  // namespace
}  // namespace novelty::objects
