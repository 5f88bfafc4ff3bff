#include "maps/illumination/gradient_correlation.h"

#include "core/float_image.h"

#include <opencv2/imgproc.hpp>
#include <stdexcept>
#include <vector>

namespace novelty::illumination {

namespace {

// 1 - ρ at one layer.
cv::Mat LayerChange(const cv::Mat& a, const cv::Mat& b, const GradientCorrelationOptions& o) {
  cv::Mat ax, ay, bx, by;
  cv::Sobel(a, ax, CV_32F, 1, 0, 3, 1.0 / 8);
  cv::Sobel(a, ay, CV_32F, 0, 1, 3, 1.0 / 8);
  cv::Sobel(b, bx, CV_32F, 1, 0, 3, 1.0 / 8);
  cv::Sobel(b, by, CV_32F, 0, 1, 3, 1.0 / 8);
  cv::Mat cross = cv::abs(ax.mul(bx) + ay.mul(by)), ea = ax.mul(ax) + ay.mul(ay),
          eb = bx.mul(bx) + by.mul(by);
  const cv::Size block(o.block, o.block);
  cv::boxFilter(cross, cross, CV_32F, block, {-1, -1}, false);
  cv::boxFilter(ea, ea, CV_32F, block, {-1, -1}, false);
  cv::boxFilter(eb, eb, CV_32F, block, {-1, -1}, false);
  cv::Mat change(a.size(), CV_32F);
  for (int y = 0; y < a.rows; ++y) {
    const float *c = cross.ptr<float>(y), *p = ea.ptr<float>(y), *q = eb.ptr<float>(y);
    float* out = change.ptr<float>(y);
    for (int x = 0; x < a.cols; ++x) {
      const float n = float(o.noise_energy);
      const float rho = std::min(1.0f, (c[x] + n) / std::sqrt((p[x] + n) * (q[x] + n)));
      out[x] = 1.0f - rho;
    }
  }
  return change;
}

}  // namespace

cv::Mat GradientCorrelationChange(const cv::Mat& observation, const cv::Mat& reference,
                                  const GradientCorrelationOptions& options) {
  if (observation.empty() || observation.size() != reference.size() ||
      observation.type() != reference.type())
    throw std::invalid_argument(
        "GradientCorrelationChange: observation and reference must be images of one size and "
        "type");
  if (options.block < 1 || options.block % 2 == 0 || options.layers < 1 ||
      !(options.noise_energy > 0.0))
    throw std::invalid_argument(
        "GradientCorrelationChange: block must be odd and >= 1, layers >= 1, noise_energy > 0");
  cv::Mat a = core::ChannelMean(observation), b = core::ChannelMean(reference);
  if (!cv::checkRange(a) || !cv::checkRange(b))
    throw std::invalid_argument(
        "GradientCorrelationChange: the images hold NaN or infinite values");
  cv::Mat sum = cv::Mat::zeros(a.size(), CV_32F);
  int used = 0;
  for (int layer = 0; layer < options.layers; ++layer) {
    if (layer > 0) {
      if (a.cols < 2 * options.block || a.rows < 2 * options.block) break;
      cv::pyrDown(a, a);
      cv::pyrDown(b, b);
    }
    cv::Mat change = LayerChange(a, b, options), full;
    cv::resize(change, full, sum.size(), 0, 0, cv::INTER_LINEAR);
    sum += full;
    ++used;
  }
  return sum / used;
}

}  // namespace novelty::illumination
