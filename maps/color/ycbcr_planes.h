// 8-bit RGB rows ↔ one float plane per YCbCr channel (ycbcr.h's transform), in one pass each way,
// for the appearance map's row tiles: its kernel reads and writes planes, cameras and the
// expected image are interleaved 8-bit RGB. The image functions of ycbcr.h take three passes for
// the same (to float, the affine map, split or merge) and a fourth to 8 bits; with AVX-512 VBMI
// sixteen pixels' bytes are (de)interleaved with one byte permute.
#pragma once

#include <opencv2/core.hpp>
#include <vector>

namespace novelty::color {

/// `rgb` (CV_8UC3, R, G, B; continuous or a view) → Y, Cb, Cr as three CV_32FC1 planes of its size
/// in `planes` (buffers reused). Throws std::invalid_argument for another type.
void RgbToYCbCrPlanes(const cv::Mat& rgb, std::vector<cv::Mat>& planes);

/// Y, Cb, Cr planes (CV_32FC1 of rgb's size) → `rgb`, which the caller created as CV_8UC3 (may be
/// a view into a larger image): rounded to nearest and saturated as cv::Mat::convertTo does, NaN
/// → 0. Throws std::invalid_argument when types or sizes disagree.
void YCbCrPlanesToRgb(const cv::Mat& y, const cv::Mat& cb, const cv::Mat& cr, cv::Mat& rgb);

}  // namespace novelty::color
