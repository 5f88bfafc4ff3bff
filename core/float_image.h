// Images as float on the 0…255 scale, whatever they were stored as: the illumination part reads
// 8-bit camera frames, 16-bit linear photographs (the MIT objects) and float virtual images alike.
#pragma once

#include <opencv2/core.hpp>

namespace novelty::core {

/// CV_8U, CV_16U (scaled by 255/65535) or CV_32F (as is) → CV_32F with the same channels.
/// Throws std::invalid_argument for other depths.
cv::Mat ToFloat255(const cv::Mat& image);

/// The mean of the channels of ToFloat255(image), CV_32FC1 (a one-channel image as float).
cv::Mat ChannelMean(const cv::Mat& image);

}  // namespace novelty::core
