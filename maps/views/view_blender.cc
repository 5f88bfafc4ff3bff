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

namespace novelty::views {

namespace {

using core::lanes::F16;
using core::lanes::I16;
using core::lanes::kLanes;

// Scalar (one pixel) and vector (sixteen) forms of the few operations the sampling kernel needs,
// so that one kernel serves the row's body and its tail.
inline float LoadLane(const float* p, float) {
  return *p;
}
inline F16 LoadLane(const float* p, F16) {
  return core::lanes::Load(p);
}
inline int ToInt(float x) {
  return int(x);
}
inline I16 ToInt(F16 x) {
  return core::lanes::AsInt(x);
}
inline float ToFloat(int x) {
  return float(x);
}
inline F16 ToFloat(I16 x) {
  return core::lanes::AsFloat(x);
}
inline int GatherBytes(const char* base, int offset) {
  int v;
  std::memcpy(&v, base + offset, 4);
  return v;
}
inline I16 GatherBytes(const char* base, I16 offset) {
  return core::lanes::GatherBytes(base, offset);
}
inline float AsFloatBits(int bits) {
  float f;
  std::memcpy(&f, &bits, 4);
  return f;
}
inline F16 AsFloatBits(I16 bits) {
  return (F16)bits;
}
// IEEE half floats (in the low 16 bits) to float (lanes.h).
inline float HalfToFloat(int bits) {
  return core::lanes::HalfToFloat(uint32_t(bits));
}
inline F16 HalfToFloat(I16 bits) {
  return core::lanes::HalfToFloat(bits);
}
// Stores one value (T = float) or sixteen at `stride` floats apart (interleaved channels).
inline void ScatterLane(float* p, int, float v) {
  *p = v;
}
inline void ScatterLane(float* p, int stride, F16 v) {
  core::lanes::Scatter(p, core::lanes::AsInt(core::lanes::Iota()) * stride, v);
}
// 255 where `hit`, 0 elsewhere, for one pixel or sixteen; returns how many are hit.
inline int StoreValid(uint8_t* p, bool hit) {
  *p = hit ? 255 : 0;
  return hit;
}
inline int StoreValid(uint8_t* p, I16 hit) {
  core::lanes::StoreMaskBytes(p, hit);
  return core::lanes::Count(hit);
}
// x^p for one pixel or sixteen. Whole powers up to 64 (the blend's usual ones) by repeated
// squaring, in vector registers: std::pow lane by lane dominated a blend with angle_power
// (BM_AppearanceMapSevenViews with angle_power set).
template <typename T>
inline T Pow(T x, float p) {
  const int n = int(p);
  if (float(n) == p && n >= 1 && n <= 64) {
    T result = T{} + 1.0f;
    for (int e = n; e > 0; e >>= 1, x = x * x)
      if (e & 1) result = result * x;
    return result;
  }
  if constexpr (std::is_same_v<T, float>) {
    return std::pow(x, p);
  } else {
    for (int k = 0; k < kLanes; ++k) x[k] = std::pow(x[k], p);
    return x;
  }
}
template <typename T>
inline T Max(T x, float lo) {
  return x > lo ? x : T{} + lo;
}
// The least cosine angle_power weighs (a view seen edge-on or from behind counts as this).
constexpr float kMinCos = 1e-6f;
// Per-pixel bounds of the views' say (LimitsAt).
template <typename T>
struct PixelLimits {
  T nearest;   // depth limit of depth_tolerance; +inf without
  T best_cos;  // largest cos(view angle) among the contributing views; 1 without angle_power
};
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
  core::lanes::LoadMaskedPairs(&(*map)[0], I16{} - 1, u, v);
}

// The channels one pass of the kernel sums in registers; planes with more take several passes.
constexpr int kPassChannels = 8;

// Where a plane's 32-bit words come from: Word(x_byte, y) is the word at byte x_byte of row y.
// Gathered from memory (one pixel or sixteen)...
struct GatherReader {
  const char* data;
  int row_bytes, last_word;  // last_word: the plane's size in bytes − 4
  template <class I>
  I Word(I x_byte, I y) const {
    // An 8-bit pixel's word runs past the pixel, and the last one's past the plane: a word
    // starts at most four bytes before the plane's end and is shifted down to its byte.
    const I byte = y * row_bytes + x_byte;
    const I start = Min(byte, last_word);
    return GatherBytes(data, start) >> ((byte - start) * 8);  // Values read the low bytes only
  }
  static int Min(int a, int b) { return std::min(a, b); }
  static I16 Min(I16 a, int b) { return a < b ? a : I16{} + b; }
};

// ... or from core::RowWindows holding the source rows that sixteen pixels read (row_windows.h).
struct WindowReader {
  const core::RowWindows& windows;
  int row0, first;  // the windows' first row and first byte
  I16 Word(I16 x_byte, I16 y) const { return windows.Read(y - row0, x_byte - first); }
};

// A view's plane as the kernel reads it, in place, in one of three forms; Corner(reader, x, y,
// c0, n) reads the words of channels [c0, c0 + n) at pixel (x, y), Value(words, c0, c) is
// channel c among them. Every word read lies inside its pixel but an 8-bit pixel's, which runs
// at most three bytes past it (LastWordOffset(): where the last word of a pixel starts).
//   float: continuous floats, a word per channel;
//   bytes: 8-bit planes of 1–4 channels, one word holding every channel;
//   half:  half-float planes of 2–8 channels, a word per two channels (the last word of an odd
//          count starts one channel earlier, so it stays inside the pixel).
struct PlaneLayout {
  const char* data;
  int cols, rows, channels, pixel_bytes;
  int RowBytes() const { return cols * pixel_bytes; }
  std::size_t TotalBytes() const { return std::size_t(rows) * RowBytes(); }
  GatherReader Gatherer() const { return {data, RowBytes(), int(TotalBytes()) - 4}; }
};

struct FloatPlane : PlaneLayout {
  bool WholePixels() const { return channels >= 2 && channels <= 8; }
  int LastWordOffset() const { return 4 * (channels - 1); }
  template <class R, class I>
  std::array<I, kPassChannels> Corner(const R& r, I x, I y, int c0, int n) const {
    std::array<I, kPassChannels> words{};
    const I byte = x * pixel_bytes;
    for (int i = 0; i < n; ++i) words[std::size_t(i)] = r.Word(byte + 4 * (c0 + i), y);
    return words;
  }
  template <class T, class W>
  T Value(const W& words, int c0, int c) const {
    return AsFloatBits(words[std::size_t(c - c0)]);
  }
};

struct BytePlane : PlaneLayout {
  bool WholePixels() const { return false; }
  int LastWordOffset() const { return 0; }
  template <class R, class I>
  std::array<I, 1> Corner(const R& r, I x, I y, int, int) const {
    return {r.Word(x * pixel_bytes, y)};
  }
  template <class T, class W>
  T Value(const W& words, int, int c) const {
    return ToFloat((words[0] >> (8 * c)) & 0xFF);
  }
};

struct HalfPlane : PlaneLayout {
  static constexpr int kMaxChannels = 8;
  bool WholePixels() const { return true; }
  int First(int word) const { return std::min(2 * word, channels - 2); }
  int LastWordOffset() const { return 2 * (channels - 2); }
  template <class R, class I>
  std::array<I, kMaxChannels / 2> Corner(const R& r, I x, I y, int, int) const {
    std::array<I, kMaxChannels / 2> words{};
    const I byte = x * pixel_bytes;
    for (int w = 0; w < (channels + 1) / 2; ++w) words[w] = r.Word(byte + 2 * First(w), y);
    return words;
  }
  template <class T, class W>
  T Value(const W& words, int, int c) const {
    const auto word = words[std::size_t(c / 2)];
    return HalfToFloat(c == First(c / 2) ? word : word >> 16);
  }
};

template <class Plane>
Plane MakePlane(const cv::Mat& m) {
  Plane p;
  static_cast<PlaneLayout&>(p) = {reinterpret_cast<const char*>(m.ptr()), m.cols, m.rows,
                                  m.channels(), int(m.elemSize())};
  return p;
}

bool AllOfDepth(const std::vector<cv::Mat>& planes, int depth) {
  return std::all_of(planes.begin(), planes.end(),
                     [&](const cv::Mat& p) { return p.depth() == depth && p.isContinuous(); });
}

// The views' planes in one form for all (the kernel is compiled per form): bytes or half floats
// in place when every plane is continuous of that kind, else floats (converted where needed into
// `scratch`, one per view).
std::optional<std::vector<BytePlane>> AsBytePlanes(const std::vector<cv::Mat>& planes) {
  if (!AllOfDepth(planes, CV_8U) || planes[0].channels() > 4) return std::nullopt;
  std::vector<BytePlane> out;
  for (const cv::Mat& p : planes) {
    if (p.total() * p.elemSize() < 4) return std::nullopt;
    out.push_back(MakePlane<BytePlane>(p));
  }
  return out;
}

std::optional<std::vector<HalfPlane>> AsHalfPlanes(const std::vector<cv::Mat>& planes) {
  const int channels = planes[0].channels();
  if (!AllOfDepth(planes, CV_16F) || channels < 2 || channels > HalfPlane::kMaxChannels)
    return std::nullopt;
  std::vector<HalfPlane> out;
  for (const cv::Mat& p : planes) out.push_back(MakePlane<HalfPlane>(p));
  return out;
}

std::vector<FloatPlane> AsFloatPlanes(const std::vector<cv::Mat>& planes,
                                      std::vector<cv::Mat>& scratch) {
  scratch.resize(planes.size());
  std::vector<FloatPlane> out;
  for (std::size_t k = 0; k < planes.size(); ++k) {
    const cv::Mat* m = &planes[k];
    if (m->depth() != CV_32F || !m->isContinuous()) {
      m->convertTo(scratch[k], CV_32F);
      m = &scratch[k];
    }
    out.push_back(MakePlane<FloatPlane>(*m));
  }
  return out;
}

// The source pixels of a bilinear sample per lane: columns x0, x1, rows y0, y1.
template <class I>
struct Corners {
  I x0, x1, y0, y1;
};

// Adds channels [c0, c0 + n) of the weighted bilinear samples at `at` to acc[0…n), read by `r`.
template <class Plane, class R, class T, class I, class M>
inline void Sample(const Plane& p, const R& r, const Corners<I>& at, T w00, T w10, T w01, T w11,
                   M valid, int c0, int n, T* acc) {
  const auto c00 = p.Corner(r, at.x0, at.y0, c0, n), c10 = p.Corner(r, at.x1, at.y0, c0, n);
  const auto c01 = p.Corner(r, at.x0, at.y1, c0, n), c11 = p.Corner(r, at.x1, at.y1, c0, n);
  for (int i = 0; i < n; ++i) {
    const int c = c0 + i;
    const T sample = w00 * p.template Value<T>(c00, c0, c) + w10 * p.template Value<T>(c10, c0, c) +
                     w01 * p.template Value<T>(c01, c0, c) + w11 * p.template Value<T>(c11, c0, c);
    acc[i] += valid ? sample : T{};  // select: a NaN sample stays out
  }
}

#if defined(__AVX512VBMI__) && defined(__AVX512BW__)
constexpr bool kNarrowReads = true;
// An 8-bit plane of n channels (a word holds a pixel) where sixteen covered samples lie within
// 64 bytes of a row and their top corners on two neighbouring rows: the usual case between views
// of similar resolution and orientation. Three row registers (rows y_min … y_min + 2, from the
// leftmost corner's byte) serve every corner with one two-register byte permute each — no
// gather, and a fraction of core::RowWindows' work (its 256-byte rows and per-row selects). Returns
// false, having read nothing, where the samples lie further apart.
inline __attribute__((always_inline)) bool SampleBytesNarrow(const BytePlane& p,
                                                             const Corners<I16>& at, F16 w00,
                                                             F16 w10, F16 w01, F16 w11, I16 valid,
                                                             int n, F16* acc) {
  const int x_min = core::lanes::MinLane(at.x0, valid);
  const int y_min = core::lanes::MinLane(at.y0, valid);
  // Byte offsets from x_min (0 in uncovered lanes, whose reads are discarded).
  const I16 byte0 = valid ? (at.x0 - x_min) * n : I16{},
            byte1 = valid ? (at.x1 - x_min) * n : I16{};
  if (core::lanes::Any(valid & ((byte1 > 64 - 4) | (at.y0 - y_min > 1)))) return false;
  const std::size_t total = p.TotalBytes();
  __m512i rows[3];
  for (int k = 0; k < 3; ++k) {
    const std::size_t start =
        std::size_t(std::min(y_min + k, p.rows - 1)) * std::size_t(p.RowBytes()) +
        std::size_t(x_min) * std::size_t(n);
    const std::size_t left = total - start;  // (nothing past the plane is read)
    const __mmask64 mask = left >= 64 ? ~__mmask64{0} : (__mmask64{1} << left) - 1;
    rows[k] = _mm512_maskz_loadu_epi8(mask, p.data + start);
  }
  // Bit 6 of a byte's index picks the pair's second row: top corners read rows (y_min,
  // y_min + 1), bottom ones the next pair. (A bottom corner clamped to the last row, y1 = y0,
  // reads a row that the clamped loads made the last row as well.)
  const I16 second = valid ? (at.y0 - y_min) << 6 : I16{};
  const auto word = [](const __m512i& a, const __m512i& b, I16 byte) {
    return (I16)_mm512_permutex2var_epi8(a, (__m512i)(byte * 0x01010101 + 0x03020100), b);
  };
  const I16 c00 = word(rows[0], rows[1], byte0 + second),
            c10 = word(rows[0], rows[1], byte1 + second);
  const I16 c01 = word(rows[1], rows[2], byte0 + second),
            c11 = word(rows[1], rows[2], byte1 + second);
  for (int c = 0; c < n; ++c) {
    const auto value = [c](I16 w) { return core::lanes::AsFloat((w >> (8 * c)) & 0xFF); };
    const F16 sample = w00 * value(c00) + w10 * value(c10) + w01 * value(c01) + w11 * value(c11);
    acc[c] += valid ? sample : F16{};
  }
  return true;
}
#else
constexpr bool kNarrowReads = false;
inline bool SampleBytesNarrow(const BytePlane&, const Corners<I16>&, F16, F16, F16, F16, I16, int,
                              F16*) {
  return false;  // never called: kNarrowReads is false
}
#endif

// The rows and bytes that sixteen lanes' covered samples read, if core::RowWindows can hold them
// (rows = 0: it cannot — a magnified, shrunk or turned view, whose lanes then gather).
struct WindowSpan {
  int row0 = 0, rows = 0, first = 0;
  int x_min = 0;
  // Uncovered lanes read where the first covered lane reads (their weight is 0).
  Corners<I16> Inside(I16 valid, const Corners<I16>& at) const {
    const I16 x = I16{} + x_min, y = I16{} + row0;
    return {valid ? at.x0 : x, valid ? at.x1 : x, valid ? at.y0 : y, valid ? at.y1 : y};
  }
};

template <class Plane>
inline WindowSpan SpanOf(const Plane& p, I16 valid, const Corners<I16>& at) {
  WindowSpan s;
  const int x_min = core::lanes::MinLane(at.x0, valid), x_max = core::lanes::MaxLane(at.x1, valid);
  const int y_min = core::lanes::MinLane(at.y0, valid), y_max = core::lanes::MaxLane(at.y1, valid);
  const int last_read = (x_max - x_min) * p.pixel_bytes + p.LastWordOffset();
  if (y_max - y_min >= core::RowWindows::kMaxRows || last_read > core::RowWindows::kBytes - 4)
    return s;
  s.row0 = y_min;
  s.rows = y_max - y_min + 1;
  s.first = x_min * p.pixel_bytes;
  s.x_min = x_min;
  return s;
}

// Where one view's bilinear samples at pixels [x, x + lanes) of row y read, and with what
// weights: the corners, and per corner the view's weight times the bilinear one (0 where the view
// does not cover the pixel).
template <typename T, typename I, typename M>
struct Footprint {
  M valid;   // the view covers the pixel (and lies within depth_tolerance)
  T weight;  // the view's weight at the pixel, 0 where not valid
  Corners<I> at;
  T w00, w10, w01, w11;
};

// The footprint of `w` at pixels [x, x + lanes) of row y in `p`, within `limits` (LimitsAt).
// Coordinates are clamped to the source image (the border replicated). T = float for one pixel,
// F16 for sixteen.
template <typename T, class Plane>
inline auto FootprintOf(const WarpField& w, const Plane& p, float view_weight,
                        const BlendOptions& o, const PixelLimits<T>& limits, int y, int x) {
  T u, v;
  LoadMap(w.map.ptr<cv::Vec2f>(y) + x, u, v);
  // The map rows are streamed once per view; fetching ahead hides the misses. Every line the
  // pixels span is fetched: sixteen pixels' (u, v) fill two lines, and fetching only the first
  // left every other line a miss (BM_AppearanceMapSevenViews, docs/performance_history.md).
  const char* ahead = reinterpret_cast<const char*>(w.map.ptr<cv::Vec2f>(y) + x + 64);
  for (std::size_t b = 0; b < 2 * sizeof(T); b += 64) __builtin_prefetch(ahead + b);
  // Covered where the map holds source coordinates (uncovered: −1): the depth is read only when
  // an option needs it, which saves a third of what the kernel streams through.
  auto valid = u > -0.5f;
  T d{};
  if (o.depth_tolerance > 0.0 || o.resolution_power > 0.0) {
    d = LoadLane(w.depth.ptr<float>(y) + x, T{});
    valid = valid & (d <= limits.nearest);
  }
  T weight = T{} + view_weight;
  if (o.resolution_power > 0.0) {
    weight *= Pow(d / LoadLane(w.source_depth.ptr<float>(y) + x, T{}), float(o.resolution_power));
  }
  if (o.angle_power > 0.0) {  // relative to the best view: ≤ 1, and 1 for that view
    const T cos_angle = Max(LoadLane(w.cos_angle.ptr<float>(y) + x, T{}), kMinCos);
    weight *= Pow(cos_angle / limits.best_cos, float(o.angle_power));
  }
  weight = valid ? weight : T{};
  u = Clamp(u, 0.0f, float(p.cols - 1));
  v = Clamp(v, 0.0f, float(p.rows - 1));
  const auto x0 = ToInt(u), y0 = ToInt(v);  // non-negative: truncation is floor
  const auto x1 = x0 + (x0 < p.cols - 1 ? 1 : 0), y1 = y0 + (y0 < p.rows - 1 ? 1 : 0);
  const T fx = u - ToFloat(x0), fy = v - ToFloat(y0);
  using I = std::remove_const_t<decltype(x0)>;
  return Footprint<T, I, decltype(valid)>{valid,
                                          weight,
                                          {x0, x1, y0, y1},
                                          weight * (1.0f - fx) * (1.0f - fy),
                                          weight * fx * (1.0f - fy),
                                          weight * (1.0f - fx) * fy,
                                          weight * fx * fy};
}

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

// What bounds each view's say at pixels [x, x + lanes) of row y, over the views that cover
// them: the depth beyond which views do not contribute (the nearest view's depth stretched by
// depth_tolerance; +inf without), and the largest cosine of the view angle among the views that
// do (angle_power's reference; 1 without). Weighting relative to the best view keeps that
// view's weight at 1: cos^p of an absolute angle underflows to 0 for p = 10⁴ a few degrees off,
// which would uncover a pixel that views cover.
template <typename T>
inline PixelLimits<T> LimitsAt(const std::vector<const WarpField*>& warps, const BlendOptions& o,
                               int y, int x) {
  PixelLimits<T> limits{T{} + std::numeric_limits<float>::infinity(), T{} + 1.0f};
  if (o.depth_tolerance > 0.0) {  // only views within the tolerance of the nearest depth
    for (const WarpField* w : warps) {
      const T d = LoadLane(w->depth.ptr<float>(y) + x, T{});
      limits.nearest = (d > 0.0f) & (d < limits.nearest) ? d : limits.nearest;
    }
    limits.nearest *= float(1.0 + o.depth_tolerance);
  }
  if (o.angle_power > 0.0) {
    T best = T{} + kMinCos;
    for (const WarpField* w : warps) {
      T u, v;
      LoadMap(w->map.ptr<cv::Vec2f>(y) + x, u, v);
      auto counts = u > -0.5f;
      if (o.depth_tolerance > 0.0)
        counts = counts & (LoadLane(w->depth.ptr<float>(y) + x, T{}) <= limits.nearest);
      const T c = LoadLane(w->cos_angle.ptr<float>(y) + x, T{});
      best = counts & (c > best) ? c : best;
    }
    limits.best_cos = best;
  }
  return limits;
}

#if defined(__AVX512F__) && defined(__AVX512VL__) && defined(__AVX512BW__) && defined(__F16C__)
// Planes of 2–8 half or float channels (Plane::WholePixels) are read a pixel at a time: one
// masked load gives all channels of a corner, where the gather path needs a gather per corner and
// word, and a gather costs several times a load here. Seven views' parameter planes (7 half and
// 3 float channels) blend about 1.7× faster this way. Without AVX-512 the gather path serves them.
constexpr bool kPixelReads = true;
typedef float F8 __attribute__((vector_size(32)));

// All channels of the pixel at `p` as floats (`m`: one bit per channel; nothing else is read).
inline F8 PixelChannels(const FloatPlane&, const char* p, __mmask8 m) {
  return (F8)_mm256_maskz_loadu_ps(m, p);
}
inline F8 PixelChannels(const HalfPlane&, const char* p, __mmask8 m) {
  return (F8)_mm256_cvtph_ps(_mm_maskz_loadu_epi16(m, p));
}
inline F8 PixelChannels(const BytePlane&, const char*, __mmask8) {
  return F8{};  // never called: BytePlane::WholePixels() is false
}

// One view's weighted bilinear samples at pixels [x, x + 16) of row y added to acc[lane] (every
// channel at once) and its weight to `weight_sum`, lane by covered lane.
template <class Plane>
inline void AddViewPixels(const WarpField& w, const Plane& p, float view_weight,
                          const BlendOptions& o, const PixelLimits<F16>& limits, int y, int x,
                          F8* acc, F16& weight_sum) {
  const auto f = FootprintOf(w, p, view_weight, o, limits, y, x);
  weight_sum += f.weight;
  unsigned lanes = core::lanes::Bits(f.valid);
  if (!lanes) return;
  const I16 row0 = f.at.y0 * p.RowBytes(), row1 = f.at.y1 * p.RowBytes();
  const I16 col0 = f.at.x0 * p.pixel_bytes, col1 = f.at.x1 * p.pixel_bytes;
  const I16 o00 = row0 + col0, o10 = row0 + col1, o01 = row1 + col0, o11 = row1 + col1;
  const __mmask8 m = __mmask8((1u << p.channels) - 1);
  // The source lines the next virtual rows will read, fetched ahead: these samples wait on
  // memory (seven views' parameter planes are 14 MB), and a turned view's rows slant where the
  // hardware prefetcher does not follow (parameter blend ≈ −20 %).
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
  F8 acc[kLanes] = {};
  F16 weight_sum{};
  for (std::size_t k = 0; k < warps.size(); ++k) {
    AddViewPixels(*warps[k], planes[k], weights[k], o, limits, y, x, acc, weight_sum);
  }
  const int channels = planes[0].channels;
  const __mmask8 m = __mmask8((1u << channels) - 1);
  float* row = out.value.ptr<float>(y) + std::size_t(x) * channels;
  const F8 nan = F8{} + std::numeric_limits<float>::quiet_NaN();
  for (int k = 0; k < kLanes; ++k) {
    // Divide, not multiply by 1/sum: a sum of tiny (denormal) weights has no finite inverse.
    const F8 value = weight_sum[k] > 0.0f ? acc[k] / weight_sum[k] : nan;
    _mm256_mask_storeu_ps(row + std::size_t(k) * channels, m, (__m256)value);
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
                  hit ? acc[i] / weight_sum : nan);
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
          "BlendPlanes: angle_power needs warps computed with "
          "compute_view_angles");
    }
    if (reads_depth && warps[k].depth.empty()) {
      throw std::invalid_argument(
          "BlendPlanes: depth_tolerance and resolution_power need warps computed with "
          "compute_depth");
    }
    if (o.resolution_power > 0.0 && warps[k].source_depth.empty()) {
      throw std::invalid_argument(
          "BlendPlanes: resolution_power needs warps computed with compute_source_depth");
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

WarpOptions WarpOptionsFor(const BlendOptions& blend, WarpOptions warp) {
  warp.compute_source_depth = blend.resolution_power > 0.0;
  warp.compute_view_angles = blend.angle_power > 0.0;
  warp.compute_depth = blend.depth_tolerance > 0.0 || warp.compute_source_depth ||
                       warp.compute_view_angles;  // (the view angles are found from the depth)
  return warp;
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
