// Change detection by the spherical coordinate transform (SCT) [SS07, MMHM01], thesis eq.
// 2.32-2.34, the other baseline of 6.4: a colour (R, G, B) becomes intensity I = |RGB| and two
// angles φ = atan(G/R), θ = acos(B/I) that do not change with the intensity; the change measure
// is the Euclidean distance of (φ, θ) between observation and reference (radians). A black
// pixel has no colour: its distance is 0.
#pragma once

#include <opencv2/core.hpp>

namespace novelty::illumination {

/// CV_32FC1 distances of two RGB images (CV_8UC3, CV_16UC3 or CV_32FC3) of one size and type.
/// Throws std::invalid_argument otherwise.
cv::Mat SphericalColorChange(const cv::Mat& observation, const cv::Mat& reference);

}  // namespace novelty::illumination
