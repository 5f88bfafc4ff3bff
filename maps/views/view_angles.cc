#include "maps/views/view_angles.h"

#include <cmath>

namespace novelty::views {

void ViewAngles(const cv::Mat& depth, const core::PinholeCamera& cam, const Eigen::Vector3d& source,
                cv::Mat& cos_angle) {
  cos_angle.create(depth.size(), CV_32FC1);
  const float cx = float(source.x()), cy = float(source.y()), cz = float(source.z());
  const float ifx = float(1.0 / cam.fx), ify = float(1.0 / cam.fy);
  const float ox = float(cam.cx), oy = float(cam.cy);
  for (int y = 0; y < depth.rows; ++y) {
    const float* z = depth.ptr<float>(y);
    float* out = cos_angle.ptr<float>(y);
    const float ry = (float(y) - oy) * ify;
    for (int x = 0; x < depth.cols; ++x) {
      const float rx = (float(x) - ox) * ifx;
      const float px = z[x] * rx, py = z[x] * ry, pz = z[x];  // the surface point
      const float qx = px - cx, qy = py - cy, qz = pz - cz;   // … seen from the source
      const float dot = px * qx + py * qy + pz * qz;
      const float norms = (px * px + py * py + pz * pz) * (qx * qx + qy * qy + qz * qz);
      out[x] = z[x] > 0.0f ? dot / std::sqrt(norms) : 0.0f;
    }
  }
}

}  // namespace novelty::views
