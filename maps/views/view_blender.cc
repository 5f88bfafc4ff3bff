#include "maps/views/view_blender.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <opencv2/core/utility.hpp>
#include <stdexcept>
#include <string>

namespace novelty::views {

namespace {

// Bilinear sample of an n-channel plane at (u, v), coordinates clamped to the image (the
// border replicated), added with weight w to acc.
template <typename T>
inline void AddSample(const cv::Mat& plane, float u, float v, float w, int channels, float* acc) {
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
  for (int c = 0; c < channels; ++c) {
    acc[c] += w00 * float(r0[x0 * channels + c]) + w10 * float(r0[x1 * channels + c]) +
              w01 * float(r1[x0 * channels + c]) + w11 * float(r1[x1 * channels + c]);
  }
}

using Sampler = void (*)(const cv::Mat&, float, float, float, int, float*);

Sampler SamplerFor(int depth) {
  switch (depth) {
    case CV_8U:
      return &AddSample<uint8_t>;
    case CV_16U:
      return &AddSample<uint16_t>;
    case CV_16S:
      return &AddSample<int16_t>;
    case CV_16F:
      return &AddSample<cv::float16_t>;
    case CV_32F:
      return &AddSample<float>;
    case CV_64F:
      return &AddSample<double>;
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
  std::vector<Sampler> samplers;
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
    samplers.push_back(SamplerFor(planes[k].depth()));
  }
  BlendResult result;
  result.value.create(size, CV_32FC(channels));
  result.valid.create(size, CV_8UC1);
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const float tolerance = float(1.0 + o.depth_tolerance);
  // One pass over the virtual image: per pixel, the nearest depth (if a tolerance is set), then
  // the weighted sum of the valid views' bilinear samples. `sample(k, u, v, w, acc)` is inlined
  // when every plane has the same depth (the usual case), else called through a pointer.
  auto blend = [&](auto sample) {
    cv::parallel_for_(cv::Range(0, size.height), [&](const cv::Range& rows) {
      std::vector<float> acc(static_cast<std::size_t>(channels), 0.0f);
      for (int y = rows.start; y < rows.end; ++y) {
        float* out = result.value.ptr<float>(y);
        uint8_t* valid = result.valid.ptr<uint8_t>(y);
        for (int x = 0; x < size.width; ++x) {
          float nearest = std::numeric_limits<float>::infinity();
          if (o.depth_tolerance > 0.0) {
            for (const WarpField& w : warps) {
              const float d = w.depth.ptr<float>(y)[x];
              if (d > 0.0f) nearest = std::min(nearest, d);
            }
            nearest *= tolerance;
          }
          std::fill(acc.begin(), acc.end(), 0.0f);
          float weight_sum = 0.0f;
          for (std::size_t k = 0; k < warps.size(); ++k) {
            const WarpField& w = warps[k];
            const float d = w.depth.ptr<float>(y)[x];
            if (!(d > 0.0f) || d > nearest) continue;
            float weight = o.weights.empty() ? 1.0f : float(o.weights[k]);
            if (o.resolution_power > 0.0) {
              weight *= float(std::pow(d / w.source_depth.ptr<float>(y)[x], o.resolution_power));
            }
            if (o.angle_power > 0.0) {
              weight *=
                  float(std::pow(std::max(w.cos_angle.ptr<float>(y)[x], 1e-6f), o.angle_power));
            }
            const cv::Vec2f uv = w.map.ptr<cv::Vec2f>(y)[x];
            sample(k, uv[0], uv[1], weight, acc.data());
            weight_sum += weight;
          }
          valid[x] = weight_sum > 0.0f ? 255 : 0;
          for (int c = 0; c < channels; ++c) {
            out[x * channels + c] = weight_sum > 0.0f ? acc[std::size_t(c)] / weight_sum : nan;
          }
        }
      }
    });
  };
  auto typed = [&](auto tag) {
    using T = decltype(tag);
    blend([&](std::size_t k, float u, float v, float w, float* acc) {
      AddSample<T>(planes[k], u, v, w, channels, acc);
    });
  };
  bool uniform = true;
  for (const cv::Mat& p : planes) uniform &= p.depth() == planes[0].depth();
  switch (uniform ? planes[0].depth() : -1) {
    case CV_8U:
      typed(uint8_t{});
      break;
    case CV_16F:
      typed(cv::float16_t{});
      break;
    case CV_32F:
      typed(float{});
      break;
    default:
      blend([&](std::size_t k, float u, float v, float w, float* acc) {
        samplers[k](planes[k], u, v, w, channels, acc);
      });
  }
  result.covered = cv::countNonZero(result.valid);
  return result;
}

}  // namespace novelty::views
