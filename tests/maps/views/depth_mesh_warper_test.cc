#include "maps/views/depth_mesh_warper.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "core/rigid_pose.h"
#include "maps/views/planar_blocks.h"

namespace novelty::views {
namespace {

const core::PinholeCamera kCam = core::PinholeCamera::FromFov(160, 120, 1.0);

// Camera at the origin looking along world +x (so world x is depth).
Eigen::Isometry3d Forward(double y = 0.0, double z = 0.0) {
  return core::LookAt({0, y, z}, {1, y, z});
}

cv::Mat Constant(float depth) {
  return cv::Mat(kCam.height, kCam.width, CV_32FC1, cv::Scalar(depth));
}

TEST(DepthMeshWarper, IdentityWarpMapsEveryPixelToItself) {
  const WarpField w = WarpView(kCam, Forward(), Constant(2.0f), kCam, Forward());
  for (int y = 0; y < kCam.height - 1; ++y) {
    for (int x = 0; x < kCam.width - 1; ++x) {
      const cv::Vec2f s = w.map.at<cv::Vec2f>(y, x);
      ASSERT_NEAR(s[0], x, 1e-3);
      ASSERT_NEAR(s[1], y, 1e-3);
      ASSERT_NEAR(w.depth.at<float>(y, x), 2.0f, 1e-5);
    }
  }
  // The last row and column are vertices of no complete quad beyond them, but lie on edges.
  EXPECT_GE(w.covered, (kCam.width - 1) * (kCam.height - 1));
}

TEST(DepthMeshWarper, SidewaysMoveShiftsAFrontoParallelPlaneByTheDisparity) {
  // Virtual camera 0.1 m to the left (world +y): a plane at 2 m shifts by fx · 0.1 / 2 pixels.
  const WarpField w = WarpView(kCam, Forward(), Constant(2.0f), kCam, Forward(0.1));
  const double disparity = kCam.fx * 0.1 / 2.0;
  int checked = 0;
  for (int y = 5; y < kCam.height - 5; y += 7) {
    for (int x = 20; x < kCam.width - 20; x += 7) {
      const cv::Vec2f s = w.map.at<cv::Vec2f>(y, x);
      ASSERT_GE(s[0], 0.0f);
      EXPECT_NEAR(s[0], x - disparity, 1e-3) << x << "," << y;
      EXPECT_NEAR(s[1], y, 1e-3);
      ++checked;
    }
  }
  EXPECT_GT(checked, 100);
}

// The view angle at each covered pixel against the geometry in double: the surface point on the
// plane x = 2 m (world), the rays from it to the virtual camera (0.1 m left) and to the source.
TEST(DepthMeshWarper, ViewAnglesMatchTheGeometry) {
  WarpOutputs o;
  o.view_angles = true;
  const Eigen::Isometry3d virt = Forward(0.1, 0.05);
  const WarpField w = WarpView(kCam, Forward(), Constant(2.0f), kCam, virt, {}, o);
  ASSERT_EQ(w.cos_angle.size(), w.depth.size());
  int checked = 0;
  for (int y = 3; y < kCam.height - 3; y += 5) {
    for (int x = 20; x < kCam.width - 20; x += 5) {
      const float z = w.depth.at<float>(y, x);
      if (!(z > 0.0f)) continue;
      const Eigen::Vector3d p = virt * kCam.Unproject(x, y, z);  // world
      const Eigen::Vector3d to_virtual = virt.translation() - p, to_source = -p;
      const double truth = to_virtual.normalized().dot(to_source.normalized());
      ASSERT_NEAR(w.cos_angle.at<float>(y, x), truth, 2e-6) << x << "," << y;
      ++checked;
    }
  }
  EXPECT_GT(checked, 300);
  EXPECT_EQ(w.cos_angle.at<float>(0, kCam.width - 1) == 0.0f,
            !(w.depth.at<float>(0, kCam.width - 1) > 0.0f));
}

TEST(DepthMeshWarper, SourceDepthOnlyWhenAsked) {
  // Virtual camera 0.5 m nearer a plane at 2 m: depth 1.5 there, 2 in the source view.
  const Eigen::Isometry3d nearer = core::LookAt({0.5, 0, 0}, {1.5, 0, 0});
  EXPECT_TRUE(WarpView(kCam, Forward(), Constant(2.0f), kCam, nearer).source_depth.empty());
  WarpOutputs o;
  o.source_depth = true;
  const WarpField w = WarpView(kCam, Forward(), Constant(2.0f), kCam, nearer, {}, o);
  ASSERT_EQ(w.source_depth.size(), w.depth.size());
  int covered = 0;
  for (int y = 0; y < kCam.height; ++y) {
    for (int x = 0; x < kCam.width; ++x) {
      const float d = w.depth.at<float>(y, x), zs = w.source_depth.at<float>(y, x);
      if (d == 0.0f) {
        ASSERT_EQ(zs, 0.0f);
        continue;
      }
      ASSERT_NEAR(d, 1.5f, 1e-4);
      ASSERT_NEAR(zs, 2.0f, 1e-4);
      ++covered;
    }
  }
  EXPECT_EQ(covered, w.covered);
  EXPECT_GT(covered, kCam.width * kCam.height / 2);
}

TEST(DepthMeshWarper, DepthDiscontinuitiesAreNotBridged) {
  // Left half at 1 m, right half at 3 m; a sideways virtual camera opens a gap between them.
  cv::Mat depth = Constant(3.0f);
  depth(cv::Rect(0, 0, kCam.width / 2, kCam.height)).setTo(1.0f);
  const WarpField w = WarpView(kCam, Forward(), depth, kCam, Forward(-0.2));
  int between = 0, gap = 0;
  for (int i = 0; i < kCam.width * kCam.height; ++i) {
    const float d = w.depth.at<float>(i);
    if (d > 1.05f && d < 2.9f) ++between;  // a stretched triangle would put depths here
    gap += d == 0.0f;
  }
  EXPECT_EQ(between, 0);
  EXPECT_GT(gap, kCam.height * 5);  // the disoccluded strip stays uncovered
  WarpOptions joined;
  joined.max_relative_depth_jump = 10.0;  // bridging allowed: the gap fills with rubber
  const WarpField r = WarpView(kCam, Forward(), depth, kCam, Forward(-0.2), joined);
  EXPECT_GT(r.covered, w.covered);
}

TEST(DepthMeshWarper, NothingInFrontGivesAnAllInvalidField) {
  const WarpField w = WarpView(kCam, Forward(), Constant(2.0f), kCam,
                               core::LookAt({5, 0, 0}, {6, 0, 0}));  // the plane is behind it
  EXPECT_EQ(w.covered, 0);
  EXPECT_EQ(cv::countNonZero(w.depth), 0);
}

// A view of `depth` from Forward() warped into `virt` with planar blocks and quad by quad, and
// over the pixels both cover the largest differences of source coordinates (px) and of depth
// (relative).
struct BlocksAgainstQuads {
  WarpField blocks, quads;
  double worst_px = 0, worst_depth = 0;
};

BlocksAgainstQuads CompareBlocksWithQuads(const cv::Mat& depth, const Eigen::Isometry3d& virt) {
  BlocksAgainstQuads c;
  WarpOptions quads;
  quads.planar_block = 0;
  c.blocks = WarpView(kCam, Forward(), depth, kCam, virt);
  c.quads = WarpView(kCam, Forward(), depth, kCam, virt, quads);
  const WarpField &a = c.blocks, &b = c.quads;
  for (int i = 0; i < kCam.width * kCam.height; ++i) {
    if (a.depth.at<float>(i) == 0.0f || b.depth.at<float>(i) == 0.0f) continue;
    c.worst_px =
        std::max<double>(c.worst_px, cv::norm(a.map.at<cv::Vec2f>(i) - b.map.at<cv::Vec2f>(i)));
    c.worst_depth =
        std::max<double>(c.worst_depth, std::abs(a.depth.at<float>(i) / b.depth.at<float>(i) - 1));
  }
  return c;
}

TEST(DepthMeshWarper, PlanarBlocksGiveTheFieldOfTheSmallQuads) {
  // A tilted plane with a box standing out of it, seen from a turned and
  // shifted virtual camera: drawn as blocks (with their rings towards the box) or quad by quad,
  // the same pixels get the same source coordinates and depth.
  cv::Mat depth(kCam.height, kCam.width, CV_32FC1);
  const cv::Rect box(60, 40, 37, 29);  // its face another plane, 0.5–0.9 m nearer
  for (int y = 0; y < depth.rows; ++y)
    for (int x = 0; x < depth.cols; ++x)
      depth.at<float>(y, x) =
          1.0f / ((box.contains({x, y}) ? 0.7f : 0.4f) + 0.0008f * x + 0.0005f * y);
  ASSERT_GT(cv::countNonZero(FindPlanarBlocks(depth, 8, 0.002)), 200);  // of 19 × 14
  const BlocksAgainstQuads c =
      CompareBlocksWithQuads(depth, core::LookAt({0.05, 0.15, 0.1}, {1.0, 0.1, 0.0}));
  EXPECT_GT(c.blocks.covered, kCam.width * kCam.height / 2);
  EXPECT_NEAR(c.blocks.covered, c.quads.covered, 3);  // no crack along the blocks' edges
  // Within a small quad the quad path interpolates source coordinates linearly on screen, the
  // blocks perspective-correctly: they differ by a fraction of a hundredth of a pixel.
  EXPECT_LT(c.worst_px, 0.01);
  EXPECT_LT(c.worst_depth, 2e-5);
  std::printf("blocks against quads: %.4f px, relative depth %.1e\n", c.worst_px, c.worst_depth);
}

TEST(DepthMeshWarper, MeshPlansKeptByTheCallerAreUsedWhereTheyFit) {
  // A tilted plane: a kept plan made for the warp's options gives the field planned anew; a kept
  // plan is used as it is (one without blocks gives exactly the quad-by-quad field where the warp
  // itself would use blocks, one with a planted hole leaves a hole); plans made for other options
  // or another size are ignored (planned anew).
  cv::Mat depth(kCam.height, kCam.width, CV_32FC1);
  for (int y = 0; y < depth.rows; ++y)
    for (int x = 0; x < depth.cols; ++x)
      depth.at<float>(y, x) = 1.0f / (0.4f + 0.0008f * x + 0.0005f * y);
  const Eigen::Isometry3d src = Forward(), virt = core::LookAt({0.05, 0.15, 0.1}, {1.0, 0.1, 0.0});
  WarpOptions blocks_8;
  blocks_8.planar_block = 8;
  const MeshPlan found = MeshPlanFor(depth, blocks_8);
  ASSERT_FALSE(found.runs.empty());
  MeshPlan none = found;  // the same size and options, but nothing drawn as a block
  none.runs.clear();
  std::fill(none.skip.begin(), none.skip.end(), int8_t{0});
  MeshPlan holed = none;  // and one quad planted as skipped
  holed.skip[std::size_t(100) * kCam.width + 150] = -1;
  const MeshPlan other_block = PlanMesh(depth, 4, 0.002),
                 other_tolerance = PlanMesh(depth, 8, 0.01);
  const MeshPlan other_size = PlanMesh(depth(cv::Rect(0, 0, 100, 80)).clone(), 8, 0.002);
  auto warp = [&](const MeshPlan* plan, int planar_block) {
    WarpOptions o;
    o.planar_block = planar_block;
    DepthMeshWarper warper(o);
    std::vector<WarpField> fields;
    warper.WarpMany({{&kCam, &src, &depth, plan}}, kCam, virt, fields);
    return fields[0];
  };
  const WarpField blocks = warp(nullptr, 8), quads = warp(nullptr, 0);
  ASSERT_GT(cv::norm(blocks.map, quads.map, cv::NORM_INF), 0.0);  // the two paths differ a little
  EXPECT_EQ(cv::norm(warp(&found, 8).map, blocks.map, cv::NORM_INF), 0.0);
  EXPECT_EQ(cv::norm(warp(&none, 8).map, quads.map, cv::NORM_INF), 0.0);
  EXPECT_LT(warp(&holed, 8).covered, quads.covered);
  for (const MeshPlan* ignored : {&other_block, &other_tolerance, &other_size})
    EXPECT_EQ(cv::norm(warp(ignored, 8).map, blocks.map, cv::NORM_INF), 0.0);
}

TEST(DepthMeshWarper, RunsReachingBehindTheCameraAreDrawnQuadByQuad) {
  // A tilted plane 2.2–2.6 m ahead, seen by a virtual camera standing 2 m ahead and looking
  // sideways along it: each block row is one run, which reaches behind the virtual camera and so
  // cannot be drawn as one polygon. Its quads in front must come out as without blocks.
  cv::Mat depth(kCam.height, kCam.width, CV_32FC1);
  for (int y = 0; y < depth.rows; ++y)
    for (int x = 0; x < depth.cols; ++x) depth.at<float>(y, x) = 1.0f / (0.4f + 0.0004f * x);
  ASSERT_EQ(cv::countNonZero(FindPlanarBlocks(depth, 8, 0.002)),
            PlanarGrid(kCam.width, kCam.height, 8).area());
  const BlocksAgainstQuads c =
      CompareBlocksWithQuads(depth, core::LookAt({2.0, 0.0, 0.0}, {2.3, 1.5, 0.0}));
  EXPECT_GT(c.quads.covered, kCam.width * kCam.height / 10);
  EXPECT_NEAR(c.blocks.covered, c.quads.covered, 3);
  EXPECT_LT(c.worst_px, 0.01);
}

TEST(DepthMeshWarper, AReusedWarperGivesFreshFieldsWithOrWithoutDepth) {
  // One warper, two views in turn (its z-buffer is cleared by each warp's end, not its start):
  // every field equals a fresh warper's. Without the depth output the map is the same and there
  // is no depth plane.
  cv::Mat wavy(kCam.height, kCam.width, CV_32FC1);
  for (int y = 0; y < wavy.rows; ++y)
    for (int x = 0; x < wavy.cols; ++x)
      wavy.at<float>(y, x) = 2.0f + 0.3f * std::sin(x * 0.13f) * std::cos(y * 0.05f);
  const cv::Mat flat = Constant(1.5f);
  const Eigen::Isometry3d virt = core::LookAt({0.05, -0.1, 0.05}, {1.0, 0.0, 0.1});
  const WarpField fresh_wavy = WarpView(kCam, Forward(), wavy, kCam, virt);
  const WarpField fresh_flat = WarpView(kCam, Forward(0.2), flat, kCam, virt);
  DepthMeshWarper reused;
  WarpOutputs no_depth;
  no_depth.depth = false;
  DepthMeshWarper map_only({}, no_depth);
  const Eigen::Isometry3d poses[2] = {Forward(), Forward(0.2)};
  const cv::Mat* depths[2] = {&wavy, &flat};
  const WarpField* fresh_fields[2] = {&fresh_wavy, &fresh_flat};
  for (int round = 0; round < 4; ++round) {
    const cv::Mat& depth = *depths[round % 2];
    const Eigen::Isometry3d& pose = poses[round % 2];
    const WarpField& fresh = *fresh_fields[round % 2];
    {
      WarpField w, m;
      reused.Warp(kCam, pose, depth, kCam, virt, w);
      EXPECT_EQ(w.covered, fresh.covered);
      EXPECT_EQ(cv::norm(w.depth, fresh.depth, cv::NORM_INF), 0.0);
      EXPECT_EQ(cv::norm(w.map, fresh.map, cv::NORM_INF), 0.0);
      map_only.Warp(kCam, pose, depth, kCam, virt, m);
      EXPECT_TRUE(m.depth.empty());
      EXPECT_EQ(m.covered, fresh.covered);
      EXPECT_EQ(cv::norm(m.map, fresh.map, cv::NORM_INF), 0.0);
    }
  }
  no_depth.view_angles = true;  // found from the depth, which the warper then computes as well
  EXPECT_TRUE(DepthMeshWarper({}, no_depth).outputs().depth);
  const WarpField angles = WarpView(kCam, Forward(0.2), flat, kCam, virt, {}, no_depth);
  EXPECT_EQ(cv::norm(angles.depth, fresh_flat.depth, cv::NORM_INF), 0.0);
  EXPECT_EQ(angles.cos_angle.size(), angles.depth.size());
}

TEST(DepthMeshWarper, WarpManyEqualsOneViewAtATime) {
  // Three views of a wavy surface; whole views per thread must give exactly the fields of
  // warping each view alone (the same rasteriser, only the work split differs).
  std::vector<cv::Mat> depths;
  std::vector<Eigen::Isometry3d> poses;
  for (int k = 0; k < 3; ++k) {
    cv::Mat d(kCam.height, kCam.width, CV_32FC1);
    for (int y = 0; y < d.rows; ++y)
      for (int x = 0; x < d.cols; ++x)
        d.at<float>(y, x) = 2.0f + 0.1f * k + 0.2f * std::sin(x * 0.1f + k) * std::cos(y * 0.07f);
    depths.push_back(d);
    poses.push_back(core::LookAt({0.02 * k, 0.05 * k, 0.0}, {1.0, 0.1 * k, 0.0}));
  }
  const Eigen::Isometry3d virt = core::LookAt({0.05, 0.08, 0.02}, {1.0, 0.05, 0.0});
  WarpOptions two;
  two.threads = 2;
  WarpOutputs with_source_depth;
  with_source_depth.source_depth = true;
  DepthMeshWarper many(two, with_source_depth);
  std::vector<SourceView> sources;
  for (int k = 0; k < 3; ++k) sources.push_back({&kCam, &poses[k], &depths[k]});
  std::vector<WarpField> fields;
  many.WarpMany(sources, kCam, virt, fields);
  ASSERT_EQ(fields.size(), 3u);
  WarpOptions split;  // each view alone split between three threads, merged by depth
  split.threads = 3;
  for (int k = 0; k < 3; ++k) {
    const WarpField one = WarpView(kCam, poses[k], depths[k], kCam, virt, split, with_source_depth);
    EXPECT_GT(one.covered, kCam.width * kCam.height / 3);
    EXPECT_EQ(fields[k].covered, one.covered) << k;
    EXPECT_EQ(cv::norm(fields[k].depth, one.depth, cv::NORM_INF), 0.0) << k;
    EXPECT_EQ(cv::norm(fields[k].map, one.map, cv::NORM_INF), 0.0) << k;
    EXPECT_EQ(cv::norm(fields[k].source_depth, one.source_depth, cv::NORM_INF), 0.0) << k;
  }
  // A bad view among them is reported as Warp reports it.
  cv::Mat wrong(10, 10, CV_32FC1, cv::Scalar(1));
  sources[1].depth = &wrong;
  EXPECT_THROW(many.WarpMany(sources, kCam, virt, fields), std::invalid_argument);
}

TEST(DepthMeshWarper, BadInputIsRejected) {
  Eigen::Isometry3d sheared = Forward();
  sheared.linear()(0, 1) += 0.3;
  EXPECT_THROW(WarpView(kCam, sheared, Constant(2.0f), kCam, Forward()), std::invalid_argument);
  EXPECT_THROW(WarpView(kCam, Forward(), cv::Mat(10, 10, CV_32FC1, cv::Scalar(1)), kCam, Forward()),
               std::invalid_argument);
  cv::Mat nan_depth = Constant(std::nanf(""));
  EXPECT_EQ(WarpView(kCam, Forward(), nan_depth, kCam, Forward()).covered, 0);
}

}  // namespace
}  // namespace novelty::views
