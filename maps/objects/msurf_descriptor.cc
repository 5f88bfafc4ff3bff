#include "maps/objects/msurf_descriptor.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "maps/objects/box_filters.h"

namespace novelty::objects {

namespace {

// An even Haar side of about `side` px, at least 2.
int HaarSide(float side) { return std::max(2, 2 * int(std::lround(side / 2.0f))); }

}  // namespace

float SurfOrientation(const cv::Mat& integral, cv::Point2f pt, float scale) {
  const int side = HaarSide(4.0f * scale);
  std::vector<float> rx, ry, angle;
  for (int i = -6; i <= 6; ++i) {
    for (int j = -6; j <= 6; ++j) {
      if (i * i + j * j >= 36) continue;
      const float g = std::exp(-float(i * i + j * j) / (2.0f * 2.0f * 2.0f));  // σ = 2s
      float x, y;
      HaarAt(integral, pt.x + i * scale, pt.y + j * scale, side, x, y);
      x *= g, y *= g;
      rx.push_back(x);
      ry.push_back(y);
      angle.push_back(std::atan2(y, x));
    }
  }
  constexpr float kPi = float(M_PI), kWindow = kPi / 3.0f;
  float best = -1.0f, best_x = 0.0f, best_y = 0.0f;
  for (float start = -kPi; start < kPi; start += 0.15f) {
    float sx = 0.0f, sy = 0.0f;
    for (std::size_t k = 0; k < angle.size(); ++k) {
      float d = angle[k] - start;  // the response's angle past the window's start, 0…2π
      if (d < 0.0f) d += 2.0f * kPi;
      if (d < kWindow) sx += rx[k], sy += ry[k];
    }
    const float length = sx * sx + sy * sy;
    if (length > best) best = length, best_x = sx, best_y = sy;
  }
  return std::atan2(best_y, best_x);
}

void MSurfDescriptor(const cv::Mat& integral, cv::Point2f pt, float scale, float angle,
                     float* out) {
  const float co = std::cos(angle), si = std::sin(angle);
  const int side = HaarSide(2.0f * scale);
  constexpr float kSigma1 = 2.5f, kSigma2 = 1.5f;
  // The sub-regions' sample weights, the same for each: offsets −4…4 from its centre.
  static const std::array<float, 81> kSampleWeight = [] {
    std::array<float, 81> w{};
    for (int k = -4; k <= 4; ++k)
      for (int l = -4; l <= 4; ++l)
        w[std::size_t(9 * (k + 4) + l + 4)] =
            std::exp(-float(k * k + l * l) / (2.0f * kSigma1 * kSigma1));
    return w;
  }();
  double length = 0.0;
  for (int a = 0; a < 4; ++a) {      // sub-region along the orientation (u)
    for (int b = 0; b < 4; ++b) {    // … and across it (v)
      const float cu = -7.5f + 5.0f * a, cv_ = -7.5f + 5.0f * b;  // its centre, units of s
      float du = 0, dv = 0, adu = 0, adv = 0;
      for (int k = -4; k <= 4; ++k) {
        for (int l = -4; l <= 4; ++l) {
          const float u = cu + k, v = cv_ + l;
          // The sample in the image: (u, v) rotated by the orientation, scaled by s.
          const float x = pt.x + scale * (u * co - v * si);
          const float y = pt.y + scale * (u * si + v * co);
          const float g = kSampleWeight[std::size_t(9 * (k + 4) + l + 4)];
          float rx, ry;
          HaarAt(integral, x, y, side, rx, ry);
          const float ru = g * (rx * co + ry * si);   // along the orientation
          const float rv = g * (-rx * si + ry * co);  // across it
          du += ru, dv += rv, adu += std::abs(ru), adv += std::abs(rv);
        }
      }
      const float ga = -1.5f + a, gb = -1.5f + b;
      const float g2 = std::exp(-(ga * ga + gb * gb) / (2.0f * kSigma2 * kSigma2));
      float* d = out + 4 * (4 * a + b);
      d[0] = g2 * du, d[1] = g2 * dv, d[2] = g2 * adu, d[3] = g2 * adv;
      for (int q = 0; q < 4; ++q) length += double(d[q]) * d[q];
    }
  }
  // Below this the responses are the integral image's rounding (a flat patch): no direction.
  constexpr double kFlat = 1e-9;
  const float inv = std::sqrt(length) > kFlat ? float(1.0 / std::sqrt(length)) : 0.0f;
  for (int q = 0; q < 64; ++q) out[q] *= inv;
}

}  // namespace novelty::objects
