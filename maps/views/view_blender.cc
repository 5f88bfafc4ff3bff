#include "maps/views/view_blender.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <opencv2/core/utility.hpp>
#include <stdexcept>
#include <string>

namespace novelty::views {

namespace {

// Adds w × the bilinear sample of an n-channel plane at (u, v) to acc; coordinates clamped to the
// image (the border replicated). C > 0 fixes the channel count at compile time (the common 1, 3
// and 7 unroll); C = 0 takes `channels`.
template <typename T, int C>
inline void AddSample(const cv::Mat& plane, float u, float v, float w, int channels, float* acc) {
  const int n = C > 0 ? C : channels;
  const int max_x = plane.cols - 1, max_y = plane.rows - 1;
  u = std::clamp(u, 0.0f, float(max_x));
  v = std::clamp(v, 0.0f, float(max_y));
  const int x0 = std::min(int(u), max_x), y0 = std::min(int(v), max_y);
  const int x1 = std::min(x0 + 1, max_x), y1 = std::min(y0 + 1, max_y);
  const float fx = u - float(x0), fy = v - float(y0);
  const float w00 = w * (1 - fx) * (1 - fy), w10 = w * fx * (1 - fy), w01 = w * (1 - fx) * fy,
              w11 = w * fx * fy;
  const T* r0 = plane.ptr<T>(y0);
  const T* r1 = plane.ptr<T>(y1);
  const T *a = r0 + x0 * n, *b = r0 + x1 * n, *c = r1 + x0 * n, *d = r1 + x1 * n;
  for (int k = 0; k < n; ++k) {
    acc[k] += w00 * float(a[k]) + w10 * float(b[k]) + w01 * float(c[k]) + w11 * float(d[k]);
  }
}

// Per pixel, the nearest warped depth over all views × (1 + tolerance); +inf where none.
cv::Mat NearestDepth(const std::vector<WarpField>& warps, double tolerance) {
  cv::Mat nearest(warps[0].depth.size(), CV_32FC1,
                  cv::Scalar(std::numeric_limits<float>::infinity()));
  for (const WarpField& w : warps) {
    // Uncovered pixels have depth 0: only positive depths count.
    cv::Mat positive = w.depth > 0.0f;
    cv::Mat d = cv::min(nearest, w.depth);
    d.copyTo(nearest, positive);
  }
  nearest *= 1.0 + tolerance;
  return nearest;
}

// The per-frame images the per-pixel weights need, computed once for all views.
struct PixelLimits {
  cv::Mat nearest;  // depth limit (depth_tolerance), empty if unused
};

// Adds one view's weighted samples to the accumulators (acc: n channels, weight_sum: 1).
template <typename T, int C>
void AccumulateView(const WarpField& w, const cv::Mat& plane, float view_weight,
                    const PixelLimits& limits, const BlendOptions& o, int channels, cv::Mat& acc,
                    cv::Mat& weight_sum) {
  const cv::Mat& nearest = limits.nearest;
  const float resolution_power = float(o.resolution_power), angle_power = float(o.angle_power);
  cv::parallel_for_(cv::Range(0, acc.rows), [&](const cv::Range& rows) {
    for (int y = rows.start; y < rows.end; ++y) {
      const float* depth = w.depth.ptr<float>(y);
      const cv::Vec2f* map = w.map.ptr<cv::Vec2f>(y);
      const float* limit = nearest.empty() ? nullptr : nearest.ptr<float>(y);
      float* sum = acc.ptr<float>(y);
      float* wsum = weight_sum.ptr<float>(y);
      for (int x = 0; x < acc.cols; ++x) {
        const float d = depth[x];
        if (!(d > 0.0f) || (limit && d > limit[x])) continue;
        float weight = view_weight;
        if (resolution_power > 0.0f) {
          weight *= std::pow(d / w.source_depth.ptr<float>(y)[x], resolution_power);
        }
        if (angle_power > 0.0f) {
          weight *= std::pow(std::max(w.cos_angle.ptr<float>(y)[x], 1e-6f), angle_power);
        }
        AddSample<T, C>(plane, map[x][0], map[x][1], weight, channels,
                        sum + std::size_t(x) * (C > 0 ? C : channels));
        wsum[x] += weight;
      }
    }
  });
}

using Accumulator = void (*)(const WarpField&, const cv::Mat&, float, const PixelLimits&,
                             const BlendOptions&, int, cv::Mat&, cv::Mat&);

template <typename T>
Accumulator AccumulatorForChannels(int channels) {
  switch (channels) {
    case 1:
      return &AccumulateView<T, 1>;
    case 3:
      return &AccumulateView<T, 3>;
    case 7:
      return &AccumulateView<T, 7>;
  }
  return &AccumulateView<T, 0>;
}

Accumulator AccumulatorFor(int depth, int channels) {
  switch (depth) {
    case CV_8U:
      return AccumulatorForChannels<uint8_t>(channels);
    case CV_16U:
      return AccumulatorForChannels<uint16_t>(channels);
    case CV_16S:
      return AccumulatorForChannels<int16_t>(channels);
    case CV_16F:
      return AccumulatorForChannels<cv::float16_t>(channels);
    case CV_32F:
      return AccumulatorForChannels<float>(channels);
    case CV_64F:
      return AccumulatorForChannels<double>(channels);
  }
  throw std::invalid_argument("BlendPlanes: unsupported plane depth " + std::to_string(depth));
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
  std::vector<Accumulator> accumulators;
  for (std::size_t k = 0; k < warps.size(); ++k) {
    if (planes[k].channels() != channels || warps[k].depth.size() != size ||
        warps[k].map.size() != size) {
      throw std::invalid_argument("BlendPlanes: view " + std::to_string(k) +
                                  " disagrees in channels or virtual size");
    }
    if (o.angle_power > 0.0 && warps[k].cos_angle.empty()) {
      throw std::invalid_argument(
          "BlendPlanes: angle_power needs warps computed with "
          "compute_view_angles");
    }
    accumulators.push_back(AccumulatorFor(planes[k].depth(), channels));
  }
  // View by view into accumulators (streaming through each warp field once), then one pass
  // dividing by the weight sum.
  PixelLimits limits;
  if (o.depth_tolerance > 0.0) limits.nearest = NearestDepth(warps, o.depth_tolerance);
  cv::Mat acc(size, CV_32FC(channels), cv::Scalar::all(0));
  acc = acc.reshape(channels);  // Scalar::all covers ≤ 4 channels; zero the rest below
  acc.reshape(1).setTo(0.0f);
  cv::Mat weight_sum(size, CV_32FC1, cv::Scalar(0));
  for (std::size_t k = 0; k < warps.size(); ++k) {
    const float view_weight = o.weights.empty() ? 1.0f : float(o.weights[k]);
    accumulators[k](warps[k], planes[k], view_weight, limits, o, channels, acc, weight_sum);
  }
  BlendResult result;
  result.value = acc;  // divided in place
  result.valid.create(size, CV_8UC1);
  const float nan = std::numeric_limits<float>::quiet_NaN();
  cv::parallel_for_(cv::Range(0, size.height), [&](const cv::Range& rows) {
    for (int y = rows.start; y < rows.end; ++y) {
      float* out = result.value.ptr<float>(y);
      const float* wsum = weight_sum.ptr<float>(y);
      uint8_t* valid = result.valid.ptr<uint8_t>(y);
      for (int x = 0; x < size.width; ++x) {
        // Divide, not multiply by 1/sum: a sum of tiny (denormal) weights has no finite inverse.
        const bool hit = wsum[x] > 0.0f;
        valid[x] = hit ? 255 : 0;
        for (int c = 0; c < channels; ++c) {
          out[x * channels + c] = hit ? out[x * channels + c] / wsum[x] : nan;
        }
      }
    }
  });
  result.covered = cv::countNonZero(result.valid);
  return result;
}

}  // namespace novelty::views
