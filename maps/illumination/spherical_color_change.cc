#include "maps/illumination/spherical_color_change.h"

#include <cmath>
#include <stdexcept>

#include "core/float_image.h"

namespace novelty::illumination {

namespace {

// (φ, θ) of eq. 2.33-2.34; false for a black pixel.
bool Angles(const cv::Vec3f& rgb, float& phi, float& theta) {
  const float r = std::max(0.0f, rgb[0]), g = std::max(0.0f, rgb[1]), b = std::max(0.0f, rgb[2]);
  const float intensity = std::sqrt(r * r + g * g + b * b);  // eq. 2.32
  if (intensity <= 0.0f) return false;
  phi = std::atan2(g, r);
  theta = std::acos(std::min(1.0f, b / intensity));
  return true;
}

}  // namespace

cv::Mat SphericalColorChange(const cv::Mat& observation, const cv::Mat& reference) {
  if (observation.empty() || observation.channels() != 3 ||
      observation.size() != reference.size() || observation.type() != reference.type() ||
      (observation.depth() != CV_8U && observation.depth() != CV_16U &&
       observation.depth() != CV_32F))
    throw std::invalid_argument(
        "SphericalColorChange: observation and reference must be RGB images of one size and "
        "type");
  const cv::Mat a = core::ToFloat255(observation), b = core::ToFloat255(reference);
  if (!cv::checkRange(a) || !cv::checkRange(b))
    throw std::invalid_argument("SphericalColorChange: the images hold NaN or infinite values");
  cv::Mat d(a.size(), CV_32F);
  for (int y = 0; y < a.rows; ++y) {
    const cv::Vec3f *p = a.ptr<cv::Vec3f>(y), *q = b.ptr<cv::Vec3f>(y);
    float* out = d.ptr<float>(y);
    for (int x = 0; x < a.cols; ++x) {
      float phi_a, theta_a, phi_b, theta_b;
      out[x] = Angles(p[x], phi_a, theta_a) && Angles(q[x], phi_b, theta_b)
                   ? std::hypot(phi_a - phi_b, theta_a - theta_b)
                   : 0.0f;
    }
  }
  return d;
}

}  // namespace novelty::illumination
