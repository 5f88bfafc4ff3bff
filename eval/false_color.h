// False-colour pictures of scalar maps (surprise, uncertainty, differences) for panels and
// reports: OpenCV's "inferno" colour map over [0, max]; NaN (no data) is drawn dark grey so it
// never looks like a low value.
#pragma once

#include <opencv2/core.hpp>
#include <string>

namespace novelty::eval {

/// CV_32FC1 → CV_8UC3 (R, G, B). Values are clamped to [0, max_value]; if `log_scale`, the map
/// shows log(1 + v) / log(1 + max_value) (for quantities spanning decades, like Σβ).
cv::Mat FalseColor(const cv::Mat& map, double max_value, bool log_scale = false);

/// Images side by side (all CV_8UC3 of one height), separated by `gap` dark pixels; with
/// `captions` (one per image, or none), each under a strip holding its caption.
cv::Mat SideBySide(const std::vector<cv::Mat>& images, int gap = 4,
                   const std::vector<std::string>& captions = {});

}  // namespace novelty::eval
