// How the blend kernel (view_blender.cc) reads a view's plane in place: 8-bit, half-float or
// float pixels, each channel's value from 32-bit words gathered from memory or taken from row
// windows (core/row_windows.h). Included by view_blender.cc only.
#pragma once

#include <algorithm>
#include <array>
#include <opencv2/core.hpp>
#include <optional>
#include <vector>

#include "core/row_windows.h"
#include "maps/views/blend_lanes.h"

namespace novelty::views::blend {

using core::lanes::F16;
using core::lanes::I16;
using core::lanes::kLanes;

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
  static I16 Min(I16 a, int b) { return Select(a < b, a, I16{} + b); }
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

inline bool AllOfDepth(const std::vector<cv::Mat>& planes, int depth) {
  return std::all_of(planes.begin(), planes.end(),
                     [&](const cv::Mat& p) { return p.depth() == depth && p.isContinuous(); });
}

// The views' planes in one form for all (the kernel is compiled per form): bytes or half floats
// in place when every plane is continuous of that kind, else floats (converted where needed into
// `scratch`, one per view).
inline std::optional<std::vector<BytePlane>> AsBytePlanes(const std::vector<cv::Mat>& planes) {
  if (!AllOfDepth(planes, CV_8U) || planes[0].channels() > 4) return std::nullopt;
  std::vector<BytePlane> out;
  for (const cv::Mat& p : planes) {
    if (p.total() * p.elemSize() < 4) return std::nullopt;
    out.push_back(MakePlane<BytePlane>(p));
  }
  return out;
}

inline std::optional<std::vector<HalfPlane>> AsHalfPlanes(const std::vector<cv::Mat>& planes) {
  const int channels = planes[0].channels();
  if (!AllOfDepth(planes, CV_16F) || channels < 2 || channels > HalfPlane::kMaxChannels)
    return std::nullopt;
  std::vector<HalfPlane> out;
  for (const cv::Mat& p : planes) out.push_back(MakePlane<HalfPlane>(p));
  return out;
}

inline std::vector<FloatPlane> AsFloatPlanes(const std::vector<cv::Mat>& planes,
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

}  // namespace novelty::views::blend
