#include "maps/views/view_selection.h"
#include "core/rigid_pose.h"

#include <gtest/gtest.h>

#include <cmath>

namespace novelty::views {
namespace {

Eigen::Isometry3d Looking(const Eigen::Vector3d& eye, const Eigen::Vector3d& dir) {
  return core::LookAt(eye, eye + dir);
}

TEST(ViewSelection, CostIsDistanceFromTheRayOverCosine) {
  // Ray from the origin along +x; a view 0.3 m off the ray, looking 60° away from the ray.
  const Eigen::Vector3d dir = Eigen::Vector3d::UnitX();
  const Eigen::Isometry3d view =
      Looking({2.0, 0.3, 0.0}, {std::cos(M_PI / 3), std::sin(M_PI / 3), 0});
  EXPECT_NEAR(ViewCost(Eigen::Vector3d::Zero(), dir, view), 0.3 / 0.5, 1e-12);  // eq. 3.8
  const Eigen::Isometry3d away = Looking({2.0, 0.0, 0.0}, {-1, 0.1, 0});
  EXPECT_TRUE(std::isinf(ViewCost(Eigen::Vector3d::Zero(), dir, away)));
}

TEST(ViewSelection, PicksTheViewsNearTheRaysOnceEachAndNeverOnesFacingAway) {
  const core::PinholeCamera cam = core::PinholeCamera::FromFov(320, 240, 1.0);
  const Eigen::Isometry3d virt = Looking({0, 0, 1}, {1, 0, 0});
  std::vector<Eigen::Isometry3d> poses;
  poses.push_back(Looking({-0.05, 0.0, 1.0}, {1, 0, 0}));    // 0: right behind, same direction
  poses.push_back(Looking({0.0, 2.0, 1.0}, {1, 0, 0}));      // 1: far to the side
  poses.push_back(Looking({0.3, 0.0, 1.0}, {-1, 0, 0}));     // 2: on the axis but facing back
  poses.push_back(Looking({0.2, -0.4, 1.0}, {1, 0.35, 0}));  // 3: right of the camera, turned
  const std::vector<int> sel = SelectViews(poses, cam, virt);
  ASSERT_FALSE(sel.empty());
  EXPECT_EQ(sel[0], 0);  // the centre ray's best view comes first
  EXPECT_EQ(std::count(sel.begin(), sel.end(), 2), 0);
  for (std::size_t i = 0; i < sel.size(); ++i)
    for (std::size_t j = i + 1; j < sel.size(); ++j) EXPECT_NE(sel[i], sel[j]);
  EXPECT_TRUE(SelectViews({poses[2]}, cam, virt).empty());  // only a view facing away: none
}

}  // namespace
}  // namespace novelty::views
