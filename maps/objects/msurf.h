// SURF features as the thesis used them (5.1): Fast-Hessian keypoints (fast_hessian.h) with
// M-SURF descriptors (msurf_descriptor.h), as an OpenCV Feature2D, so that the object database
// takes them, OpenCV's SIFT or AKAZE through the same interface, and OpenCV's matchers
// (NORM_L2) compare them. Debian's OpenCV has no SURF (it lives in opencv_contrib's nonfree).
#pragma once

#include <opencv2/features2d.hpp>

#include "maps/objects/fast_hessian.h"

namespace novelty::objects {

struct MSurfOptions {
  FastHessianOptions detector;
  /// true: no orientation (U-SURF), for a camera that does not roll; false: rotation invariant.
  bool upright = false;
};

/// Keypoints: pt (px), size = 10·s (a convention:
/// descriptors of given keypoints take s = size/10), angle in degrees (0…360, OpenCV's convention), response =
/// det H, class_id = the Laplacian's sign (+1 dark blob, −1 bright: only keypoints of equal
/// sign can match), octave = the detector's octave. Descriptors: CV_32F, 64 per keypoint.
class MSurf : public cv::Feature2D {
 public:
  explicit MSurf(const MSurfOptions& options = {});
  static cv::Ptr<MSurf> create(const MSurfOptions& options = {});

  /// Grey (CV_8U 0…255 or CV_32F 0…1) or colour (CV_8UC3, BGR as OpenCV reads it) images;
  /// keypoints where `mask` (CV_8U, if given) is non-zero. With use_provided_keypoints, their
  /// descriptors only (scale from size, orientation from angle). Throws cv::Exception for other
  /// image types, as OpenCV's detectors do, and for a given keypoint that is not finite or has
  /// no size.
  void detectAndCompute(cv::InputArray image, cv::InputArray mask,
                        std::vector<cv::KeyPoint>& keypoints, cv::OutputArray descriptors,
                        bool use_provided_keypoints = false) override;
  int descriptorSize() const override { return 64; }
  int descriptorType() const override { return CV_32F; }
  int defaultNorm() const override { return cv::NORM_L2; }
  cv::String getDefaultName() const override { return "NoveltyMaps.MSURF"; }

 private:
  MSurfOptions options_;
};

}  // namespace novelty::objects
