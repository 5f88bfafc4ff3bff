// The illumination-invariant image of one viewpoint from M images of it under different lighting
// (6.1.2, after [Wei01]). In the log domain an image is i_m = r + l_m (eq. 6.5): invariant part
// plus illumination part. Illumination gradients (shading, shadow borders, highlight edges) are
// sparse and move with the light, so per pixel and per colour channel the median over the M
// images of the forward differences f^x = [1, -1], f^y = [1, -1]^T (eq. 6.6-6.9) is the invariant
// image's gradient; pseudo-inverse filtering integrates it (eq. 6.10-6.13,
// gradient_integration.h), and l̂_m = i_m - r̂ (eq. 6.14).
//
// What the thesis leaves open, decided here:
// - Small intensities are raised to `min_intensity` before the logarithm (6.1.2, "clipped"); 3
//   on the 0…255 scale, as the reference code of the MIT benchmark [Grosse et al. 2009].
// - An even number of images has the mean of the two middle values as median (as NumPy's).
// - r̂ is defined up to a constant per channel (and per connected part of the covered pixels);
//   it is fixed so that the illumination images average 0 in the log domain (1 in linear
//   terms), around which 6.2's statistics centre.
// - Pixels that some images do not cover (virtual images, masked objects) take the median over
//   the images that cover both pixels of a difference; a difference that fewer than
//   `min_lightings` images cover is taken as 0 (flat). Where some pixel is covered by fewer
//   than min_lightings images the integration runs over the covered pixels only (sparse least
//   squares, slow: seconds at 640×480); else over the whole image (Fourier, milliseconds).
#pragma once

#include <opencv2/core.hpp>
#include <vector>

namespace novelty::illumination {

struct InvariantImageOptions {
  /// How colour images are treated.
  enum class Colour {
    /// Each RGB channel on its own (6.1.2: "separately for each color channel"). The default.
    kPerChannel,
    /// The luminance (channel mean) by eq. 6.6-6.13, the colour as the per-pixel median over the
    /// images of each channel's share of the luminance. Under light of one colour the shares do
    /// not change with shading or shadows, and highlights in a minority of images are outvoted;
    /// the luminance averages the channels' noise. Scores better on the MIT objects (README).
    kLuminanceChromaticity,
  };
  Colour colour = Colour::kPerChannel;
  /// Intensities below this (0…255 scale) are raised to it before the logarithm: log 0 is
  /// undefined and the ratios of dark pixels are noise (6.1.2). 3 as the MIT reference code.
  double min_intensity = 3.0;
  /// Fewest images whose median makes a gradient (and that must cover a pixel for it to be in
  /// the result). The median of one image is that image's gradient, not an invariant one.
  int min_lightings = 2;
};

struct InvariantImage {
  /// r̂ (eq. 6.12): the log invariant image, CV_32FC(channels of the input), natural log of the
  /// 0…255 scale; 0 where `covered` is 0.
  cv::Mat log_invariant;
  /// l̂_m = i_m - r̂ (eq. 6.14), one per input image, same type; 0 where image m or r̂ does not
  /// cover.
  std::vector<cv::Mat> log_illumination;
  /// CV_8UC1, 255 where at least min_lightings images cover the pixel.
  cv::Mat covered;
};

/// `images`: M ≥ 2 images of one size and one type, CV_8UC1/3, CV_16UC1/3 (scaled by 255/65535)
/// or CV_32FC1/3 (0…255, finite). `coverage`: empty (all pixels of all images are valid) or one
/// CV_8UC1 mask per image (non-zero = valid). Throws std::invalid_argument naming the image and
/// what is wrong (one image: "a single lighting ... not invariant"; sizes, types, NaN, options).
InvariantImage ComputeInvariantImage(const std::vector<cv::Mat>& images,
                                     const std::vector<cv::Mat>& coverage = {},
                                     const InvariantImageOptions& options = {});

/// The log illumination image of a camera image against an invariant image (eq. 6.14; eq. 6.19
/// for a new frame): log(max(I, min_intensity)) - r̂. `image` as ComputeInvariantImage takes
/// (one of its types, finite), of r̂'s size and channels; throws std::invalid_argument otherwise.
cv::Mat LogIllumination(const cv::Mat& image, const cv::Mat& log_invariant, double min_intensity);

/// exp(log image) → CV_32FC(n) on the 0…255 scale, 0 where `covered` is 0 (when given).
cv::Mat LinearImage(const cv::Mat& log_image, const cv::Mat& covered = cv::Mat());

/// LinearImage as 8 bits (saturated), for pictures: the reflectance up to r̂'s constant.
cv::Mat LinearImage8(const cv::Mat& log_image, const cv::Mat& covered = cv::Mat());

}  // namespace novelty::illumination
