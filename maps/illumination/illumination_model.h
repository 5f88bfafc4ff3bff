// Statistics of the illumination images at one viewpoint (thesis 6.2): gamma distributions of
// their luminance and colour saturation (eq. 6.16, maximum likelihood), the information of each
// value (eq. 6.17), the threshold T_Y on the luminance's information (eq. 6.18), and the binary
// shapes of the regions above it — highlights and strong shadows, which 6.3 matches against a
// new frame's to tell lighting from change.
//
// Luminance and saturation are HSV's V and S of the linear illumination image L = exp(l̂)
// (color/hsv.h): V = max over the channels, S = 1 - min/max.
// What the thesis leaves open, decided here (eq. 6.17: "the probability of a luminance value is
// approximated by the product of the probability density ... and the width of the quantization
// interval"): the width is how far one grey level `grey_level` of the camera moves the value at
// that pixel — q / V_R for the luminance (L = I / R) and q / V_I for the saturation, V_R and V_I
// the largest channel of the invariant and of the camera image. Values are taken no smaller than
// half their width, so that an exact 0 (a grey pixel's saturation) has a finite information.
#pragma once

#include <opencv2/core.hpp>
#include <vector>

#include "maps/illumination/invariant_image.h"
#include "maps/stats/gamma_ml_fit.h"

namespace novelty::illumination {

struct IlluminationModelOptions {
  /// κ of T_Y = mean(i_Y) / (1 - κ) (eq. 6.18): 0.5 for Lambertian scenes, 0.2 with specular
  /// surfaces (6.4). Default: the Lambertian value.
  double kappa = 0.5;
  /// q: one grey level of the camera on the 0…255 scale, the quantisation of eq. 6.17.
  double grey_level = 1.0;
};

/// One image's luminance and saturation with their quantisation widths (CV_32FC1 each; the
/// saturation planes are empty for one-channel images).
struct IlluminationComponents {
  cv::Mat luminance, luminance_step;
  cv::Mat saturation, saturation_step;
};

struct IlluminationModel {
  stats::GammaFit luminance;      ///< a_Y, b_Y of eq. 6.16
  stats::GammaFit saturation;     ///< a_S, b_S (α = β = 0 for one-channel images)
  double mean_information = 0.0;  ///< mean of i_Y over all images' covered pixels
  double threshold = 0.0;         ///< T_Y (eq. 6.18)
  /// Per training image, CV_8UC1: 255 where i_Y > T_Y (highlights and strong shadows).
  std::vector<cv::Mat> shapes;
};

/// Luminance and saturation of illumination image m of `invariant`, with their widths; `image`
/// is that camera image (its largest channel sets the saturation's width; any type
/// ComputeInvariantImage takes).
IlluminationComponents ComputeIlluminationComponents(const cv::Mat& log_illumination,
                                                     const cv::Mat& log_invariant,
                                                     const cv::Mat& image,
                                                     const IlluminationModelOptions& options = {});

/// i = -log(p(x) · Δ) per pixel (eq. 6.17) under a fitted gamma distribution; values and widths
/// CV_32FC1 of one size. Returns CV_32FC1.
cv::Mat InformationMap(const cv::Mat& values, const cv::Mat& steps, const stats::GammaFit& fit);

/// Fits the model to the illumination images of `invariant`, computed from `images` (the same
/// images, in order; `coverage` as given to ComputeInvariantImage). Throws std::invalid_argument
/// for κ outside [0, 1), grey_level ≤ 0, or images that do not match `invariant`.
IlluminationModel LearnIlluminationModel(const InvariantImage& invariant,
                                         const std::vector<cv::Mat>& images,
                                         const std::vector<cv::Mat>& coverage = {},
                                         const IlluminationModelOptions& options = {});

}  // namespace novelty::illumination
