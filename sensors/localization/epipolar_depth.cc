#include "sensors/localization/epipolar_depth.h"

#include <cmath>
#include <limits>
#include <opencv2/imgproc.hpp>

#include "sensors/localization/bilinear_sample.h"

namespace novelty::sensors {
namespace {

// The search segment in the other image for reference pixel `px`: from the far depth's
// projection to the near depth's; false if either lies behind the other camera.
bool EpipolarSegment(const StereoPair& pair, const Eigen::Isometry3d& other_from_ref,
                     const cv::Point2f& px, const StereoTriangulationOptions& range,
                     Eigen::Vector2d& far, Eigen::Vector2d& near) {
  const Eigen::Vector3d pf = other_from_ref * pair.reference_camera.Unproject(px.x, px.y,
                                                                              range.max_depth);
  const Eigen::Vector3d pn = other_from_ref * pair.reference_camera.Unproject(px.x, px.y,
                                                                              range.min_depth);
  if (pf.z() <= 1e-6 || pn.z() <= 1e-6) return false;
  far = pair.other_camera.Project(pf);
  near = pair.other_camera.Project(pn);
  return true;
}

// Clips the segment a→b to the part where a patch of radius r fits inside the image.
bool ClipToImage(Eigen::Vector2d& a, Eigen::Vector2d& b, int width, int height, int r) {
  const double lo_x = r, hi_x = width - 2 - r, lo_y = r, hi_y = height - 2 - r;
  double t0 = 0, t1 = 1;
  const Eigen::Vector2d d = b - a;
  auto clip = [&](double p, double q) {  // Liang–Barsky
    if (std::abs(p) < 1e-12) return q >= 0;
    const double t = q / p;
    if (p < 0) t0 = std::max(t0, t);
    else t1 = std::min(t1, t);
    return t0 <= t1;
  };
  if (!clip(-d.x(), a.x() - lo_x) || !clip(d.x(), hi_x - a.x()) || !clip(-d.y(), a.y() - lo_y) ||
      !clip(d.y(), hi_y - a.y()))
    return false;
  const Eigen::Vector2d a0 = a;
  a = a0 + t0 * d;
  b = a0 + t1 * d;
  return true;
}

}  // namespace

std::vector<EpipolarPoint> EpipolarDepths(const StereoPair& pair, const cv::Mat& reference,
                                          const cv::Mat& other,
                                          const EpipolarDepthOptions& o) {
  CV_Assert(reference.type() == CV_32F && other.type() == CV_32F);
  const Eigen::Isometry3d other_from_ref = pair.reference_from_other.inverse();
  cv::Mat gx, gy;
  cv::Sobel(reference, gx, CV_32F, 1, 0, 3, 1.0 / 8);
  cv::Sobel(reference, gy, CV_32F, 0, 1, 3, 1.0 / 8);
  const int r = o.patch_radius, border = r + 1;
  std::vector<EpipolarPoint> result;
  for (int by = border; by + o.block <= reference.rows - border; by += o.block)
    for (int bx = border; bx + o.block <= reference.cols - border; bx += o.block) {
      // The block's pixel with the strongest gradient along its epipolar direction.
      float best_g = float(o.min_epipolar_gradient);
      cv::Point2f best(-1, -1);
      Eigen::Vector2d best_far, best_near;
      for (int y = by; y < by + o.block; ++y)
        for (int x = bx; x < bx + o.block; ++x) {
          Eigen::Vector2d far, near;
          const cv::Point2f px{float(x), float(y)};
          if (!EpipolarSegment(pair, other_from_ref, px, o.range, far, near)) continue;
          const Eigen::Vector2d e = (near - far).normalized();
          const float g = float(std::abs(gx.at<float>(y, x) * e.x() + gy.at<float>(y, x) * e.y()));
          if (g <= best_g) continue;
          best_g = g, best = px, best_far = far, best_near = near;
        }
      if (best.x < 0) continue;
      if (!ClipToImage(best_far, best_near, other.cols, other.rows, r)) continue;
      // SSD at one-pixel steps along the segment.
      const Eigen::Vector2d d = best_near - best_far;
      const int steps = int(std::ceil(d.norm()));
      if (steps < 3) continue;
      const Eigen::Vector2d step = d / steps;
      std::vector<float> cost(steps + 1);
      for (int s = 0; s <= steps; ++s) {
        const Eigen::Vector2d q = best_far + s * step;
        float ssd = 0;
        for (int dy = -r; dy <= r; ++dy)
          for (int dx = -r; dx <= r; ++dx) {
            const float diff = reference.at<float>(int(best.y) + dy, int(best.x) + dx) -
                               SampleBilinear(other, float(q.x()) + dx, float(q.y()) + dy);
            ssd += diff * diff;
          }
        cost[s] = ssd;
      }
      int s_best = 0;
      for (int s = 1; s <= steps; ++s)
        if (cost[s] < cost[s_best]) s_best = s;
      float second = std::numeric_limits<float>::max();
      for (int s = 0; s <= steps; ++s)
        if (std::abs(s - s_best) > 2) second = std::min(second, cost[s]);
      const float n = float((2 * r + 1) * (2 * r + 1));
      if (s_best == 0 || s_best == steps || cost[s_best] > o.max_mean_ssd * n ||
          cost[s_best] > o.uniqueness * second)
        continue;
      // eq. of the parabola through the three costs around the minimum.
      const float c0 = cost[s_best - 1], c1 = cost[s_best], c2 = cost[s_best + 1];
      const float denom = c0 - 2 * c1 + c2;
      const float sub = denom > 0 ? 0.5f * (c0 - c2) / denom : 0.f;
      const Eigen::Vector2d q = best_far + (s_best + sub) * step;
      const auto p = Triangulate(pair, best, cv::Point2f(float(q.x()), float(q.y())), o.range);
      if (!p) continue;
      result.push_back({best, float(p->z())});
    }
  return result;
}

}  // namespace novelty::sensors
