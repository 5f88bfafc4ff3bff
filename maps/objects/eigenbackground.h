// The eigenbackground [ORP00], the segmentation of the baseline the thesis compares its object
// learning with ([WIS+10], 5.2): N background images give a mean and the M eigenvectors of
// their largest variance (the ways the background varies: light, small misalignments); an image
// projected onto that space and back is the background it would show; where it differs from
// that by more than a threshold, there is foreground. In 5.2 the N = 7 images are reference views
// of the appearance map warped to the current pose (a moving camera has no fixed background).
#pragma once

#include <opencv2/core.hpp>
#include <vector>

namespace novelty::objects {

struct EigenbackgroundOptions {
  /// M, the eigenvectors kept ([ORP00]: fewer than the images; 3 of 7 chosen).
  int components = 3;
  /// |image − its background| above this (grey levels, 0…255) is foreground (chosen: about
  /// eight times the simulated sensor noise).
  double threshold = 25.0;
  /// px, side of the opening then closing that removes specks and fills holes (0: none).
  int morphology_size = 5;
};

/// `backgrounds`: N ≥ 2 CV_32FC1 images (grey levels; NaN where a warped view does not cover),
/// `image` CV_32FC1 of the same size. Returns CV_8UC1, 255 on foreground; pixels some background
/// does not cover are not foreground. Throws std::invalid_argument for sizes, types or options
/// that do not fit.
cv::Mat EigenbackgroundForeground(const std::vector<cv::Mat>& backgrounds, const cv::Mat& image,
                                  const EigenbackgroundOptions& options = {});

/// The largest 8-connected region of `mask` (CV_8UC1), 255 there; empty mask if none.
cv::Mat LargestRegion(const cv::Mat& mask);

}  // namespace novelty::objects
