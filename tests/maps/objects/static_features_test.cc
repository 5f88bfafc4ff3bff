#include "maps/objects/static_features.h"

#include <gtest/gtest.h>

namespace novelty::objects {
namespace {

cv::Mat Unit(unsigned seed) {
  cv::Mat d(1, 64, CV_32F);
  cv::RNG(seed).fill(d, cv::RNG::NORMAL, 0.0, 1.0);
  cv::normalize(d, d);
  return d;
}

// Two active features 1.5 m in front of a camera turned and moved off the world origin; selected
// features near and far from where they project, with descriptors near and far from theirs.
TEST(StaticFeatures, Equations51And52) {
  const core::PinholeCamera camera = core::PinholeCamera::FromFov(320, 240, M_PI / 3);
  Eigen::Isometry3d T_world_cam = Eigen::Isometry3d::Identity();
  T_world_cam.linear() = Eigen::AngleAxisd(0.3, Eigen::Vector3d::UnitY()).toRotationMatrix();
  T_world_cam.translation() = Eigen::Vector3d(0.2, -0.1, 0.5);
  std::vector<ActiveFeature> active(2);
  const Eigen::Vector3d in_cam[2] = {{0.1, 0.05, 1.5}, {-0.2, 0.1, 1.4}};
  cv::Point2f at[2];
  for (int g = 0; g < 2; ++g) {
    active[std::size_t(g)].p_world = T_world_cam * in_cam[g];
    active[std::size_t(g)].descriptor = Unit(10 + g);
    // Its stereo match was 0.3 away from it in descriptor space.
    active[std::size_t(g)].max_descriptor_change = 0.3;
    const Eigen::Vector2d uv = camera.Project(in_cam[g]);
    at[g] = cv::Point2f(float(uv.x()), float(uv.y()));
  }
  auto near_descriptor = [&](int g, float by) {
    cv::Mat d = active[std::size_t(g)].descriptor.clone();
    d.at<float>(1) += by;
    return d;
  };
  std::vector<cv::KeyPoint> keypoints;
  cv::Mat descriptors;
  auto add = [&](cv::Point2f p, const cv::Mat& d) {
    keypoints.emplace_back(p, 20.0f);
    descriptors.push_back(d);
  };
  add(at[0] + cv::Point2f(1.2f, -1.0f), near_descriptor(0, 0.1f));  // 0: static (1.56 px, 0.1 ≤ 0.3)
  add(at[0] + cv::Point2f(2.5f, 0.0f), near_descriptor(0, 0.1f));   // 1: too far (eq. 5.1)
  add(at[1] + cv::Point2f(0.5f, 0.5f), near_descriptor(1, 0.4f));   // 2: descriptor moved (eq. 5.2)
  add(at[1] + cv::Point2f(-0.5f, 0.0f), near_descriptor(1, 0.29f));  // 3: static, just within
  add(at[1], Unit(99));                                              // 4: another feature there
  EXPECT_EQ(StaticFeatures(keypoints, descriptors, active, camera, T_world_cam, 2.0),
            (std::vector<int>{0, 3}));
  // Seen from behind (the camera turned around), nothing projects: nothing is static.
  Eigen::Isometry3d behind = T_world_cam;
  behind.linear() = behind.linear() * Eigen::AngleAxisd(M_PI, Eigen::Vector3d::UnitY());
  EXPECT_TRUE(StaticFeatures(keypoints, descriptors, active, camera, behind, 2.0).empty());
  EXPECT_THROW(StaticFeatures(keypoints, descriptors.rowRange(0, 2), active, camera, T_world_cam),
               std::invalid_argument);
}

}  // namespace
}  // namespace novelty::objects
