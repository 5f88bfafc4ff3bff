#include "eval/pose_error.h"

#include <gtest/gtest.h>

#include <cmath>

namespace novelty::eval {
namespace {

// Frame k is off by k degrees about z and k mm along x, k = 1…20 (frame 21 has no truth): the
// median is frame 11's (index 10 of 20), the 95th percentile frame 20's (index 19).
TEST(PoseError, KnownErrorsGiveTheirMedianAndPercentile) {
  std::map<int, Eigen::Isometry3d> truth, estimated;
  for (int k = 1; k <= 21; ++k) {
    Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
    t.translation() = Eigen::Vector3d(0.5, -0.2, 1.0);
    t.linear() = Eigen::AngleAxisd(0.3, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
    Eigen::Isometry3d e = t;
    e.linear() = t.linear() * Eigen::AngleAxisd(k * M_PI / 180, Eigen::Vector3d::UnitZ());
    e.translation() += Eigen::Vector3d(0.001 * k, 0, 0);
    if (k <= 20) truth[k] = t;
    estimated[k] = e;
  }
  const auto s = ComparePoses(estimated, truth);
  ASSERT_TRUE(s);
  EXPECT_EQ(s->frames, 20);
  EXPECT_EQ(s->last_frame, 20);
  EXPECT_NEAR(s->last_deg, 20.0, 1e-9);
  EXPECT_NEAR(s->last_mm, 20.0, 1e-9);
  EXPECT_NEAR(s->median_deg, 11.0, 1e-9);
  EXPECT_NEAR(s->median_mm, 11.0, 1e-9);
  EXPECT_NEAR(s->p95_deg, 20.0, 1e-9);
  EXPECT_NEAR(s->p95_mm, 20.0, 1e-9);
  EXPECT_FALSE(ComparePoses(estimated, {}));
}

}  // namespace
}  // namespace novelty::eval
