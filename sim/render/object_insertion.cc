#include "sim/render/object_insertion.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "core/rigid_pose.h"
#include "sim/render/triangle_mesh.h"

namespace novelty::sim {
namespace {

constexpr int kBoxId = 1;
constexpr double kNearest = 0.1;  // m: nearer than this a box fills the view and is no test

}  // namespace

ObjectInserter::ObjectInserter(const InsertedBoxOptions& o) : options_(o) {
  if (!(o.size.minCoeff() > 0.0) || !o.size.allFinite())
    throw std::invalid_argument("inserted box: edge lengths must be positive and finite");
  if (!core::IsRigid(o.pose)) throw std::invalid_argument("inserted box: the pose is not rigid");
  scene_.AddObject(MakeBox(o.size), o.pose, o.material, kBoxId);
  scene_.Commit();
}

cv::Mat ObjectInserter::Insert(cv::Mat& rgb, cv::Mat& depth, const core::PinholeCamera& camera,
                               const Eigen::Isometry3d& T_world_cam, int frame) const {
  if (rgb.type() != CV_8UC3 || depth.type() != CV_32FC1 || rgb.size() != depth.size() ||
      rgb.cols != camera.width || rgb.rows != camera.height)
    throw std::invalid_argument("ObjectInserter::Insert: an RGB-D frame of the camera's size");
  Lighting lighting;
  lighting.ambient = options_.ambient;
  PointLight lamp;  // at the camera: every face it sees is lit, no shadow falls where it looks
  lamp.position = T_world_cam.translation();
  lamp.intensity = options_.lamp;
  lighting.points.push_back(lamp);
  RenderOptions render;
  render.noise_sigma = options_.noise_sigma;
  render.frame = std::uint64_t(frame);
  render.seed = 51;
  const RenderedFrame box = Render(scene_, lighting, camera, T_world_cam, render);
  cv::Mat mask(rgb.size(), CV_8UC1, cv::Scalar(0));
  for (int v = 0; v < rgb.rows; ++v) {
    for (int u = 0; u < rgb.cols; ++u) {
      const float z = box.depth.at<float>(v, u);
      const float seen = depth.at<float>(v, u);
      const bool unknown = !(seen > 0.0f);  // 0 or NaN
      if (box.ids.at<int>(v, u) != kBoxId || !(z > 0.0f) || (!unknown && seen <= z)) continue;
      rgb.at<cv::Vec3b>(v, u) = box.rgb.at<cv::Vec3b>(v, u);
      depth.at<float>(v, u) = z;
      mask.at<uint8_t>(v, u) = 255;
    }
  }
  return mask;
}

Eigen::Isometry3d ObjectInserter::StandInFrontOf(const cv::Mat& depth,
                                                 const core::PinholeCamera& camera,
                                                 const Eigen::Isometry3d& T_world_cam,
                                                 double standoff, const Eigen::Vector3d& size) {
  if (depth.type() != CV_32FC1 || depth.cols != camera.width || depth.rows != camera.height)
    throw std::invalid_argument("StandInFrontOf: a depth image of the camera's size");
  const int half = 10;
  if (camera.width < 2 * half + 1 || camera.height < 2 * half + 1)
    throw std::invalid_argument("StandInFrontOf: a camera of at least 21x21 pixels");
  const int u0 = std::clamp(int(std::lround(camera.cx)), half, camera.width - half - 1);
  const int v0 = std::clamp(int(std::lround(camera.cy)), half, camera.height - half - 1);
  std::vector<float> known;
  for (int v = v0 - half; v <= v0 + half; ++v)
    for (int u = u0 - half; u <= u0 + half; ++u)
      if (const float z = depth.at<float>(v, u); z > 0.0f && std::isfinite(z)) known.push_back(z);
  if (known.size() < 21 * 21 / 2)
    throw std::invalid_argument("StandInFrontOf: the centre of the frame has no depth");
  std::nth_element(known.begin(), known.begin() + long(known.size() / 2), known.end());
  const double surface = known[known.size() / 2];
  const double centre = surface - standoff - size.z() / 2;  // box depth along the camera's z
  if (!std::isfinite(centre) || centre - size.z() / 2 < kNearest)
    throw std::invalid_argument("StandInFrontOf: the surface is too near for the box");
  Eigen::Isometry3d pose = T_world_cam;
  pose.translation() = T_world_cam * camera.Unproject(camera.cx, camera.cy, centre);
  return pose;
}

}  // namespace novelty::sim
