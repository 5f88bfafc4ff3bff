#include "maps/views/view_blender.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <limits>
#include <optional>
#include <opencv2/core/utility.hpp>
#include <stdexcept>
#include <string>

#include "maps/stats/lanes.h"

namespace novelty::views {

namespace {

using stats::lanes::F16;
using stats::lanes::I16;
using stats::lanes::kLanes;

// Scalar (one pixel) and vector (sixteen) forms of the few operations the sampling kernel needs,
// so that one kernel serves the row's body and its tail.
inline float LoadLane(const float* p, float) { return *p; }
inline F16 LoadLane(const float* p, F16) { return stats::lanes::Load(p); }
inline void StoreLane(float* p, float v) { *p = v; }
inline void StoreLane(float* p, F16 v) { stats::lanes::Store(p, v); }
inline int ToInt(float x) { return int(x); }
inline I16 ToInt(F16 x) { return stats::lanes::AsInt(x); }
inline float ToFloat(int x) { return float(x); }
inline F16 ToFloat(I16 x) { return stats::lanes::AsFloat(x); }
inline float Gather(const float* p, int i) { return p[i]; }
inline F16 Gather(const float* p, I16 i) { return stats::lanes::Gather(p, i); }
inline int GatherWord(const int32_t* p, int i) { return p[i]; }
inline I16 GatherWord(const int32_t* p, I16 i) { return stats::lanes::GatherInt(p, i); }
inline int GatherBytes(const char* base, int offset) {
  int v;
  std::memcpy(&v, base + offset, 4);
  return v;
}
inline I16 GatherBytes(const char* base, I16 offset) {
  return stats::lanes::GatherBytes(base, offset);
}
// IEEE half floats (in the low 16 bits) to float.
inline float HalfToFloat(int bits) {
  return float(cv::float16_t::fromBits(static_cast<ushort>(bits & 0xFFFF)));
}
inline F16 HalfToFloat(I16 bits) {
#if defined(__AVX512F__)
  return (F16)_mm512_cvtph_ps(_mm512_cvtepi32_epi16((__m512i)bits));
#else
  F16 v;
  for (int k = 0; k < kLanes; ++k) v[k] = HalfToFloat(bits[k]);
  return v;
#endif
}
inline float Pow(float x, float p) { return std::pow(x, p); }
inline F16 Pow(F16 x, float p) {
  for (int k = 0; k < kLanes; ++k) x[k] = std::pow(x[k], p);
  return x;
}
template <typename T>
inline T Clamp(T x, float lo, float hi) {
  x = x < lo ? T{} + lo : x;
  return x > hi ? T{} + hi : x;
}
// The (u, v) pairs of the warp map at pixel x: interleaved in memory.
inline void LoadMap(const cv::Vec2f* map, float& u, float& v) {
  u = (*map)[0];
  v = (*map)[1];
}
inline void LoadMap(const cv::Vec2f* map, F16& u, F16& v) {
  const F16 a = stats::lanes::Load(&(*map)[0]), b = stats::lanes::Load(&(*map)[0] + kLanes);
  u = __builtin_shuffle(a, b, I16{0, 2, 4, 6, 8, 10, 12, 14, 16, 18, 20, 22, 24, 26, 28, 30});
  v = __builtin_shuffle(a, b, I16{1, 3, 5, 7, 9, 11, 13, 15, 17, 19, 21, 23, 25, 27, 29, 31});
}

// Channels whose accumulator rows the final pass keeps in registers (more are read per pixel).
constexpr int kMaxPlanarChannels = 8;

// A view's plane as the kernel reads it, in one of three forms:
//   float:  continuous floats, one gather per channel and bilinear corner;
//   packed: 8-bit planes of up to four channels as one 32-bit word per pixel (RGB → RGBA), so
//           one gather per corner fetches every channel — for RGB three times fewer gathers;
//   half:   half-float planes in place, one gather per two channels (HalfPlane below).
// Corner(pixel) is what a corner's samples are read from; Value(corner, c) is channel c there.
struct FloatPlane {
  const float* data;
  int cols, rows, channels;
  template <class I>
  I Corner(I pixel) const {
    return pixel * channels;
  }
  template <class T, class I>
  T Value(I corner, int c) const {
    return Gather(data, corner + c);
  }
};

struct PackedPlane {
  const int32_t* data;
  int cols, rows, channels;
  template <class I>
  I Corner(I pixel) const {
    return GatherWord(data, pixel);
  }
  template <class T, class I>
  T Value(I word, int c) const {
    return ToFloat((word >> (8 * c)) & 0xFF);
  }
};

// Half-float planes of 2…8 channels, read in place (no float copy of the view): the 32-bit word
// at channel 2w holds channels 2w and 2w+1; with an odd count the last word starts one channel
// earlier, so every read stays inside the pixel. One gather per two channels and corner.
struct HalfPlane {
  static constexpr int kMaxChannels = 8;
  const char* data;  // pixel p starts at byte 2·channels·p
  int cols, rows, channels;
  int First(int word) const { return std::min(2 * word, channels - 2); }
  template <class I>
  std::array<I, kMaxChannels / 2> Corner(I pixel) const {
    std::array<I, kMaxChannels / 2> words{};
    const I byte = pixel * (2 * channels);
    for (int w = 0; w < (channels + 1) / 2; ++w) words[w] = GatherBytes(data, byte + 2 * First(w));
    return words;
  }
  template <class T, class W>
  T Value(const W& words, int c) const {
    const auto word = words[std::size_t(c / 2)];
    return HalfToFloat(c == First(c / 2) ? word : word >> 16);
  }
};

std::optional<HalfPlane> AsHalfPlane(const cv::Mat& plane) {
  if (plane.depth() != CV_16F || plane.channels() < 2 ||
      plane.channels() > HalfPlane::kMaxChannels || !plane.isContinuous())
    return std::nullopt;
  return HalfPlane{reinterpret_cast<const char*>(plane.ptr()), plane.cols, plane.rows,
                   plane.channels()};
}

// Converts to the float form where the plane is not continuous float already.
FloatPlane AsFloatPlane(const cv::Mat& plane, cv::Mat& scratch) {
  const cv::Mat* m = &plane;
  if (plane.depth() != CV_32F || !plane.isContinuous()) {
    plane.convertTo(scratch, CV_32F);
    m = &scratch;
  }
  return {m->ptr<float>(), m->cols, m->rows, m->channels()};
}

// 8-bit planes of 1–4 channels, padded to four bytes per pixel.
std::optional<PackedPlane> AsPackedPlane(const cv::Mat& plane, cv::Mat& scratch) {
  if (plane.depth() != CV_8U || plane.channels() > 4) return std::nullopt;
  // One pass: the plane's channels into bytes 0…n−1 of each word, zeros after (from index −1).
  scratch.create(plane.size(), CV_8UC4);
  std::vector<int> from_to;
  for (int c = 0; c < 4; ++c) from_to.insert(from_to.end(), {c < plane.channels() ? c : -1, c});
  cv::mixChannels(&plane, 1, &scratch, 1, from_to.data(), 4);
  return PackedPlane{reinterpret_cast<const int32_t*>(scratch.ptr()), plane.cols, plane.rows,
                     plane.channels()};
}

// What the kernel reads for one view (all per-pixel inputs are rows of the virtual image).
template <class Plane>
struct ViewInputs {
  const WarpField* warp;
  Plane plane;
  float weight;
};

// Adds the view's weighted bilinear samples at pixels [x, x + lanes) of row y to the planar
// accumulators (one CV_32FC1 per channel) and the weight sum. Coordinates are clamped to the
// source image (the border replicated). T = float for one pixel, F16 for sixteen.
template <typename T, class Plane>
inline void AccumulatePixels(const ViewInputs<Plane>& in, const BlendOptions& o,
                             const cv::Mat& nearest, int y, int x, std::vector<cv::Mat>& acc,
                             cv::Mat& weight_sum) {
  const WarpField& w = *in.warp;
  const Plane& p = in.plane;
  const T d = LoadLane(w.depth.ptr<float>(y) + x, T{});
  auto valid = d > 0.0f;
  if (!nearest.empty()) valid = valid & (d <= LoadLane(nearest.ptr<float>(y) + x, T{}));
  T weight = T{} + in.weight;
  if (o.resolution_power > 0.0) {
    weight *= Pow(d / LoadLane(w.source_depth.ptr<float>(y) + x, T{}), float(o.resolution_power));
  }
  if (o.angle_power > 0.0) {
    const T cos_angle = LoadLane(w.cos_angle.ptr<float>(y) + x, T{});
    weight *= Pow(cos_angle > 1e-6f ? cos_angle : T{} + 1e-6f, float(o.angle_power));
  }
  weight = valid ? weight : T{};
  T u, v;
  LoadMap(w.map.ptr<cv::Vec2f>(y) + x, u, v);
  u = Clamp(u, 0.0f, float(p.cols - 1));
  v = Clamp(v, 0.0f, float(p.rows - 1));
  const auto x0 = ToInt(u), y0 = ToInt(v);  // non-negative: truncation is floor
  const auto x1 = x0 + (x0 < p.cols - 1 ? 1 : 0), y1 = y0 + (y0 < p.rows - 1 ? 1 : 0);
  const T fx = u - ToFloat(x0), fy = v - ToFloat(y0);
  const T w00 = weight * (1.0f - fx) * (1.0f - fy), w10 = weight * fx * (1.0f - fy),
          w01 = weight * (1.0f - fx) * fy, w11 = weight * fx * fy;
  const auto c00 = p.Corner(y0 * p.cols + x0), c10 = p.Corner(y0 * p.cols + x1);
  const auto c01 = p.Corner(y1 * p.cols + x0), c11 = p.Corner(y1 * p.cols + x1);
  for (int c = 0; c < p.channels; ++c) {
    const T sample = w00 * p.template Value<T>(c00, c) + w10 * p.template Value<T>(c10, c) +
                     w01 * p.template Value<T>(c01, c) + w11 * p.template Value<T>(c11, c);
    float* a = acc[std::size_t(c)].ptr<float>(y) + x;
    StoreLane(a, LoadLane(a, T{}) + (valid ? sample : T{}));  // select: a NaN sample stays out
  }
  float* ws = weight_sum.ptr<float>(y) + x;
  StoreLane(ws, LoadLane(ws, T{}) + weight);
}

// Adds one view to the accumulators, sixteen pixels at a time.
template <class Plane>
void AccumulateView(const ViewInputs<Plane>& in, const BlendOptions& o, const cv::Mat& nearest,
                    std::vector<cv::Mat>& acc, cv::Mat& weight_sum) {
  const int width = weight_sum.cols;
  cv::parallel_for_(cv::Range(0, weight_sum.rows), [&](const cv::Range& rows) {
    for (int y = rows.start; y < rows.end; ++y) {
      int x = 0;
      for (; x + kLanes <= width; x += kLanes) {
        AccumulatePixels<F16>(in, o, nearest, y, x, acc, weight_sum);
      }
      for (; x < width; ++x) AccumulatePixels<float>(in, o, nearest, y, x, acc, weight_sum);
    }
  });
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
    const int depth = planes[k].depth();
    if (depth != CV_8U && depth != CV_16U && depth != CV_16S && depth != CV_16F &&
        depth != CV_32F && depth != CV_64F) {
      throw std::invalid_argument("BlendPlanes: unsupported plane depth " + std::to_string(depth));
    }
  }
  // View by view into planar accumulators (streaming through each warp field once), then one
  // pass dividing by the weight sum and interleaving the channels.
  const cv::Mat nearest = o.depth_tolerance > 0.0 ? NearestDepth(warps, o.depth_tolerance)
                                                  : cv::Mat();
  std::vector<cv::Mat> acc(static_cast<std::size_t>(channels));
  for (cv::Mat& a : acc) a = cv::Mat::zeros(size, CV_32FC1);
  cv::Mat weight_sum = cv::Mat::zeros(size, CV_32FC1);
  cv::Mat scratch;
  for (std::size_t k = 0; k < warps.size(); ++k) {
    const float weight = o.weights.empty() ? 1.0f : float(o.weights[k]);
    if (const auto packed = AsPackedPlane(planes[k], scratch)) {
      AccumulateView(ViewInputs<PackedPlane>{&warps[k], *packed, weight}, o, nearest, acc,
                     weight_sum);
    } else if (const auto half = AsHalfPlane(planes[k])) {
      AccumulateView(ViewInputs<HalfPlane>{&warps[k], *half, weight}, o, nearest, acc,
                     weight_sum);
    } else {
      AccumulateView(ViewInputs<FloatPlane>{&warps[k], AsFloatPlane(planes[k], scratch), weight},
                     o, nearest, acc, weight_sum);
    }
  }
  BlendResult result;
  result.value.create(size, CV_32FC(channels));
  result.valid.create(size, CV_8UC1);
  const float nan = std::numeric_limits<float>::quiet_NaN();
  cv::parallel_for_(cv::Range(0, size.height), [&](const cv::Range& rows) {
    for (int y = rows.start; y < rows.end; ++y) {
      float* out = result.value.ptr<float>(y);
      const float* wsum = weight_sum.ptr<float>(y);
      uint8_t* valid = result.valid.ptr<uint8_t>(y);
      const float* a[kMaxPlanarChannels];
      const int n = std::min(channels, kMaxPlanarChannels);
      for (int c = 0; c < n; ++c) a[c] = acc[std::size_t(c)].ptr<float>(y);
      for (int x = 0; x < size.width; ++x) {
        const bool hit = wsum[x] > 0.0f;
        valid[x] = hit ? 255 : 0;
        float* o_px = out + std::size_t(x) * channels;
        // Divide, not multiply by 1/sum: a sum of tiny (denormal) weights has no finite inverse.
        for (int c = 0; c < n; ++c) o_px[c] = hit ? a[c][x] / wsum[x] : nan;
        for (int c = n; c < channels; ++c) {
          o_px[c] = hit ? acc[std::size_t(c)].ptr<float>(y)[x] / wsum[x] : nan;
        }
      }
    }
  });
  result.covered = cv::countNonZero(result.valid);
  return result;
}

}  // namespace novelty::views
