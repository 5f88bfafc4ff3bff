// Compact storage of a plane (depth, parameter planes), in map files and for the views a map
// holds compact in memory (reference_view_store.h): values rounded to the precision the maps
// can tell apart, then
//   - kPredicted (the default; map files from version 4 and memory): each rounded value as an
//     integer of its kept bits, predicted from its left, upper and upper-left neighbours of the
//     same channel by LOCO-I's median predictor (Weinberger et al. 2000, as in JPEG-LS), the
//     residual's bytes grouped by significance, zstd. Parameter planes and depth are smooth:
//     the residuals are small and their high bytes nearly all zero.
//   - kShuffled (map file version 3): the rounded values' bytes grouped by significance, zstd.
// Both with zstd's checksum: a damaged plane is refused, not decoded into other values.
//
// The defaults keep 14 of a float's 23 mantissa bits (relative error ≤ 2⁻¹⁵: 0.008 grey levels
// for τ at 255, 0.15 mm for a depth at 5 m) and 6 of a half float's 10 (α, β, σ within 2⁻⁷).
// On the glass-and-cup map (151 views at 320×240, thesis 4.3): 7.4 bytes a pixel predicted,
// 9.2 shuffled, 20.4 gzip'd raw; the surprise of frames replayed against the rounded map within
// 0.23 % (relative L1) of the exact map's (docs/map_storage.md; plane_codec_test and
// c_appearance_map_test hold the bounds).
#pragma once

#include <cstdint>
#include <opencv2/core.hpp>
#include <vector>

namespace novelty::views {

enum class PlaneEncoding : uint8_t {
  kShuffled = 3,   ///< map file version 3
  kPredicted = 4,  ///< map file version 4, memory
};

struct PlaneCodecOptions {
  int float_mantissa_bits = 14;  ///< of 23 kept for CV_32F values (23: exact; at least 1)
  int half_mantissa_bits = 6;    ///< of 10 kept for CV_16F values (10: exact; at least 1)
  int zstd_level = 1;            ///< 1 fastest … 19 smallest (3 saves 1 % more, 1.3× slower)
  PlaneEncoding encoding = PlaneEncoding::kPredicted;
};

/// The plane's values (8-, 16- or 32-bit elements, any channel count; rows, columns and type are
/// the caller's to store) as bytes. Throws std::invalid_argument for 64-bit elements or bit
/// counts out of range.
std::vector<uint8_t> EncodePlane(const cv::Mat& plane, const PlaneCodecOptions& options = {});

/// The plane of `rows`×`cols` and `type` that `bytes` encode in `encoding`. Throws
/// std::runtime_error if the bytes are not a complete encoding of exactly that many values.
cv::Mat DecodePlane(const uint8_t* bytes, std::size_t size, int rows, int cols, int type,
                    PlaneEncoding encoding = PlaneEncoding::kPredicted);

/// `value` with its mantissa rounded to `bits` of 23 (to nearest, ties to even); NaN and ±Inf
/// unchanged.
float RoundMantissa(float value, int bits);
/// The same for the bits of an IEEE half float (`bits` of 10).
uint16_t RoundHalfMantissa(uint16_t half, int bits);

}  // namespace novelty::views
