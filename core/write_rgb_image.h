// Writing an R G B image to a file (PNG, …): OpenCV writes B G R, and a failed write must not pass
// silently.
#pragma once

#include <opencv2/core.hpp>
#include <string>
#include <vector>

namespace novelty::core {

/// Writes a CV_8UC3 R G B image; the format follows the extension, `params` are OpenCV's
/// (cv::IMWRITE_JPEG_QUALITY, …). Throws std::runtime_error naming the path if it cannot be
/// written.
void WriteRgbImage(const std::string& path, const cv::Mat& rgb,
                   const std::vector<int>& params = {});

/// The same for an image written as it is (grey, 16-bit, or already B G R).
void WriteImage(const std::string& path, const cv::Mat& image, const std::vector<int>& params = {});

}  // namespace novelty::core
