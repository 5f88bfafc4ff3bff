// Interleaved rows ↔ one float plane per channel, in one pass each way, for the appearance map's
// row tiles (appearance_map.cc): the kernel reads and writes planes, the store keeps interleaved
// images. OpenCV's split and merge take a generic per-element path beyond four channels, need a
// second pass for half
// floats, and cost a few microseconds per call, which a frame of 30 tiles pays hundreds of times.
// With AVX-512 the map's own layouts (seven half-float and three float channels) go sixteen
// pixels at a time through register permutes, half floats converted on the way.
#pragma once

#include <opencv2/core.hpp>
#include <vector>

namespace novelty::core {

/// `rows` (CV_8U, CV_16F or CV_32F; 1–32 channels; continuous or not) → one CV_32FC1 plane of
/// its size per channel in `planes` (buffers reused). Throws std::invalid_argument otherwise.
void SplitToFloat(const cv::Mat& rows, std::vector<cv::Mat>& planes);

/// `planes` (CV_32FC1, of out's size, one per channel of `out`) → `out`, which the caller
/// created as CV_16F (rounded to nearest, as convertTo) or CV_32F of 1–32 channels; `out` may be a
/// view into a larger image. Throws std::invalid_argument when they disagree.
void MergeInto(const std::vector<cv::Mat>& planes, cv::Mat& out);

}  // namespace novelty::core
