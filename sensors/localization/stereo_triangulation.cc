#include "sensors/localization/stereo_triangulation.h"

#include <opencv2/video/tracking.hpp>

namespace novelty::sensors {

std::optional<Eigen::Vector3d> Triangulate(const StereoPair& pair, const cv::Point2f& ref_px,
                                           const cv::Point2f& other_px,
                                           const StereoTriangulationOptions& o) {
  // Rays c0 + s·d0 (reference) and c1 + t·d1 (other camera), in the reference frame.
  const Eigen::Vector3d d0 = pair.reference_camera.RayCam(ref_px.x, ref_px.y).normalized();
  const Eigen::Vector3d c1 = pair.reference_from_other.translation();
  const Eigen::Vector3d d1 =
      (pair.reference_from_other.linear() * pair.other_camera.RayCam(other_px.x, other_px.y))
          .normalized();
  const double b = d0.dot(d1), denom = 1.0 - b * b;
  if (denom < 1e-12) return std::nullopt;  // parallel rays: at infinity
  const Eigen::Vector3d w = -c1;           // c0 − c1 with c0 = 0
  const double s = (b * d1.dot(w) - d0.dot(w)) / denom;
  const double t = (d1.dot(w) - b * d0.dot(w)) / denom;
  const Eigen::Vector3d p0 = s * d0, p1 = c1 + t * d1, p = (p0 + p1) / 2;
  if (!(p.z() >= o.min_depth && p.z() <= o.max_depth) || t <= 0) return std::nullopt;
  // The rays' gap seen from the other camera, in its pixels.
  const double gap_px = (p0 - p1).norm() / std::max(1e-9, t) * std::abs(pair.other_camera.fx);
  if (gap_px > o.max_epipolar_error) return std::nullopt;
  return p;
}

std::vector<std::optional<Eigen::Vector3d>> TriangulateFeatures(
    const StereoPair& pair, const cv::Mat& reference_grey, const cv::Mat& other_grey,
    const std::vector<cv::Point2f>& points, const StereoTriangulationOptions& o) {
  std::vector<std::optional<Eigen::Vector3d>> result(points.size());
  if (points.empty()) return result;
  // Initial guess: the match of a point at 2 m, so KLT starts near the right disparity.
  std::vector<cv::Point2f> guess;
  const Eigen::Isometry3d other_from_ref = pair.reference_from_other.inverse();
  for (const cv::Point2f& p : points) {
    const Eigen::Vector2d g =
        pair.other_camera.Project(other_from_ref * pair.reference_camera.Unproject(p.x, p.y, 2.0));
    guess.emplace_back(float(g.x()), float(g.y()));
  }
  std::vector<unsigned char> status;
  std::vector<float> error;
  cv::calcOpticalFlowPyrLK(
      reference_grey, other_grey, points, guess, status, error,
      cv::Size(o.klt_window, o.klt_window), o.klt_levels,
      cv::TermCriteria(cv::TermCriteria::COUNT | cv::TermCriteria::EPS, 30, 0.01),
      cv::OPTFLOW_USE_INITIAL_FLOW);
  for (size_t i = 0; i < points.size(); ++i)
    if (status[i]) result[i] = Triangulate(pair, points[i], guess[i], o);
  return result;
}

}  // namespace novelty::sensors
