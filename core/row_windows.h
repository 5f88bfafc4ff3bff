// Sixteen lanes' 32-bit reads from up to three consecutive rows of an image, served from
// registers instead of a gather. Each row's bytes [first, first + 256) are loaded once (four
// 64-byte registers) and each read picks every lane's four bytes with two byte permutes
// (AVX-512 VBMI). Blending warped views reads sixteen neighbouring pixels from a few neighbouring
// source pixels of each view, so one set of windows serves every corner and channel of a view's
// sixteen pixels, and a gather costs several times what the permutes do. Without VBMI,
// `kAvailable` is false and callers gather.
#pragma once

#include <algorithm>
#include <cstddef>

#include "core/lanes.h"

namespace novelty::core {

class RowWindows {
 public:
  static constexpr int kBytes = 256;  ///< bytes of each row a window holds
  static constexpr int kMaxRows = 3;
#if defined(__AVX512VBMI__) && defined(__AVX512BW__)
  static constexpr bool kAvailable = true;
#else
  static constexpr bool kAvailable = false;
#endif

  /// Loads rows row0 … row0 + rows − 1 (rows ≤ kMaxRows) of an image at `data` whose rows are
  /// `row_bytes` apart and which holds `total_bytes`: bytes [first, first + kBytes) of each, none
  /// past the image (those read as 0).
  RowWindows(const char* data, std::size_t total_bytes, std::size_t row_bytes, int row0, int rows,
             int first) {
#if defined(__AVX512VBMI__) && defined(__AVX512BW__)
    for (int r = 0; r < rows; ++r) {
      const std::size_t start = std::size_t(row0 + r) * row_bytes + std::size_t(first);
      for (int q = 0; q < 4; ++q) {
        const std::size_t at = start + 64 * std::size_t(q);
        const std::size_t left = total_bytes > at ? total_bytes - at : 0;
        const __mmask64 mask = left >= 64 ? ~__mmask64{0} : (__mmask64{1} << left) - 1;
        window_[r][q] = _mm512_maskz_loadu_epi8(mask, data + std::min(at, total_bytes));
      }
    }
#else
    (void)data, (void)total_bytes, (void)row_bytes, (void)row0, (void)rows, (void)first;
#endif
  }

  /// Per lane, the 32-bit word at byte `byte` (0 ≤ byte ≤ kBytes − 4, from `first`) of window
  /// row `row` (0 … rows − 1).
  core::lanes::I16 Read(core::lanes::I16 row, core::lanes::I16 byte) const {
#if defined(__AVX512VBMI__) && defined(__AVX512BW__)
    // Byte 4k + j of the result is byte `byte[k] + j` of the window (no carry: byte ≤ 252).
    const __m512i index = (__m512i)(byte * 0x01010101 + 0x03020100).p[0];
    const __mmask64 high = _mm512_movepi8_mask(index);  // bit 7: the window's second half
    core::lanes::I16 out{};
    for (int r = 0; r < kMaxRows; ++r) {
      const __mmask16 lanes = _mm512_cmpeq_epi32_mask((__m512i)row.p[0], _mm512_set1_epi32(r));
      if (!lanes) continue;
      const __m512i lo = _mm512_permutex2var_epi8(window_[r][0], index, window_[r][1]);
      const __m512i hi = _mm512_permutex2var_epi8(window_[r][2], index, window_[r][3]);
      out = core::lanes::BitCast<core::lanes::I16>(
          _mm512_mask_mov_epi32((__m512i)out.p[0], lanes, _mm512_mask_blend_epi8(high, lo, hi)));
    }
    return out;
#else
    (void)row;
    return byte;  // never called: kAvailable is false
#endif
  }

 private:
#if defined(__AVX512VBMI__) && defined(__AVX512BW__)
  __m512i window_[kMaxRows][4];
#endif
};

}  // namespace novelty::core
