#include "sensors/localization/photometric_alignment.h"

#include <gtest/gtest.h>

#include <cmath>
#include <opencv2/imgproc.hpp>

#include "tests/sensors/blurred_noise.h"

namespace novelty::sensors {
namespace {

constexpr double kPlaneDepth = 1.5;

core::PinholeCamera Camera() {
  return core::PinholeCamera::FromFov(320, 240, M_PI / 3);
}

cv::Mat AlignmentTexture() {
  return BlurredNoise({320, 240}, CV_32F, 11, 2.0, 20, 235);
}

// What a camera at T_kf_cur sees of the keyframe's fronto-parallel plane z = kPlaneDepth
// textured with the keyframe image.
cv::Mat SeenFrom(const cv::Mat& keyframe, const Eigen::Isometry3d& kf_from_cur) {
  const core::PinholeCamera c = Camera();
  cv::Mat map_x(keyframe.size(), CV_32F), map_y(keyframe.size(), CV_32F);
  for (int v = 0; v < keyframe.rows; ++v)
    for (int u = 0; u < keyframe.cols; ++u) {
      const Eigen::Vector3d dir = kf_from_cur.linear() * c.RayCam(u, v);
      const double s = (kPlaneDepth - kf_from_cur.translation().z()) / dir.z();
      const Eigen::Vector2d px = c.Project(kf_from_cur.translation() + s * dir);
      map_x.at<float>(v, u) = float(px.x());
      map_y.at<float>(v, u) = float(px.y());
    }
  cv::Mat seen;
  cv::remap(keyframe, seen, map_x, map_y, cv::INTER_CUBIC, cv::BORDER_REFLECT);
  return seen;
}

// The keyframe's points: pixels of strong gradient on a 3-pixel grid, on the plane.
void PlanePoints(const cv::Mat& keyframe, std::vector<Eigen::Vector3d>& points,
                 std::vector<cv::Point2f>& px) {
  cv::Mat gx, gy;
  cv::Sobel(keyframe, gx, CV_32F, 1, 0, 3, 1.0 / 8);
  cv::Sobel(keyframe, gy, CV_32F, 0, 1, 3, 1.0 / 8);
  for (int v = 8; v < keyframe.rows - 8; v += 3)
    for (int u = 8; u < keyframe.cols - 8; u += 3)
      if (std::hypot(gx.at<float>(v, u), gy.at<float>(v, u)) > 4) {
        points.push_back(Camera().Unproject(u, v, kPlaneDepth));
        px.emplace_back(float(u), float(v));
      }
}

Eigen::Isometry3d SomeMotion() {  // T_kf_cur: 2° about a skew axis, 4 cm
  Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
  t.linear() = Eigen::AngleAxisd(2.0 * M_PI / 180, Eigen::Vector3d(0.3, 1, 0.2).normalized())
                   .toRotationMatrix();
  t.translation() = Eigen::Vector3d(0.03, -0.01, 0.025);
  return t;
}

void ExpectNear(const Eigen::Isometry3d& a, const Eigen::Isometry3d& b, double mm, double deg) {
  const Eigen::Isometry3d e = a * b.inverse();
  EXPECT_LT(1000 * e.translation().norm(), mm);
  EXPECT_LT(Eigen::AngleAxisd(e.linear()).angle() * 180 / M_PI, deg);
}

// The keyframe (the textured plane), its points, and what the camera sees after SomeMotion().
struct MovedPlane {
  cv::Mat image = AlignmentTexture();
  Eigen::Isometry3d kf_from_cur = SomeMotion();
  GradientPyramid keyframe = GradientPyramid::Build(image, 3);
  GradientPyramid current = GradientPyramid::Build(SeenFrom(image, kf_from_cur), 3);
  std::vector<Eigen::Vector3d> points;
  std::vector<cv::Point2f> px;
  MovedPlane() { PlanePoints(image, points, px); }
};

TEST(AlignPhotometric, RecoversAKnownMotionFromIdentity) {
  const MovedPlane m;
  ASSERT_GT(m.points.size(), 2000u);
  const auto r = AlignPhotometric(m.points, m.px, m.keyframe, m.current, Camera(),
                                  Eigen::Isometry3d::Identity());
  ExpectNear(r.current_from_keyframe, m.kf_from_cur.inverse(), 0.5, 0.01);
  EXPECT_LT(r.rms, 1.0);  // grey levels: only interpolation differs
  EXPECT_GT(r.inlier_fraction, 0.99);
  EXPECT_GT(r.visible, int(m.points.size() * 8 / 10));
}

TEST(AlignPhotometric, ReturnsARotationFromAStartThatIsNotQuiteOne) {
  const MovedPlane m;
  Eigen::Isometry3d start = m.kf_from_cur.inverse();
  start.linear() *= 1.01;  // what compounding rounding does to a prediction
  const auto r = AlignPhotometric(m.points, m.px, m.keyframe, m.current, Camera(), start);
  const Eigen::Matrix3d rt = r.current_from_keyframe.linear();
  EXPECT_LT((rt.transpose() * rt - Eigen::Matrix3d::Identity()).norm(), 1e-9);
  ExpectNear(r.current_from_keyframe, m.kf_from_cur.inverse(), 0.5, 0.01);
}

// The odometry starts each frame from a prediction close to the pose (here 0.5° and 1 cm off);
// from there the second camera's residuals pull to the same pose.
TEST(AlignPhotometric, UsesASecondCameraOfTheRigWithItsOffset) {
  const MovedPlane m;
  Eigen::Isometry3d cur_from_other = Eigen::Isometry3d::Identity();
  cur_from_other.translation() = Eigen::Vector3d(0.12, 0, 0);  // a stereo rig's right camera
  const GradientPyramid other =
      GradientPyramid::Build(SeenFrom(m.image, m.kf_from_cur * cur_from_other), 3);
  Eigen::Isometry3d off = Eigen::Isometry3d::Identity();
  off.linear() = Eigen::AngleAxisd(0.5 * M_PI / 180, Eigen::Vector3d::UnitY()).toRotationMatrix();
  off.translation() = Eigen::Vector3d(0.01, 0, 0);
  const Eigen::Isometry3d start = off * m.kf_from_cur.inverse();
  const AlignmentView other_view{&other, Camera(), cur_from_other.inverse()};
  const auto only_other = AlignPhotometric(m.points, m.px, m.keyframe, {other_view}, start);
  ExpectNear(only_other.current_from_keyframe, m.kf_from_cur.inverse(), 1.0, 0.03);
  const auto both =
      AlignPhotometric(m.points, m.px, m.keyframe, {{&m.current, Camera()}, other_view}, start);
  ExpectNear(both.current_from_keyframe, m.kf_from_cur.inverse(), 1.0, 0.03);
  EXPECT_LT(both.rms, 1.0);  // both views' residuals vanish: the offset is applied right
  // The other view taken for the reference camera's: residuals neither pose can explain.
  const auto wrong = AlignPhotometric(m.points, m.px, m.keyframe,
                                      {{&m.current, Camera()}, {&other, Camera()}}, start);
  EXPECT_GT(wrong.rms, 5.0);
}

TEST(GradientPyramid, KeepsPixelCentresAtHalvedCoordinatesWithGradientsPerLevelPixel) {
  // A linear ramp I = 2x + 3y: level l samples it at 2^l·(x, y), so its gradients are 2^l·(2, 3).
  cv::Mat ramp(64, 96, CV_32F);
  for (int y = 0; y < ramp.rows; ++y)
    for (int x = 0; x < ramp.cols; ++x) ramp.at<float>(y, x) = float(2 * x + 3 * y);
  const GradientPyramid p = GradientPyramid::Build(ramp, 3);
  ASSERT_EQ(p.image.size(), 3u);
  EXPECT_EQ(p.image[2].size(), cv::Size(24, 16));
  for (int l = 0; l < 3; ++l) {
    const float s = float(1 << l);
    EXPECT_NEAR(p.image[l].at<float>(5, 7), 2 * 7 * s + 3 * 5 * s, 1e-3) << "level " << l;
    EXPECT_NEAR(p.gx[l].at<float>(5, 7), 2 * s, 1e-4) << "level " << l;
    EXPECT_NEAR(p.gy[l].at<float>(5, 7), 3 * s, 1e-4) << "level " << l;
  }
}

}  // namespace
}  // namespace novelty::sensors
