#include "maps/objects/keypoint_consistency.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "core/nearest_pixel.h"

namespace novelty::objects {

double MetricSize(const cv::KeyPoint& keypoint, double depth, const core::PinholeCamera& camera) {
  if (!(std::isfinite(depth) && depth > 0.0)) return std::nan("");
  return double(keypoint.size) * depth / std::abs(camera.fx);
}

std::vector<double> MetricSizes(const std::vector<cv::KeyPoint>& keypoints, const cv::Mat& depth,
                                const core::PinholeCamera& camera) {
  if (!depth.empty() && depth.type() != CV_32FC1)
    throw std::invalid_argument("MetricSizes: the depth image must be CV_32FC1");
  std::vector<double> sizes(keypoints.size(), std::nan(""));
  if (depth.empty()) return sizes;
  for (std::size_t i = 0; i < keypoints.size(); ++i)
    if (const std::optional<cv::Point> at = core::NearestPixel(keypoints[i].pt, depth.size()))
      sizes[i] = MetricSize(keypoints[i], depth.at<float>(*at), camera);
  return sizes;
}

LearntKeypoint ToLearntKeypoint(const cv::KeyPoint& keypoint, double size_m) {
  LearntKeypoint k;
  // fmod: a float just below 0 wrapped to [0, 360) can round to 360.
  if (keypoint.angle >= 0.0f) k.angle_deg = std::fmod(double(keypoint.angle), 360.0);
  k.size_m = size_m;
  return k;
}

double TurnDeg(const LearntKeypoint& learnt, const cv::KeyPoint& seen) {
  if (!std::isfinite(learnt.angle_deg) || !(seen.angle >= 0.0f)) return std::nan("");
  const double d = std::fmod(std::abs(double(seen.angle) - learnt.angle_deg), 360.0);
  return std::min(d, 360.0 - d);
}

double SizeRatio(const LearntKeypoint& learnt, double seen_size_m) {
  if (!(learnt.size_m > 0.0 && seen_size_m > 0.0)) return std::nan("");  // NaN fails too
  return std::max(seen_size_m / learnt.size_m, learnt.size_m / seen_size_m);
}

bool ConsistentKeypoint(const LearntKeypoint& learnt, const cv::KeyPoint& seen, double seen_size_m,
                        const KeypointConsistencyOptions& options) {
  if (!options.enabled) return true;
  const double turn = TurnDeg(learnt, seen), ratio = SizeRatio(learnt, seen_size_m);
  return !(turn > options.max_angle_deg) && !(ratio > options.max_size_ratio);  // NaN passes
}

void CheckKeypointConsistencyOptions(const KeypointConsistencyOptions& options) {
  if (!(options.max_angle_deg > 0.0 && options.max_angle_deg <= 180.0))
    throw std::invalid_argument(
        "KeypointConsistencyOptions: max_angle_deg must be in (0, 180], got " +
        std::to_string(options.max_angle_deg));
  if (!(options.max_size_ratio >= 1.0 && std::isfinite(options.max_size_ratio)))
    throw std::invalid_argument("KeypointConsistencyOptions: max_size_ratio must be >= 1, got " +
                                std::to_string(options.max_size_ratio));
}

}  // namespace novelty::objects
