#include "maps/views/view_blender.h"

#include <limits>
#include <opencv2/imgproc.hpp>
#include <stdexcept>
#include <string>

namespace novelty::views {

namespace {

// Per pixel, which views contribute: valid depth and, with a tolerance, near the nearest view.
std::vector<cv::Mat> ContributionMasks(const std::vector<WarpField>& warps, double tolerance) {
  std::vector<cv::Mat> masks;
  cv::Mat nearest;
  if (tolerance > 0.0) {
    nearest = cv::Mat(warps[0].depth.size(), CV_32FC1,
                      cv::Scalar(std::numeric_limits<float>::infinity()));
    for (const WarpField& w : warps) {
      cv::Mat d = w.depth.clone();
      d.setTo(std::numeric_limits<float>::infinity(), w.depth <= 0.0f);
      cv::min(nearest, d, nearest);
    }
    nearest *= (1.0 + tolerance);
  }
  for (const WarpField& w : warps) {
    cv::Mat m = w.depth > 0.0f;
    if (tolerance > 0.0) m &= (w.depth <= nearest);
    masks.push_back(m);
  }
  return masks;
}

}  // namespace

BlendResult BlendPlanes(const std::vector<WarpField>& warps, const std::vector<cv::Mat>& planes,
                        const BlendOptions& o) {
  if (warps.empty() || warps.size() != planes.size()) {
    throw std::invalid_argument("BlendPlanes: need one plane per warp, got " +
                                std::to_string(planes.size()) + " planes for " +
                                std::to_string(warps.size()) + " warps");
  }
  if (!o.weights.empty() && o.weights.size() != warps.size()) {
    throw std::invalid_argument("BlendPlanes: " + std::to_string(o.weights.size()) +
                                " weights for " + std::to_string(warps.size()) + " views");
  }
  const int channels = planes[0].channels();
  const cv::Size size = warps[0].depth.size();
  cv::Mat sum(size, CV_32FC(channels), cv::Scalar::all(0));
  cv::Mat weight(size, CV_32FC1, cv::Scalar(0));
  const std::vector<cv::Mat> masks = ContributionMasks(warps, o.depth_tolerance);
  for (std::size_t k = 0; k < warps.size(); ++k) {
    if (planes[k].channels() != channels || warps[k].depth.size() != size) {
      throw std::invalid_argument("BlendPlanes: view " + std::to_string(k) +
                                  " disagrees in channels or virtual size");
    }
    cv::Mat plane;
    planes[k].convertTo(plane, CV_32F);
    cv::Mat warped;
    cv::remap(plane, warped, warps[k].map, cv::noArray(), cv::INTER_LINEAR, cv::BORDER_REPLICATE);
    const double w = o.weights.empty() ? 1.0 : o.weights[k];
    cv::Mat wk(size, CV_32FC1, cv::Scalar(w));
    if (o.resolution_power > 0.0) {
      cv::Mat ratio;
      cv::divide(warps[k].depth, warps[k].source_depth, ratio);  // 0/0 only where masked out
      cv::pow(ratio, o.resolution_power, ratio);
      wk = wk.mul(ratio);
    }
    if (o.angle_power > 0.0) {
      if (warps[k].cos_angle.empty()) {
        throw std::invalid_argument(
            "BlendPlanes: angle_power needs warps computed with "
            "compute_view_angles");
      }
      cv::Mat c = cv::max(warps[k].cos_angle, 1e-6);
      cv::pow(c, o.angle_power, c);
      wk = wk.mul(c);
    }
    cv::Mat wk_c;
    cv::merge(std::vector<cv::Mat>(channels, wk), wk_c);
    cv::add(sum, warped.mul(wk_c), sum, masks[k]);
    cv::add(weight, wk, weight, masks[k]);
  }
  BlendResult result;
  result.valid = weight > 0.0f;
  result.covered = cv::countNonZero(result.valid);
  cv::Mat weight_c;
  cv::merge(std::vector<cv::Mat>(channels, weight), weight_c);
  cv::divide(sum, weight_c, result.value);
  result.value.setTo(cv::Scalar::all(std::numeric_limits<float>::quiet_NaN()), ~result.valid);
  return result;
}

}  // namespace novelty::views
