// Compact storage of a plane (depth, parameter planes) for map files: values rounded to the
// precision the maps can tell apart, bytes regrouped by significance (sign and exponent bytes of
// neighbouring pixels are nearly equal, low mantissa bytes are noise), then zstd.
//
// The defaults keep 14 of a float's 23 mantissa bits (relative error ≤ 2⁻¹⁵: 0.008 grey levels
// for τ at 255, 0.15 mm for a depth at 5 m) and 6 of a half float's 10 (α, β, σ within 2⁻⁷).
// Measured on the glass-and-cup map (151 views at 320×240, thesis 4.3): 0.71 MB a view against
// 1.57 MB gzip'd raw, and the surprise of frames replayed against the reloaded map within 0.23 %
// (relative L1) of the exact map's (docs/map_storage.md; plane_codec_test and
// c_appearance_map_test hold the bounds).
#pragma once

#include <cstdint>
#include <opencv2/core.hpp>
#include <vector>

namespace novelty::views {

struct PlaneCodecOptions {
  int float_mantissa_bits = 14;  ///< of 23 kept for CV_32F values (23: exact)
  int half_mantissa_bits = 6;    ///< of 10 kept for CV_16F values (10: exact)
  int zstd_level = 3;            ///< 1 fastest … 19 smallest
};

/// The plane's values (any type; rows, columns and type are the caller's to store) as bytes.
std::vector<uint8_t> EncodePlane(const cv::Mat& plane, const PlaneCodecOptions& options = {});

/// The plane of `rows`×`cols` and `type` that `bytes` encode. Throws std::runtime_error if the
/// bytes are not a complete encoding of exactly that many values.
cv::Mat DecodePlane(const uint8_t* bytes, std::size_t size, int rows, int cols, int type);

/// `value` with its mantissa rounded to `bits` of 23 (to nearest, ties to even); NaN and ±Inf
/// unchanged.
float RoundMantissa(float value, int bits);
/// The same for the bits of an IEEE half float (`bits` of 10).
uint16_t RoundHalfMantissa(uint16_t half, int bits);

}  // namespace novelty::views
