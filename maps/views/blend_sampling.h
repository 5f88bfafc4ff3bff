// Bilinear samples of a view's plane for the blend kernel (view_blender.cc): the four corners
// of sixteen pixels read through a plane layout (blend_plane_layouts.h), from three row
// registers, row windows or gathers, whichever the samples' spread allows. Included by
// view_blender.cc only.
#pragma once

#include <algorithm>
#include <cstddef>

#include "core/lanes.h"
#include "core/row_windows.h"
#include "maps/views/blend_plane_layouts.h"

namespace novelty::views::blend {

using core::lanes::F16;
using core::lanes::I16;
using core::lanes::kLanes;

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
    acc[i] += Select(valid, sample, T{});  // select: a NaN sample stays out
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
  const I16 byte0 = Select(valid, (at.x0 - x_min) * n, I16{}),
            byte1 = Select(valid, (at.x1 - x_min) * n, I16{});
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
  const I16 second = Select(valid, (at.y0 - y_min) << 6, I16{});
  const auto word = [](const __m512i& a, const __m512i& b, I16 byte) {
    return core::lanes::BitCast<I16>(
        _mm512_permutex2var_epi8(a, (__m512i)(byte * 0x01010101 + 0x03020100).p[0], b));
  };
  const I16 c00 = word(rows[0], rows[1], byte0 + second),
            c10 = word(rows[0], rows[1], byte1 + second);
  const I16 c01 = word(rows[1], rows[2], byte0 + second),
            c11 = word(rows[1], rows[2], byte1 + second);
  for (int c = 0; c < n; ++c) {
    const auto value = [c](I16 w) { return core::lanes::AsFloat((w >> (8 * c)) & 0xFF); };
    const F16 sample = w00 * value(c00) + w10 * value(c10) + w01 * value(c01) + w11 * value(c11);
    acc[c] += Select(valid, sample, F16{});
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
    return {Select(valid, at.x0, x), Select(valid, at.x1, x), Select(valid, at.y0, y),
            Select(valid, at.y1, y)};
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

}  // namespace novelty::views::blend
