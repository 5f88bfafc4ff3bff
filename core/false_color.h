// False-colour pictures of scalar maps (surprise, uncertainty, differences) for panels, reports
// and MRPT images: OpenCV's "inferno" colour map over [0, max]; NaN (no data) is drawn dark grey
// so it never looks like a low value. The scales of the maps' products are in
// maps/appearance/product_images.h.
#pragma once

#include <opencv2/core.hpp>

namespace novelty::core {

/// CV_32FC1 → CV_8UC3 (R, G, B). Values are clamped to [0, max_value]; if `log_scale`, the map
/// shows log(1 + v) / log(1 + max_value) (for quantities spanning decades, like Σβ).
cv::Mat FalseColor(const cv::Mat& map, double max_value, bool log_scale = false);

}  // namespace novelty::core
