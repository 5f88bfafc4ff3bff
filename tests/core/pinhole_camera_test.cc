#include "core/pinhole_camera.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

namespace novelty::core {
namespace {

// Closed form: a 90° horizontal field of view puts the image border at x/z = ±1, so
// fx = (width / 2) / tan(45°) = width / 2.
TEST(PinholeCamera, FromFovGivesTheClosedFormFocalLength) {
  const PinholeCamera c = PinholeCamera::FromFov(320, 240, M_PI / 2);
  EXPECT_NEAR(c.fx, 160.0, 1e-12);
  EXPECT_NEAR(c.fy, 160.0, 1e-12);
  EXPECT_EQ(c.cx, 159.5);
  EXPECT_EQ(c.cy, 119.5);
  // The left border's pixel edge (u = -0.5) lies on the 45° ray.
  EXPECT_NEAR(c.RayCam(-0.5, c.cy).x(), -1.0, 1e-12);
}

TEST(PinholeCamera, ProjectInvertsUnproject) {
  PinholeCamera c;
  c.fx = 277.0, c.fy = -289.0, c.cx = 160.2, c.cy = 118.7;  // negative fy: image y up (ICL-NUIM)
  for (double u : {0.0, 33.3, 319.0})
    for (double v : {0.0, 120.5, 239.0})
      for (double d : {0.3, 2.0, 9.5}) {
        const Eigen::Vector3d p = c.Unproject(u, v, d);
        EXPECT_NEAR(p.z(), d, 1e-12);
        const Eigen::Vector2d q = c.Project(p);
        EXPECT_NEAR(q.x(), u, 1e-9);
        EXPECT_NEAR(q.y(), v, 1e-9);
      }
}

TEST(PinholeCamera, CheckRejectsWhatCannotProject) {
  PinholeCamera c;
  EXPECT_NO_THROW(c.Check());
  c.fx = 0.0;
  EXPECT_THROW(c.Check(), std::invalid_argument);
  c = PinholeCamera();
  c.cy = NAN;
  EXPECT_THROW(c.Check(), std::invalid_argument);
  c = PinholeCamera();
  c.width = 0;
  EXPECT_THROW(c.Check(), std::invalid_argument);
}

}  // namespace
}  // namespace novelty::core
