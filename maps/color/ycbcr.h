// YCbCr by the irreversible colour transform (ICT) of JPEG 2000 [TM02], the colour space of the
// appearance map (4.1). With luma weights Kr = 0.299, Kb = 0.114, Kg = 1 - Kr - Kb:
//   Y  = Kr R + Kg G + Kb B
//   Cb = ½ (B - Y) / (1 - Kb) + offset       (= -0.168736 R - 0.331264 G + 0.5 B + offset)
//   Cr = ½ (R - Y) / (1 - Kr) + offset       (=  0.5 R - 0.418688 G - 0.081312 B + offset)
// Both directions are derived from Kr and Kb, so the inverse is exact up to float rounding.
// With 0…255 RGB and the default offset 128, all three channels are on the 0…255 scale that
// DESIGN.md fixes for the map (chroma 0.5…255.5).
#pragma once

#include <opencv2/core.hpp>

namespace novelty::color {

inline constexpr double kLumaRed = 0.299;
inline constexpr double kLumaBlue = 0.114;
inline constexpr double kLumaGreen = 1.0 - kLumaRed - kLumaBlue;
/// Offset added to Cb and Cr so that they share Y's 0…255 scale.
inline constexpr double kChromaOffset = 128.0;

/// Rows: Y, Cb, Cr as a·(R, G, B) + offset.
cv::Matx34d RgbToYCbCrMatrix();
/// Rows: R, G, B as a·(Y, Cb, Cr) + offset; the exact inverse of RgbToYCbCrMatrix().
cv::Matx34d YCbCrToRgbMatrix();

/// One pixel, for per-pixel loops that convert on the fly.
cv::Vec3f RgbToYCbCr(const cv::Vec3f& rgb);
cv::Vec3f YCbCrToRgb(const cv::Vec3f& ycbcr);

/// RGB image (CV_8UC3 or CV_32FC3, channel order R, G, B, values 0…255) → CV_32FC3 (Y, Cb, Cr).
/// Throws std::invalid_argument for other types.
cv::Mat RgbToYCbCr(const cv::Mat& rgb);

/// CV_32FC3 (Y, Cb, Cr) → CV_32FC3 (R, G, B), 0…255, not clamped: a predicted colour outside the
/// gamut stays visible as such. Throws std::invalid_argument for other types.
cv::Mat YCbCrToRgb(const cv::Mat& ycbcr);

/// The same into an output image whose buffer is reused when it has the right size and type
/// (per-frame callers avoid a fresh megabyte each time). The output must not share data with
/// the input unless it is the input itself.
void RgbToYCbCr(const cv::Mat& rgb, cv::Mat& ycbcr);
void YCbCrToRgb(const cv::Mat& ycbcr, cv::Mat& rgb);

}  // namespace novelty::color
