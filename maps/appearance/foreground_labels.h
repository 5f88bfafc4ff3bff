// A fixed camera's foreground from the appearance map's products (issue 52): the decision rule
// that turns predictive novelty (stats/predictive_novelty.h) into a mask, with an optional shadow
// label and small-blob removal.
//
//  1. Foreground where −ln p(x | background) > threshold_nats. The default, 3 ln 256 = 16.6 nats,
//     is the Bayes decision between the background model and a foreground colour uniform over
//     the 256³ colour cube, with equal priors.
//  2. Shadow (label 127, as OpenCV's MOG2 and KNN mark it): a foreground pixel whose
//     illumination image — the frame over the expected background, per channel in linear RGB
//     (eq. 6.4: the surface's reflectance cancels) — is grey and darker, as a cast shadow leaves
//     it: a light's share is taken away, the others' of similar colour remain. In HSV terms
//     (section 6.2, where the thesis models exactly these two components) its value V = max_c L_c
//     lies in [shadow_min_value, shadow_max_value] and its saturation (max − min)/max is at most
//     shadow_max_saturation. Where the background is darker than shadow_min_background levels
//     the ratio is noise and the pixel stays foreground. Without gamma statistics of the view (a
//     fixed camera has no lighting sequences), the bounds are fixed options, measured on the
//     simulator's fixed-camera room.
//  3. Foreground blobs (8-connected) smaller than min_blob_pixels are dropped to background.
#pragma once

#include <cmath>
#include <opencv2/core.hpp>

namespace novelty::appearance {

inline constexpr int kForegroundLabel = 255, kShadowLabel = 127, kBackgroundLabel = 0;

struct ForegroundLabelOptions {
  double threshold_nats = 3 * std::log(256.0);  ///< rule 1
  bool shadow_label = true;                     ///< rule 2
  double shadow_min_value = 0.25;               ///< darkest shadow: a quarter of the light left
  double shadow_max_value = 0.95;               ///< a 5 % darkening is not yet a shadow
  double shadow_max_saturation = 0.12;          ///< the lights' colours differ by about this
  double shadow_min_background = 12;            ///< 8-bit levels of the expected luminance
  double gamma = 2.2;                           ///< the camera's, to linearise
  int min_blob_pixels = 0;                      ///< rule 3; 0: keep every blob
};

/// Labels (CV_8UC1: 255 foreground, 127 shadow, 0 background) from predictive novelty
/// (CV_32FC1, NaN where uncovered: background), the frame and the expected image (CV_8UC3 R G B,
/// AppearanceProducts::expected_rgb). Throws std::invalid_argument for other types or sizes.
cv::Mat ForegroundLabels(const cv::Mat& predictive, const cv::Mat& rgb, const cv::Mat& expected_rgb,
                         const ForegroundLabelOptions& options = {});

}  // namespace novelty::appearance
