// Pictures side by side with captions, for panels and reports.
#pragma once

#include <opencv2/core.hpp>
#include <string>
#include <vector>

namespace novelty::eval {

/// Images side by side (all CV_8UC3 of one height), separated by `gap` dark pixels; with
/// `captions` (one per image, or none), each under a strip holding its caption.
cv::Mat SideBySide(const std::vector<cv::Mat>& images, int gap = 4,
                   const std::vector<std::string>& captions = {});

}  // namespace novelty::eval
