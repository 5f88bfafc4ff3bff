// The picture of one frame that panels and reports show: camera | expected (τ) | surprise |
// uncertainty Σβ [| differencing, where a differencing map runs], each captioned, on the fixed
// scales of maps/appearance/product_images.h so that panels of different frames and runs compare.
#pragma once

#include <opencv2/core.hpp>
#include <string>

#include "maps/appearance/product_images.h"

namespace novelty::eval {

/// The panel of a frame (`rgb`: the camera image, CV_8UC3 R G B) with the appearance map's and,
/// unless null, the differencing map's products for it; `label` heads the camera's caption (e.g.
/// the frame's stem).
cv::Mat NoveltyPanel(const cv::Mat& rgb, const appearance::AppearanceProducts& surprise,
                     const appearance::DifferencingProducts* differencing, const std::string& label,
                     const appearance::ProductScales& scales = {});

}  // namespace novelty::eval
