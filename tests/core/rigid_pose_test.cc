#include "core/rigid_pose.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

namespace novelty::core {
namespace {

TEST(RigidPose, IsRigidTellsRotationsFromOtherMatrices) {
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.linear() = Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
  T.translation() << 1, -2, 0.5;
  EXPECT_TRUE(IsRigid(T));
  Eigen::Isometry3d mirrored = T;
  mirrored.linear().col(0) *= -1.0;  // det -1
  EXPECT_FALSE(IsRigid(mirrored));
  Eigen::Isometry3d scaled = T;
  scaled.linear() *= 1.01;
  EXPECT_FALSE(IsRigid(scaled));
  Eigen::Isometry3d nan = T;
  nan.translation().x() = NAN;
  EXPECT_FALSE(IsRigid(nan));
}

// Known answer: a camera at the origin looking along world +x has its +Z on world +x, its +X
// (right) on world -y and its +Y (down) on world -z (MRPT's frames: x forward, y left, z up).
TEST(RigidPose, LookAtFollowsTheProjectsFrames) {
  const Eigen::Isometry3d T = LookAt({0, 0, 0}, {2, 0, 0});
  EXPECT_TRUE(IsRigid(T));
  EXPECT_NEAR((T.linear().col(2) - Eigen::Vector3d(1, 0, 0)).norm(), 0.0, 1e-12);
  EXPECT_NEAR((T.linear().col(0) - Eigen::Vector3d(0, -1, 0)).norm(), 0.0, 1e-12);
  EXPECT_NEAR((T.linear().col(1) - Eigen::Vector3d(0, 0, -1)).norm(), 0.0, 1e-12);
  // The target lies on the optical axis, in front.
  const Eigen::Vector3d eye(1, 2, 1.5), target(-1, 0.5, 0.2);
  const Eigen::Vector3d p = LookAt(eye, target).inverse() * target;
  EXPECT_NEAR(p.x(), 0.0, 1e-12);
  EXPECT_NEAR(p.y(), 0.0, 1e-12);
  EXPECT_NEAR(p.z(), (target - eye).norm(), 1e-12);
  EXPECT_THROW(LookAt(eye, eye), std::invalid_argument);
  EXPECT_THROW(LookAt({0, 0, 0}, {0, 0, 1}), std::invalid_argument);
}

}  // namespace
}  // namespace novelty::core
