#include "eval/depth_accuracy.h"

#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>
#include <stdexcept>
#include <vector>

namespace novelty::eval {

DepthAccuracy MeasureDepthAccuracy(const cv::Mat& estimate, const cv::Mat& truth,
                                   const cv::Mat& reference, const DepthAccuracyOptions& o) {
  if (estimate.type() != CV_32F || truth.type() != CV_32F || estimate.size() != truth.size() ||
      reference.size() != truth.size())
    throw std::invalid_argument("depth accuracy: need CV_32F depth maps and an image of one size");
  cv::Mat grey;
  if (reference.channels() == 3)
    cv::cvtColor(reference, grey, cv::COLOR_RGB2GRAY);
  else
    grey = reference;
  cv::Mat g, mean, mean_sq;
  grey.convertTo(g, CV_32F);
  const cv::Size window(o.texture_window, o.texture_window);
  cv::blur(g, mean, window);
  cv::blur(g.mul(g), mean_sq, window);

  // Near-discontinuity mask: a relative jump to the right or lower neighbour, dilated.
  cv::Mat jump(truth.size(), CV_8U, cv::Scalar(0));
  for (int y = 0; y + 1 < truth.rows; ++y)
    for (int x = 0; x + 1 < truth.cols; ++x) {
      const float t = truth.at<float>(y, x);
      for (const float n : {truth.at<float>(y, x + 1), truth.at<float>(y + 1, x)})
        if (!(t > 0) || !(n > 0) || std::abs(n - t) > o.discontinuity_jump * std::min(n, t))
          jump.at<uchar>(y, x) = 255;
    }
  if (o.discontinuity_margin > 0)
    cv::dilate(
        jump, jump,
        cv::Mat::ones(2 * o.discontinuity_margin + 1, 2 * o.discontinuity_margin + 1, CV_8U));

  DepthAccuracy result;
  std::vector<double> errors;
  int within = 0, edge_within = 0;
  for (int y = o.border; y < truth.rows - o.border; ++y)
    for (int x = o.border; x < truth.cols - o.border; ++x) {
      const float t = truth.at<float>(y, x);
      if (!(t > 0)) continue;
      const float m = mean.at<float>(y, x);
      if (std::sqrt(std::max(0.0f, mean_sq.at<float>(y, x) - m * m)) < o.min_texture_std) continue;
      const float e = estimate.at<float>(y, x);
      const bool correct = e > 0 && std::abs(e - t) <= o.relative_error * t;
      if (jump.at<uchar>(y, x)) {
        ++result.discontinuity_pixels;
        edge_within += correct;
        continue;
      }
      ++result.textured_pixels;
      if (!(e > 0)) continue;
      ++result.scored_pixels;
      const double rel = std::abs(e - t) / t;
      errors.push_back(rel);
      within += correct;
    }
  if (result.textured_pixels > 0) result.within_fraction = double(within) / result.textured_pixels;
  if (result.discontinuity_pixels > 0)
    result.discontinuity_within_fraction = double(edge_within) / result.discontinuity_pixels;
  if (!errors.empty()) {
    std::nth_element(errors.begin(), errors.begin() + errors.size() / 2, errors.end());
    result.median_relative_error = errors[errors.size() / 2];
  }
  return result;
}

}  // namespace novelty::eval
