#include "core/pinhole_camera.h"

#include <cmath>
#include <stdexcept>
#include <string>

namespace novelty::core {

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

}  // namespace novelty::core
