// The picture of one frame that panels and reports show: camera | expected (τ) | surprise |
// uncertainty Σβ | differencing, each captioned, on fixed scales so that panels of different
// frames and runs compare.
#pragma once

#include <opencv2/core.hpp>
#include <string>

#include "maps/appearance/appearance_map.h"
#include "maps/appearance/differencing_map.h"

namespace novelty::eval {

/// The scales the panel draws on (false_color.h).
struct NoveltyPanelScales {
  double surprise = 20.0;       ///< nats: surprise at or above this is the brightest
  double uncertainty = 1e4;     ///< Σβ, on a log scale
  double differencing = 150.0;  ///< |ΔY| + |ΔCb| + |ΔCr|
};

/// The panel of a frame (`rgb`: the camera image, CV_8UC3 R G B) with the appearance map's and the
/// differencing map's products for it; `label` heads the camera's caption (e.g. the frame's stem).
cv::Mat NoveltyPanel(const cv::Mat& rgb, const appearance::AppearanceProducts& surprise,
                     const appearance::DifferencingProducts& differencing,
                     const std::string& label, const NoveltyPanelScales& scales = {});

}  // namespace novelty::eval
