// RGB → HSV, for the saturation statistics of the illumination-invariant map (6.2).
// Conventions (OpenCV's for float images): H in degrees [0, 360), S in [0, 1], V on the input's
// scale (0…255 here). Achromatic pixels (max = min) have H = 0 and S = 0; black has S = 0.
#pragma once

#include <opencv2/core.hpp>

namespace novelty::color {

/// RGB image (CV_8UC3 or CV_32FC3, channel order R, G, B, 0…255) → CV_32FC3 (H, S, V).
/// Throws std::invalid_argument for other types.
cv::Mat RgbToHsv(const cv::Mat& rgb);

}  // namespace novelty::color
