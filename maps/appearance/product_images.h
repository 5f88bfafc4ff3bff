// The maps' per-frame products as pictures, on fixed scales so that pictures of different frames,
// runs and programs compare: false colour (core/false_color.h) from black (0) to pale yellow (the
// scale's top and above); dark grey where the map has no prediction. Panels, reports and the MRPT
// maps' CImage products all draw with these, and only these, scales.
#pragma once

#include <opencv2/core.hpp>
#include <string>

#include "maps/appearance/appearance_map.h"
#include "maps/appearance/differencing_map.h"

namespace novelty::appearance {

struct ProductScales {
  double surprise = 20.0;       ///< nats: surprise at or above this is the brightest
  double uncertainty = 1e4;     ///< Σβ, drawn on a log scale: log(1 + Σβ) / log(1 + 1e4)
  double differencing = 150.0;  ///< |ΔY| + |ΔCb| + |ΔCr| (0…255 levels each)
};

/// CV_8UC3 (R, G, B) pictures of a frame's products; an empty product gives an empty image.
cv::Mat SurpriseImage(const AppearanceProducts& p, const ProductScales& scales = {});
cv::Mat UncertaintyImage(const AppearanceProducts& p, const ProductScales& scales = {});
cv::Mat DifferenceImage(const DifferencingProducts& p, const ProductScales& scales = {});

/// Captions naming the scale, e.g. "surprise (0-20)", "uncertainty (log, 0-10000)".
std::string SurpriseCaption(const ProductScales& scales = {});
std::string UncertaintyCaption(const ProductScales& scales = {});
std::string DifferenceCaption(const ProductScales& scales = {});

}  // namespace novelty::appearance
