#include "sensors/localization/epipolar_depth.h"

#include <cmath>
#include <limits>
#include <opencv2/imgproc.hpp>
#include <optional>

#include "sensors/localization/bilinear_sample.h"

namespace novelty::sensors {
namespace {

// The search segment in the `to` image for pixel `px` of the `from` camera: from the far
// depth's projection to the near depth's; false if either lies behind the `to` camera.
bool EpipolarSegment(const core::PinholeCamera& from, const core::PinholeCamera& to,
                     const Eigen::Isometry3d& to_from_from, const cv::Point2f& px,
                     const StereoTriangulationOptions& range, Eigen::Vector2d& far,
                     Eigen::Vector2d& near) {
  const Eigen::Vector3d pf = to_from_from * from.Unproject(px.x, px.y, range.max_depth);
  const Eigen::Vector3d pn = to_from_from * from.Unproject(px.x, px.y, range.min_depth);
  if (pf.z() <= 1e-6 || pn.z() <= 1e-6) return false;
  far = to.Project(pf);
  near = to.Project(pn);
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
    if (p < 0)
      t0 = std::max(t0, t);
    else
      t1 = std::min(t1, t);
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

// The sub-pixel position along far→near in `to` whose patch best matches the patch around
// `at` in `from` (SSD at one-pixel steps, uniqueness test, parabola through the best three);
// nullopt when there is no clear, good match.
std::optional<Eigen::Vector2d> SearchSegment(const cv::Mat& from, const cv::Point2f& at,
                                             const cv::Mat& to, Eigen::Vector2d far,
                                             Eigen::Vector2d near, const EpipolarDepthOptions& o) {
  const int r = o.patch_radius;
  if (at.x < r || at.y < r || at.x >= from.cols - 1 - r || at.y >= from.rows - 1 - r)
    return std::nullopt;
  if (!ClipToImage(far, near, to.cols, to.rows, r)) return std::nullopt;
  const Eigen::Vector2d d = near - far;
  const int steps = int(std::ceil(d.norm()));
  if (steps < 3) return std::nullopt;
  const Eigen::Vector2d step = d / steps;
  std::vector<float> patch;
  for (int dy = -r; dy <= r; ++dy)
    for (int dx = -r; dx <= r; ++dx) patch.push_back(SampleBilinear(from, at.x + dx, at.y + dy));
  std::vector<float> cost(steps + 1);
  for (int s = 0; s <= steps; ++s) {
    const Eigen::Vector2d q = far + s * step;
    float ssd = 0;
    for (int dy = -r, k = 0; dy <= r; ++dy)
      for (int dx = -r; dx <= r; ++dx, ++k) {
        const float diff = patch[k] - SampleBilinear(to, float(q.x()) + dx, float(q.y()) + dy);
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
  if (s_best == 0 || s_best == steps || cost[s_best] > o.max_mean_ssd * float(patch.size()) ||
      cost[s_best] > o.uniqueness * second)
    return std::nullopt;
  const float c0 = cost[s_best - 1], c1 = cost[s_best], c2 = cost[s_best + 1];
  const float denom = c0 - 2 * c1 + c2;
  const float sub = denom > 0 ? 0.5f * (c0 - c2) / denom : 0.f;
  return far + (s_best + sub) * step;
}

}  // namespace

std::vector<EpipolarPoint> EpipolarDepths(const StereoPair& pair, const cv::Mat& reference,
                                          const cv::Mat& other, const EpipolarDepthOptions& o) {
  CV_Assert(reference.type() == CV_32F && other.type() == CV_32F);
  const Eigen::Isometry3d other_from_ref = pair.reference_from_other.inverse();
  cv::Mat gx, gy;
  cv::Sobel(reference, gx, CV_32F, 1, 0, 3, 1.0 / 8);
  cv::Sobel(reference, gy, CV_32F, 0, 1, 3, 1.0 / 8);
  const int border = o.patch_radius + 1;
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
          if (!EpipolarSegment(pair.reference_camera, pair.other_camera, other_from_ref, px,
                               o.range, far, near))
            continue;
          const Eigen::Vector2d e = (near - far).normalized();
          const float g = float(std::abs(gx.at<float>(y, x) * e.x() + gy.at<float>(y, x) * e.y()));
          if (g <= best_g) continue;
          best_g = g, best = px, best_far = far, best_near = near;
        }
      if (best.x < 0) continue;
      const auto q = SearchSegment(reference, best, other, best_far, best_near, o);
      if (!q) continue;
      const cv::Point2f matched{float(q->x()), float(q->y())};
      if (o.max_left_right_px > 0) {
        // Back from the match into the reference image: a patch straddling an occluding edge
        // (background seen past the object differently by the two cameras) does not come back.
        Eigen::Vector2d back_far, back_near;
        if (!EpipolarSegment(pair.other_camera, pair.reference_camera, pair.reference_from_other,
                             matched, o.range, back_far, back_near))
          continue;
        const auto back = SearchSegment(other, matched, reference, back_far, back_near, o);
        if (!back || (*back - Eigen::Vector2d(best.x, best.y)).norm() > o.max_left_right_px)
          continue;
      }
      const auto p = Triangulate(pair, best, matched, o.range);
      if (!p) continue;
      result.push_back({best, float(p->z())});
    }
  return result;
}

}  // namespace novelty::sensors
