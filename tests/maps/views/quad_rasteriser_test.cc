#include "maps/views/quad_rasteriser.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "core/rigid_pose.h"

namespace novelty::views::mesh {
namespace {

const core::PinholeCamera kCam = core::PinholeCamera::FromFov(160, 120, 1.0);

// One target's planes, owned.
struct Canvas {
  std::vector<float> inv_z, source_depth, uv;
  Canvas()
      : inv_z(std::size_t(kCam.width) * kCam.height, 0.0f),
        source_depth(inv_z.size(), 0.0f),
        uv(2 * inv_z.size(), -1.0f) {}
  Target target() { return {inv_z.data(), source_depth.data(), uv.data(), kCam.width, kCam.height}; }
};

// A wavy surface with a step (a depth discontinuity the rasterisers must not bridge) and a hole,
// seen from a turned and shifted virtual camera, so that quads are stretched, shrunk and cut.
TEST(QuadRasteriser, VectorisedRowsDrawWhatTheScalarQuadsDraw) {
  cv::Mat depth(kCam.height, kCam.width, CV_32FC1);
  for (int y = 0; y < depth.rows; ++y)
    for (int x = 0; x < depth.cols; ++x)
      depth.at<float>(y, x) =
          2.0f + 0.2f * std::sin(x * 0.1f) * std::cos(y * 0.07f) + (x > 100 ? 0.8f : 0.0f);
  depth(cv::Rect(30, 40, 6, 5)).setTo(0.0f);
  const Eigen::Isometry3d source = core::LookAt({0, 0, 0}, {1, 0, 0});
  const Eigen::Isometry3d virt = core::LookAt({0.05, 0.15, 0.1}, {1.0, 0.1, 0.0});
  const MeshPlan plan = PlanMesh(depth, 0, 0.0);  // every quad on its own
  Vertices v;
  v.Resize(std::size_t(kCam.width) * kCam.height);
  v.skip = plan.skip.data();
  const VertexProjector project(kCam, virt.inverse() * source, depth, kCam, 0.05, v);
  for (int r = 0; r < kCam.height; ++r) project.Row(r, true);

  Canvas vectorised, scalar;
  const float max_ratio = 1.05f;
  for (int r = 0; r + 1 < kCam.height; ++r) {
    RasteriseRowVectorised(v, kCam.width, r, max_ratio, vectorised.target());
    for (int u = 0; u + 1 < kCam.width; ++u) {
      if (plan.skip[std::size_t(r) * kCam.width + u] == 0)
        RasteriseQuad(v, kCam.width, u, r, max_ratio, scalar.target());
    }
  }
  int covered_v = 0, covered_s = 0, compared = 0;
  for (std::size_t j = 0; j < vectorised.inv_z.size(); ++j) {
    covered_v += vectorised.inv_z[j] > 0.0f;
    covered_s += scalar.inv_z[j] > 0.0f;
    if (!(vectorised.inv_z[j] > 0.0f && scalar.inv_z[j] > 0.0f)) continue;
    ASSERT_NEAR(1.0f / vectorised.inv_z[j], 1.0f / scalar.inv_z[j], 1e-4f) << j;
    ASSERT_NEAR(vectorised.source_depth[j], scalar.source_depth[j], 1e-4f) << j;
    ASSERT_NEAR(vectorised.uv[2 * j], scalar.uv[2 * j], 1e-3f) << j;
    ASSERT_NEAR(vectorised.uv[2 * j + 1], scalar.uv[2 * j + 1], 1e-3f) << j;
    ++compared;
  }
  EXPECT_GT(covered_s, kCam.width * kCam.height / 2);
  EXPECT_NEAR(covered_v, covered_s, 3);  // at most a few pixels on triangle edges differ
  EXPECT_GT(compared, kCam.width * kCam.height / 2);
}

}  // namespace
}  // namespace novelty::views::mesh
