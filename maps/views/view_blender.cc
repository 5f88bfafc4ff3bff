#include "maps/views/view_blender.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <limits>
#include <numeric>
#include <opencv2/core/utility.hpp>
#include <optional>
#include <stdexcept>
#include <string>

#include "core/lanes.h"
#include "core/row_windows.h"
#include "core/with_count.h"
#include "maps/views/blend_lanes.h"
#include "maps/views/blend_plane_layouts.h"
#include "maps/views/blend_sampling.h"
#include "maps/views/blend_weights.h"

namespace novelty::views {

// The kernel's parts: blend_lanes.h (one- and sixteen-pixel arithmetic), blend_plane_layouts.h
// (reading planes in place), blend_sampling.h (bilinear samples), blend_weights.h (each view's
// say). This file puts them together per plane layout and channel count, and checks the input.
using namespace blend;

namespace {

// One view's weighted bilinear sample at pixels [x, x + lanes) of row y, channels
// [c0, c0 + n), added to acc[0…n) and its weight to `weight_sum` (see FootprintOf). Inlined
// into BlendPixels, whose channel count is then known here: the sums stay in registers and the
// channel loops unroll (GCC left it a call, summing in memory).
template <typename T, class Plane>
inline __attribute__((always_inline)) void AddView(const WarpField& w, const Plane& p,
                                                   float view_weight, const BlendOptions& o,
                                                   const PixelLimits<T>& limits, int y, int x,
                                                   int c0, int n, T* acc, T& weight_sum) {
  const auto [valid, weight, at, w00, w10, w01, w11] =
      FootprintOf(w, p, view_weight, o, limits, y, x);
  weight_sum += weight;
  if constexpr (std::is_same_v<T, F16>) {
    if (!core::lanes::Any(valid)) return;  // sixteen uncovered pixels: nothing to read
  }
  if constexpr (std::is_same_v<T, F16> && std::is_same_v<Plane, BytePlane> && kNarrowReads) {
    if (c0 == 0 && n == p.pixel_bytes &&
        SampleBytesNarrow(p, at, w00, w10, w01, w11, valid, n, acc))
      return;
  }
  if constexpr (std::is_same_v<T, F16> && core::RowWindows::kAvailable) {
    const WindowSpan span = SpanOf(p, valid, at);
    if (span.rows > 0) {
      const core::RowWindows windows(p.data, p.TotalBytes(), std::size_t(p.RowBytes()), span.row0,
                                     span.rows, span.first);
      const Corners<I16> inside = span.Inside(valid, at);
      Sample(p, WindowReader{windows, span.row0, span.first}, inside, w00, w10, w01, w11, valid, c0,
             n, acc);
      return;
    }
  }
  Sample(p, p.Gatherer(), at, w00, w10, w01, w11, valid, c0, n, acc);
}

#if (defined(__AVX512F__) && defined(__AVX512VL__) && defined(__AVX512BW__) && \
     defined(__F16C__)) ||                                                     \
    (defined(__AVX2__) && defined(__F16C__))
// Planes of 2–8 half or float channels (Plane::WholePixels) are read a pixel at a time: one
// masked load gives all channels of a corner, where the gather path needs a gather per corner and
// word, and a gather costs several times a load (with AVX-512) or is a loop of scalar loads
// (without); BM_BlendParameterPlanes measures both.
constexpr bool kPixelReads = true;
typedef float F8 __attribute__((vector_size(32)));

#if defined(__AVX512F__) && defined(__AVX512VL__) && defined(__AVX512BW__)
// Which channels of a pixel are read and written: one bit each.
using ChannelMask = __mmask8;
inline ChannelMask MaskOf(int channels) {
  return __mmask8((1u << channels) - 1);
}
// All channels of the pixel at `p` as floats (nothing else is read; other lanes 0).
inline F8 PixelChannels(const FloatPlane&, const char* p, ChannelMask m) {
  return (F8)_mm256_maskz_loadu_ps(m, p);
}
inline F8 PixelChannels(const HalfPlane&, const char* p, ChannelMask m) {
  return (F8)_mm256_cvtph_ps(_mm_maskz_loadu_epi16(m, p));
}
inline void StorePixel(float* p, ChannelMask m, F8 value) {
  _mm256_mask_storeu_ps(p, m, (__m256)value);
}
#else
// AVX2 masks lanes of 32 bits: float channels one lane each, half channels two to a lane — an
// odd count's last half is read on its own (a 32-bit lane would run past the pixel, and the last
// pixel's past the plane) and blended into place. Those masked reads cost several instructions;
// where a whole register's width lies inside the plane (every pixel but the last few), one plain
// load serves, its lanes past the pixel's channels cleared.
struct ChannelMask {
  __m256i floats;   // lane c: channel c
  __m128i halves;   // 16-bit lane c: channel c
  __m128i pairs;    // lane i: half channels 2i, 2i + 1 (whole pairs only)
  __m128i last;     // 16-bit lane (channels − 1) of an odd count; 0 for an even one
  int last_offset;  // its byte offset in the pixel
};
inline ChannelMask MaskOf(int channels) {
  ChannelMask m;
  const __m256i lane = _mm256_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7);
  m.floats = _mm256_cmpgt_epi32(_mm256_set1_epi32(channels), lane);
  m.halves =
      _mm_cmpgt_epi16(_mm_set1_epi16(short(channels)), _mm_setr_epi16(0, 1, 2, 3, 4, 5, 6, 7));
  m.pairs = _mm_cmpgt_epi32(_mm_set1_epi32(channels / 2), _mm_setr_epi32(0, 1, 2, 3));
  m.last = channels % 2 ? _mm_cmpeq_epi16(_mm_set1_epi16(short(channels - 1)),
                                          _mm_setr_epi16(0, 1, 2, 3, 4, 5, 6, 7))
                        : _mm_setzero_si128();
  m.last_offset = 2 * (channels - 1);
  return m;
}
inline F8 PixelChannels(const FloatPlane& plane, const char* p, const ChannelMask& m) {
  if (p + sizeof(__m256) <= plane.data + plane.TotalBytes()) {
    return (F8)_mm256_and_ps(_mm256_loadu_ps(reinterpret_cast<const float*>(p)),
                             _mm256_castsi256_ps(m.floats));
  }
  return (F8)_mm256_maskload_ps(reinterpret_cast<const float*>(p), m.floats);
}
inline F8 PixelChannels(const HalfPlane& plane, const char* p, const ChannelMask& m) {
  __m128i halves;
  if (p + sizeof(__m128i) <= plane.data + plane.TotalBytes()) {
    halves = _mm_and_si128(_mm_loadu_si128(reinterpret_cast<const __m128i*>(p)), m.halves);
  } else {
    halves = _mm_maskload_epi32(reinterpret_cast<const int*>(p), m.pairs);
    uint16_t last;
    std::memcpy(&last, p + m.last_offset, 2);
    halves = _mm_blendv_epi8(halves, _mm_set1_epi16(short(last)), m.last);
  }
  return (F8)_mm256_cvtph_ps(halves);
}
inline void StorePixel(float* p, const ChannelMask& m, F8 value) {
  _mm256_maskstore_ps(p, m.floats, (__m256)value);
}
#endif
inline F8 PixelChannels(const BytePlane&, const char*, const ChannelMask&) {
  return F8{};  // never called: BytePlane::WholePixels() is false
}

// One view's weighted bilinear samples at pixels [x, x + 16) of row y added to acc[lane] (every
// channel at once, `m`: MaskOf the planes' channels) and its weight to `weight_sum`, lane by
// covered lane.
template <class Plane>
inline void AddViewPixels(const WarpField& w, const Plane& p, float view_weight,
                          const BlendOptions& o, const PixelLimits<F16>& limits, int y, int x,
                          const ChannelMask& m, F8* acc, F16& weight_sum) {
  const auto f = FootprintOf(w, p, view_weight, o, limits, y, x);
  weight_sum += f.weight;
  unsigned lanes = core::lanes::Bits(f.valid);
  if (!lanes) return;
  const I16 row0 = f.at.y0 * p.RowBytes(), row1 = f.at.y1 * p.RowBytes();
  const I16 col0 = f.at.x0 * p.pixel_bytes, col1 = f.at.x1 * p.pixel_bytes;
  const I16 o00 = row0 + col0, o10 = row0 + col1, o01 = row1 + col0, o11 = row1 + col1;
  // The source lines the next virtual rows will read, fetched ahead: these samples wait on
  // memory (seven views' parameter planes are 14 MB), and a turned view's rows slant where the
  // hardware prefetcher does not follow.
  constexpr int kRowsAhead = 2;
  const std::size_t ahead = std::size_t(kRowsAhead) * std::size_t(p.RowBytes());
  for (int k : {0, 4, 8, 12, 15}) {  // sixteen pixels' bottom corners span a few lines
    const std::size_t at = std::size_t(o01[k]) + ahead;
    if (at < p.TotalBytes()) __builtin_prefetch(p.data + at);
  }
  while (lanes) {
    const int k = __builtin_ctz(lanes);
    lanes &= lanes - 1;
    acc[k] += f.w00[k] * PixelChannels(p, p.data + o00[k], m) +
              f.w10[k] * PixelChannels(p, p.data + o10[k], m) +
              f.w01[k] * PixelChannels(p, p.data + o01[k], m) +
              f.w11[k] * PixelChannels(p, p.data + o11[k], m);
  }
}

// BlendPixels for sixteen pixels of planes read a pixel at a time.
template <class Plane>
inline int BlendWholePixels(const std::vector<const WarpField*>& warps,
                            const std::vector<Plane>& planes, const std::vector<float>& weights,
                            const BlendOptions& o, int y, int x, BlendResult& out) {
  const PixelLimits<F16> limits = LimitsAt<F16>(warps, o, y, x);
  const int channels = planes[0].channels;  // every view's (CheckInput)
  const ChannelMask m = MaskOf(channels);
  F8 acc[kLanes] = {};
  F16 weight_sum{};
  for (std::size_t k = 0; k < warps.size(); ++k) {
    AddViewPixels(*warps[k], planes[k], weights[k], o, limits, y, x, m, acc, weight_sum);
  }
  float* row = out.value.ptr<float>(y) + std::size_t(x) * channels;
  const F8 nan = F8{} + std::numeric_limits<float>::quiet_NaN();
  for (int k = 0; k < kLanes; ++k) {
    // Divide, not multiply by 1/sum: a sum of tiny (denormal) weights has no finite inverse.
    const F8 value = weight_sum[k] > 0.0f ? acc[k] / weight_sum[k] : nan;
    StorePixel(row + std::size_t(k) * channels, m, value);
  }
  return StoreValid(out.valid.ptr<uint8_t>(y) + x, weight_sum > 0.0f);
}
#else
constexpr bool kPixelReads = false;
template <class Plane>
inline int BlendWholePixels(const std::vector<const WarpField*>&, const std::vector<Plane>&,
                            const std::vector<float>&, const BlendOptions&, int, int,
                            BlendResult&) {
  return 0;  // never called: kPixelReads is false
}
#endif

// The blend at pixels [x, x + lanes) of row y: per pass of channels, every view's samples summed
// in registers, then divided by the weight sum and written interleaved; NaN where no view
// contributed. Returns the pixels covered.
template <typename T, class Plane, int kChannels = 0>
inline int BlendPixels(const std::vector<const WarpField*>& warps, const std::vector<Plane>& planes,
                       const std::vector<float>& weights, const BlendOptions& o, int y, int x,
                       BlendResult& out) {
  const std::size_t views = warps.size();
  const PixelLimits<T> limits = LimitsAt<T>(warps, o, y, x);
  const int channels = kChannels > 0 ? kChannels : planes[0].channels;
  float* row = out.value.ptr<float>(y);
  T weight_sum{};
  for (int c0 = 0; c0 < channels; c0 += kPassChannels) {
    const int n = std::min(kPassChannels, channels - c0);
    T acc[kPassChannels] = {};
    weight_sum = T{};
    for (std::size_t k = 0; k < views; ++k) {
      AddView(*warps[k], planes[k], weights[k], o, limits, y, x, c0, n, acc, weight_sum);
    }
    // Divide, not multiply by 1/sum: a sum of tiny (denormal) weights has no finite inverse.
    const auto hit = weight_sum > 0.0f;
    const T nan = T{} + std::numeric_limits<float>::quiet_NaN();
    for (int i = 0; i < n; ++i) {
      ScatterLane(row + std::size_t(x) * channels + c0 + i, channels,
                  Select(hit, acc[i] / weight_sum, nan));
    }
  }
  return StoreValid(out.valid.ptr<uint8_t>(y) + x, weight_sum > 0.0f);
}

// The kernel for groups of sixteen pixels: 8-bit planes (1–4 channels, the usual images) with
// their channel count known to the compiler, which then keeps the sums in registers and unrolls
// the channel loops; other planes with it read at run time.
template <class Plane>
auto GroupKernelFor(const Plane& p) {
  if constexpr (std::is_same_v<Plane, BytePlane>) {
    return core::WithCount<4, 1, 2, 3>(
        p.channels, [](auto n) { return &BlendPixels<F16, Plane, decltype(n)::value>; });
  }
  return &BlendPixels<F16, Plane>;
}

// Every pixel of `rows`, on all cores when `parallel`.
template <class Plane>
int BlendAll(const std::vector<const WarpField*>& warps, const std::vector<Plane>& planes,
             const std::vector<float>& weights, const BlendOptions& o, const cv::Range& rows,
             bool parallel, BlendResult& out) {
  const int width = out.value.cols;
  const bool whole_pixels = kPixelReads && planes[0].WholePixels();
  const auto group = GroupKernelFor(planes[0]);
  std::vector<int> covered(std::size_t(rows.size()), 0);
  const auto blend = [&](const cv::Range& part) {
    for (int y = part.start; y < part.end; ++y) {
      int x = 0, n = 0;
      for (; x + kLanes <= width; x += kLanes) {
        n += whole_pixels ? BlendWholePixels(warps, planes, weights, o, y, x, out)
                          : group(warps, planes, weights, o, y, x, out);
      }
      for (; x < width; ++x) n += BlendPixels<float>(warps, planes, weights, o, y, x, out);
      covered[std::size_t(y - rows.start)] = n;
    }
  };
  if (parallel) {
    cv::parallel_for_(rows, blend);
  } else {
    blend(rows);
  }
  return std::accumulate(covered.begin(), covered.end(), 0);
}

// Throws std::invalid_argument unless `planes` and `o` fit `warps`.
void CheckInput(const std::vector<WarpField>& warps, const std::vector<cv::Mat>& planes,
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
  const cv::Size size = warps[0].map.size();
  const bool reads_depth = o.depth_tolerance > 0.0 || o.resolution_power > 0.0;
  for (std::size_t k = 0; k < warps.size(); ++k) {
    if (planes[k].channels() != channels || warps[k].map.size() != size ||
        (reads_depth && warps[k].depth.size() != size)) {
      throw std::invalid_argument("BlendPlanes: view " + std::to_string(k) +
                                  " disagrees in channels or virtual size");
    }
    if (o.angle_power > 0.0 && warps[k].cos_angle.empty()) {
      throw std::invalid_argument(
          "BlendPlanes: angle_power needs warps with view angles (WarpOutputsFor)");
    }
    if (reads_depth && warps[k].depth.empty()) {
      throw std::invalid_argument(
          "BlendPlanes: depth_tolerance and resolution_power need warps with depth "
          "(WarpOutputsFor)");
    }
    if (o.resolution_power > 0.0 && warps[k].source_depth.empty()) {
      throw std::invalid_argument(
          "BlendPlanes: resolution_power needs warps with source depth (WarpOutputsFor)");
    }
    const int depth = planes[k].depth();
    if (depth != CV_8U && depth != CV_16U && depth != CV_16S && depth != CV_16F &&
        depth != CV_32F && depth != CV_64F) {
      throw std::invalid_argument("BlendPlanes: unsupported plane depth " + std::to_string(depth));
    }
  }
}

// Rows `rows` of the blend into `result` (checked and sized); returns the pixels covered there.
int BlendInto(const std::vector<WarpField>& warps, const std::vector<cv::Mat>& planes,
              const BlendOptions& o, const cv::Range& rows, bool parallel, BlendResult& result) {
  std::vector<const WarpField*> fields;
  std::vector<float> weights;
  for (std::size_t k = 0; k < warps.size(); ++k) {
    fields.push_back(&warps[k]);
    weights.push_back(o.weights.empty() ? 1.0f : float(o.weights[k]));
  }
  if (const auto bytes = AsBytePlanes(planes)) {
    return BlendAll(fields, *bytes, weights, o, rows, parallel, result);
  }
  if (const auto half = AsHalfPlanes(planes)) {
    return BlendAll(fields, *half, weights, o, rows, parallel, result);
  }
  std::vector<cv::Mat> scratch;
  return BlendAll(fields, AsFloatPlanes(planes, scratch), weights, o, rows, parallel, result);
}

}  // namespace

WarpOutputs WarpOutputsFor(const BlendOptions& blend) {
  WarpOutputs out;
  out.source_depth = blend.resolution_power > 0.0;
  out.view_angles = blend.angle_power > 0.0;
  out.depth = blend.depth_tolerance > 0.0 || out.source_depth ||
              out.view_angles;  // (the view angles are found from the depth)
  return out;
}

BlendResult BlendPlanes(const std::vector<WarpField>& warps, const std::vector<cv::Mat>& planes,
                        const BlendOptions& o) {
  BlendResult result;
  BlendPlanes(warps, planes, o, result);
  return result;
}

void BlendPlanes(const std::vector<WarpField>& warps, const std::vector<cv::Mat>& planes,
                 const BlendOptions& o, BlendResult& result) {
  PrepareBlend(warps, planes, o, result);
  result.covered = BlendInto(warps, planes, o, cv::Range(0, result.value.rows), true, result);
}

void PrepareBlend(const std::vector<WarpField>& warps, const std::vector<cv::Mat>& planes,
                  const BlendOptions& o, BlendResult& result) {
  CheckInput(warps, planes, o);
  // In place unless another owner shares the images (create() alone would write into theirs).
  for (cv::Mat* m : {&result.value, &result.valid}) {
    if (m->u && m->u->refcount > 1) m->release();
  }
  result.value.create(warps[0].map.size(), CV_32FC(planes[0].channels()));
  result.valid.create(warps[0].map.size(), CV_8UC1);
  result.covered = 0;
}

int BlendRows(const std::vector<WarpField>& warps, const std::vector<cv::Mat>& planes,
              const BlendOptions& o, const cv::Range& rows, BlendResult& result) {
  CheckInput(warps, planes, o);
  const bool prepared = result.value.size() == warps[0].map.size() &&
                        result.value.type() == CV_32FC(planes[0].channels()) &&
                        result.valid.size() == result.value.size() &&
                        result.valid.type() == CV_8UC1;
  if (!prepared || rows.start < 0 || rows.end > result.value.rows || rows.start > rows.end) {
    throw std::invalid_argument("BlendRows: rows " + std::to_string(rows.start) + "–" +
                                std::to_string(rows.end) +
                                " of a result that PrepareBlend did not size for these planes");
  }
  return BlendInto(warps, planes, o, rows, false, result);
}

}  // namespace novelty::views
