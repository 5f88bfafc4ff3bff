// Writing an R G B image to a file (PNG, …): OpenCV writes B G R, and a failed write must not pass
// silently.
#pragma once

#include <opencv2/core.hpp>
#include <string>

namespace novelty::core {

/// Writes a CV_8UC3 R G B image; the format follows the extension. Throws std::runtime_error
/// naming the path if it cannot be written.
void WriteRgbImage(const std::string& path, const cv::Mat& rgb);

}  // namespace novelty::core
