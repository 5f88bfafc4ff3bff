#include "maps/views/pinhole_camera.h"

#include <cmath>
#include <stdexcept>
#include <string>

namespace novelty::views {

PinholeCamera PinholeCamera::FromFov(int width, int height, double horizontal_fov_rad) {
  PinholeCamera c;
  c.width = width;
  c.height = height;
  c.fx = c.fy = 0.5 * width / std::tan(0.5 * horizontal_fov_rad);
  c.cx = 0.5 * (width - 1);
  c.cy = 0.5 * (height - 1);
  return c;
}

Eigen::Vector3d PinholeCamera::RayCam(double u, double v) const {
  return {(u - cx) / fx, (v - cy) / fy, 1.0};
}

Eigen::Vector2d PinholeCamera::Project(const Eigen::Vector3d& p) const {
  return {fx * p.x() / p.z() + cx, fy * p.y() / p.z() + cy};
}

void PinholeCamera::Check() const {
  if (width <= 0 || height <= 0 || !std::isfinite(fx) || !std::isfinite(fy) || fx == 0.0 ||
      fy == 0.0 || !std::isfinite(cx) || !std::isfinite(cy)) {
    throw std::invalid_argument(
        "PinholeCamera: need a positive size and finite, non-zero focal "
        "lengths, got " +
        std::to_string(width) + "x" + std::to_string(height) + " fx=" + std::to_string(fx) +
        " fy=" + std::to_string(fy));
  }
}

Eigen::Isometry3d LookAt(const Eigen::Vector3d& eye, const Eigen::Vector3d& target) {
  const Eigen::Vector3d z = target - eye;
  if (z.norm() < 1e-12) throw std::invalid_argument("LookAt: eye and target coincide");
  const Eigen::Vector3d zc = z.normalized();
  const Eigen::Vector3d xc = zc.cross(Eigen::Vector3d::UnitZ());  // right = forward × up
  if (xc.norm() < 1e-9) throw std::invalid_argument("LookAt: view direction is vertical");
  Eigen::Matrix3d r;
  r.col(0) = xc.normalized();
  r.col(2) = zc;
  r.col(1) = zc.cross(r.col(0));  // down
  Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
  t.linear() = r;
  t.translation() = eye;
  return t;
}

}  // namespace novelty::views
