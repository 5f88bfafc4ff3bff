#include "sim/render/renderer.h"
#include "core/rigid_pose.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

namespace novelty::sim {
namespace {

constexpr int kFloor = 1;

Material Matte(float albedo) {
  Material m;
  m.diffuse = Eigen::Vector3f::Constant(albedo);
  return m;
}

RenderOptions Exact() {  // linear, noise-free: pixel values are radiance · 255
  RenderOptions o;
  o.gamma = 1.0;
  o.noise_sigma = 0.0;
  o.threads = 2;
  return o;
}

void AddFloor(RayScene& scene, const Material& m = Matte(0.8f)) {
  scene.AddObject(MakePlane(40.0, 40.0), Eigen::Isometry3d::Identity(), m, kFloor);
}

Eigen::Isometry3d At(double x, double y, double z) {
  return Eigen::Isometry3d(Eigen::Translation3d(x, y, z));
}

TEST(Renderer, DepthOfAPlaneMatchesTheClosedForm) {
  RayScene scene;
  AddFloor(scene);
  scene.Commit();
  const core::PinholeCamera cam = core::PinholeCamera::FromFov(160, 120, 1.0);
  const Eigen::Isometry3d pose = core::LookAt({0, 0, 1.5}, {2, 0.3, 0});
  const RenderedFrame f = Render(scene, Lighting{}, cam, pose, Exact());
  int checked = 0;
  for (int v = 0; v < cam.height; ++v) {
    for (int u = 0; u < cam.width; ++u) {
      const Eigen::Vector3d d = pose.linear() * cam.RayCam(u, v);
      const double t = -1.5 / d.z();  // ray parameter where z = 0; equals depth (ray z_cam = 1)
      if (d.z() < 0 && t < 25.0) {
        EXPECT_NEAR(f.depth.at<float>(v, u), t, 2e-5 * t) << u << "," << v;
        EXPECT_EQ(f.ids.at<int>(v, u), kFloor);
        ++checked;
      }
    }
  }
  EXPECT_GT(checked, cam.width * cam.height / 2);
}

TEST(Renderer, SphereSilhouetteMatchesTheClosedForm) {
  RayScene scene;
  const double r = 0.5;
  const Eigen::Vector3d c(3, 0.2, 1.0);
  scene.AddObject(MakeSphere(r, 96, 48), At(c.x(), c.y(), c.z()), Matte(0.5f), 4);
  scene.Commit();
  const core::PinholeCamera cam = core::PinholeCamera::FromFov(200, 150, 0.6);
  const Eigen::Isometry3d pose = core::LookAt({0, 0, 1.0}, {3, 0, 1.0});
  const RenderedFrame f = Render(scene, Lighting{}, cam, pose, Exact());
  // The tessellated sphere lies between r·cos²(π/48) and r; outside that band the answer is sure.
  const double inner = r * std::pow(std::cos(M_PI / 48), 2);
  int inside = 0, band = 0;
  for (int v = 0; v < cam.height; ++v) {
    for (int u = 0; u < cam.width; ++u) {
      const Eigen::Vector3d d = (pose.linear() * cam.RayCam(u, v)).normalized();
      const Eigen::Vector3d oc = c - pose.translation();
      const double dist = (oc - oc.dot(d) * d).norm();  // distance of the centre from the ray
      const int id = f.ids.at<int>(v, u);
      if (dist < inner) {
        EXPECT_EQ(id, 4) << u << "," << v;
        ++inside;
      } else if (dist > r) {
        EXPECT_EQ(id, RayHit::kNoObject) << u << "," << v;
        EXPECT_EQ(f.depth.at<float>(v, u), 0.0f);
      } else {
        ++band;
      }
    }
  }
  EXPECT_GT(inside, 1000);
  EXPECT_LT(band, inside / 20);
}

// pixel_samples: a black sphere before a white background. One ray per pixel gives only black or
// white; a 4 × 4 grid gives the covered fraction at the silhouette (a box filter), while depth
// and ids still come from the pixel centre.
TEST(Renderer, PixelSamplesAverageOverThePixelArea) {
  RayScene scene;
  scene.AddObject(MakeSphere(0.5, 96, 48), At(3, 0.2, 1.0), Matte(0.0f), 4);
  scene.Commit();
  const core::PinholeCamera cam = core::PinholeCamera::FromFov(200, 150, 0.6);
  const Eigen::Isometry3d pose = core::LookAt({0, 0, 1.0}, {3, 0, 1.0});
  RenderOptions o = Exact();
  o.background = Eigen::Vector3f::Ones();
  const RenderedFrame one = Render(scene, Lighting{}, cam, pose, o);
  o.pixel_samples = 4;
  const RenderedFrame grid = Render(scene, Lighting{}, cam, pose, o);
  int mixed_one = 0, mixed_grid = 0;
  double sum_one = 0, sum_grid = 0;
  for (int v = 0; v < cam.height; ++v)
    for (int u = 0; u < cam.width; ++u) {
      const int a = one.rgb.at<cv::Vec3b>(v, u)[0], b = grid.rgb.at<cv::Vec3b>(v, u)[0];
      mixed_one += a != 0 && a != 255;
      mixed_grid += b != 0 && b != 255;
      sum_one += a, sum_grid += b;
      ASSERT_EQ(one.ids.at<int>(v, u), grid.ids.at<int>(v, u));
      ASSERT_EQ(one.depth.at<float>(v, u), grid.depth.at<float>(v, u));
    }
  EXPECT_EQ(mixed_one, 0);
  EXPECT_GT(mixed_grid, 100);  // the silhouette's pixels
  // Same covered area on average: the filter moves no edge, it only grades it.
  EXPECT_NEAR(sum_grid / sum_one, 1.0, 0.005);
}

// Slab test: does the segment p → q cross the axis-aligned box [lo, hi]?
bool SegmentHitsBox(const Eigen::Vector3d& p, const Eigen::Vector3d& q, const Eigen::Vector3d& lo,
                    const Eigen::Vector3d& hi) {
  double t0 = 0.0, t1 = 1.0;
  const Eigen::Vector3d d = q - p;
  for (int k = 0; k < 3; ++k) {
    if (std::abs(d[k]) < 1e-15) {
      if (p[k] < lo[k] || p[k] > hi[k]) return false;
      continue;
    }
    double a = (lo[k] - p[k]) / d[k], b = (hi[k] - p[k]) / d[k];
    if (a > b) std::swap(a, b);
    t0 = std::max(t0, a);
    t1 = std::min(t1, b);
  }
  return t0 <= t1;
}

TEST(Renderer, ShadowIsExactlyWhereTheOccluderBlocksTheLamp) {
  RayScene scene;
  AddFloor(scene, Matte(1.0f));
  const Eigen::Vector3d box_c(2.0, 0.0, 0.8), box_size(0.4, 0.3, 0.05);
  scene.AddObject(MakeBox(box_size), At(box_c.x(), box_c.y(), box_c.z()), Matte(0.5f), 2);
  scene.Commit();
  Lighting light;
  light.ambient = Eigen::Vector3f::Constant(0.1f);
  light.points.push_back({{2.3, 0.2, 2.5}, Eigen::Vector3f::Constant(2.0f), 0.0});
  const core::PinholeCamera cam = core::PinholeCamera::FromFov(240, 180, 0.9);
  const Eigen::Isometry3d pose = core::LookAt({0, 0, 2.0}, {2.4, 0, 0});
  const RenderedFrame f = Render(scene, light, cam, pose, Exact());
  int floor_pixels = 0, shadow_pixels = 0, wrong = 0;
  for (int v = 0; v < cam.height; ++v) {
    for (int u = 0; u < cam.width; ++u) {
      if (f.ids.at<int>(v, u) != kFloor) continue;
      const Eigen::Vector3d d = pose.linear() * cam.RayCam(u, v);
      const Eigen::Vector3d p = pose.translation() + f.depth.at<float>(v, u) * d;
      const bool shadow =
          SegmentHitsBox(p, light.points[0].position, box_c - box_size / 2, box_c + box_size / 2);
      // In shadow only the ambient term remains: 0.1 · 255 = 25.5.
      const bool dark = f.rgb.at<cv::Vec3b>(v, u)[0] <= 26;
      ++floor_pixels;
      shadow_pixels += shadow;
      wrong += shadow != dark;
    }
  }
  EXPECT_GT(shadow_pixels, 300);
  EXPECT_LE(wrong, floor_pixels / 1000) << wrong << " of " << floor_pixels << " floor pixels";
}

TEST(Renderer, HighlightIsWhereTheLawOfReflectionPutsIt) {
  RayScene scene;
  Material mirror_like;
  mirror_like.diffuse.setZero();
  mirror_like.specular = 1.0f;
  mirror_like.shininess = 20000.0f;
  AddFloor(scene, mirror_like);
  scene.Commit();
  Lighting light;
  light.ambient.setZero();
  const Eigen::Vector3d lamp(2.0, 0.3, 1.5), eye(0, 0, 1.2);
  light.points.push_back({lamp, Eigen::Vector3f::Constant(1.0f), 0.0});
  const core::PinholeCamera cam = core::PinholeCamera::FromFov(320, 240, 1.0);
  const Eigen::Isometry3d pose = core::LookAt(eye, {1.3, -0.2, 0});
  RenderOptions o = Exact();
  o.exposure = 4.0;
  const RenderedFrame f = Render(scene, light, cam, pose, o);
  // The mirror image of the lamp below the floor, seen from the eye, meets the floor at p.
  const Eigen::Vector3d mirrored(lamp.x(), lamp.y(), -lamp.z());
  const Eigen::Vector3d p = eye + eye.z() / (eye.z() + lamp.z()) * (mirrored - eye);
  const Eigen::Vector2d expected = cam.Project(pose.inverse() * p);
  cv::Mat grey;
  cv::extractChannel(f.rgb, grey, 0);
  cv::Point peak;
  double max_value;
  cv::minMaxLoc(grey, nullptr, &max_value, nullptr, &peak);
  EXPECT_GT(max_value, 100.0);
  EXPECT_NEAR(peak.x, expected.x(), 1.0);
  EXPECT_NEAR(peak.y, expected.y(), 1.0);
}

TEST(Renderer, PhongShadingOfALitPlaneMatchesTheFormula) {
  RayScene scene;
  AddFloor(scene, Matte(0.7f));
  scene.Commit();
  Lighting light;
  light.ambient = Eigen::Vector3f::Constant(0.05f);
  light.points.push_back({{1.0, 0.0, 2.0}, Eigen::Vector3f(1.0f, 0.5f, 0.25f), 0.0});
  const Eigen::Vector3d x(1.5, 0.4, 0.0), origin(0, 0, 1);
  const Eigen::Vector3f got = TraceRadiance(scene, light, origin, x - origin, Exact());
  const Eigen::Vector3d to = light.points[0].position - x;
  const double cos_term = to.normalized().z();
  for (int k = 0; k < 3; ++k) {
    const double expected =
        0.7 * (0.05 + cos_term * light.points[0].intensity[k] / to.squaredNorm());
    EXPECT_NEAR(got[k], expected, 1e-5) << "channel " << k;
  }
}

TEST(Renderer, ObjectIdsAndDepthAgree) {
  RayScene scene;
  AddFloor(scene);
  scene.AddObject(MakeBox({0.3, 0.3, 0.3}), At(2.0, 0.4, 0.15), Matte(0.3f), 7);
  scene.AddObject(MakeCylinder(0.1, 0.3), At(2.0, -0.4, 0.15), Matte(0.9f), 9);
  scene.Commit();
  const core::PinholeCamera cam = core::PinholeCamera::FromFov(160, 120, 1.0);
  const Eigen::Isometry3d pose = core::LookAt({0, 0, 1.0}, {2, 0, 0.15});
  const RenderedFrame f = Render(scene, Lighting{}, cam, pose, Exact());
  for (const auto& [id, centre] : {std::pair{7, Eigen::Vector3d(2.0, 0.4, 0.15)},
                                   std::pair{9, Eigen::Vector3d(2.0, -0.4, 0.15)}}) {
    const Eigen::Vector2d px = cam.Project(pose.inverse() * centre);
    EXPECT_EQ(f.ids.at<int>(int(std::lround(px.y())), int(std::lround(px.x()))), id);
  }
  for (int i = 0; i < cam.width * cam.height; ++i) {
    EXPECT_EQ(f.ids.at<int>(i) != RayHit::kNoObject, f.depth.at<float>(i) > 0.0f);
  }
}

Lighting TwoLamps() {
  Lighting l;
  l.points.push_back({{1.0, 1.0, 2.5}, {1.5f, 1.2f, 1.0f}, 0.15});  // soft
  l.points.push_back({{1.0, -1.0, 2.0}, {0.4f, 0.4f, 0.8f}, 0.0});
  return l;
}

TEST(Renderer, BitIdenticalForTheSameSeedWhateverTheThreads) {
  RayScene scene;
  AddFloor(scene);
  scene.AddObject(MakeSphere(0.2), At(2.0, 0.0, 0.2), Matte(0.6f), 3);
  scene.Commit();
  const core::PinholeCamera cam = core::PinholeCamera::FromFov(96, 72, 1.0);
  const Eigen::Isometry3d pose = core::LookAt({0, 0, 1.0}, {2, 0, 0});
  RenderOptions o;
  o.seed = 42;
  o.threads = 1;
  const RenderedFrame a = Render(scene, TwoLamps(), cam, pose, o);
  o.threads = 2;
  const RenderedFrame b = Render(scene, TwoLamps(), cam, pose, o);
  o.seed = 43;
  const RenderedFrame c = Render(scene, TwoLamps(), cam, pose, o);
  EXPECT_EQ(cv::norm(a.rgb, b.rgb, cv::NORM_INF), 0.0);
  EXPECT_EQ(cv::norm(a.depth, b.depth, cv::NORM_INF), 0.0);
  EXPECT_GT(cv::norm(a.rgb, c.rgb, cv::NORM_L1), 0.0);  // noise differs with the seed
}

TEST(Renderer, GlassRefractsAndCastsNoShadow) {
  RayScene scene;
  Material checker = Matte(0.9f);
  checker.texture.kind = Texture::Kind::kChecker;
  checker.texture.cells = 1.0f;  // one square per texture tile: 5 cm squares (plane tile 0.05)
  scene.AddObject(MakePlane(4.0, 4.0, 0.05), At(2.0, 0.0, 0.0), checker, kFloor);
  Material glass;
  glass.kind = Material::Kind::kGlass;
  glass.diffuse = Eigen::Vector3f::Constant(0.95f);
  scene.AddObject(MakeSphere(0.15, 64, 32), At(2.0, 0.0, 0.3), glass, 5);
  scene.Commit();
  Lighting light;
  light.points.push_back({{2.0, 0.0, 2.0}, Eigen::Vector3f::Constant(2.0f), 0.0});
  // Straight below the lamp, under the glass sphere: lit (glass casts no shadow).
  const RenderOptions o = Exact();
  EXPECT_FALSE(scene.Occluded({2.0, 0.0, 0.0}, {0, 0, 1}, 1e-4, 2.0));
  // A ray through the sphere's centre is not deflected: it reaches the same floor point, seen
  // through two air-glass interfaces (transmission (1 − R0)² · tint²).
  const Eigen::Vector3d eye(2.0, 0.0, 1.0), floor_point(2.0, 0.0, 0.0);
  const Eigen::Vector3f through = TraceRadiance(scene, light, eye, floor_point - eye, o);
  const double r0 = std::pow(0.5 / 2.5, 2.0);
  const double expected = 0.9 * (0.05 + 2.0 / 4.0) * std::pow((1 - r0) * 0.95, 2.0);
  EXPECT_NEAR(through[0], expected, 0.02 * expected);
}

TEST(Renderer, BadPoseAndCameraAreRejected) {
  RayScene scene;
  scene.Commit();
  Eigen::Isometry3d bad = Eigen::Isometry3d::Identity();
  bad.linear() *= 2.0;
  EXPECT_THROW(Render(scene, Lighting{}, core::PinholeCamera{}, bad), std::invalid_argument);
  core::PinholeCamera cam;
  cam.width = 0;
  EXPECT_THROW(Render(scene, Lighting{}, cam, Eigen::Isometry3d::Identity()),
               std::invalid_argument);
}

}  // namespace
}  // namespace novelty::sim
