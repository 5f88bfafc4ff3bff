// The object database's feature extractor, chosen by name: the thesis's SURF (our M-SURF,
// msurf.h), OpenCV's SIFT, or OpenCV's AKAZE detector with its float KAZE descriptor. All three
// give float descriptors compared with NORM_L2, which the ratio matching (ratio_matches.h) and the
// database (feature_database.h) assume; binary descriptors (ORB, AKAZE's default MLDB) are left
// out for that reason.
#pragma once

#include <opencv2/features2d.hpp>
#include <string>
#include <vector>

namespace novelty::objects {

enum class FeatureExtractor { kMSurf = 0, kSift = 1, kAkaze = 2 };

/// "msurf", "sift", "akaze": the names of FeatureExtractor's values, in their order.
const std::vector<std::string>& FeatureExtractorNames();
const std::string& FeatureExtractorName(FeatureExtractor e);
/// The extractor called `name`; throws std::invalid_argument listing the names for any other.
FeatureExtractor ParseFeatureExtractor(const std::string& name);

/// A new extractor with its library's defaults.
cv::Ptr<cv::Feature2D> CreateFeatureExtractor(FeatureExtractor e);

/// The keypoints `f`, an extractor of kind `e` (CreateFeatureExtractor), finds with their centres
/// in `box` (rounded to the pixel) and their descriptors, computed on the grey of `rgb` (CV_8UC3,
/// R, G, B). SIFT and AKAZE build their scale space over their whole input, so they get `rgb`
/// cropped to `box` grown by `margin` px on each side, clipped to the image, and pay for the
/// crop's area, not the image's; a keypoint whose descriptor window (side
/// DescriptorWindowPerSize · size, turned by its angle) leaves the crop where the image goes on
/// is left out, as its descriptor would be computed from part of its window. The crop's corner is
/// moved down to a multiple of 8 px, so that SIFT's octaves to 1/8 sample the same pixels as on
/// the whole image (coarser octaves hold keypoints whose windows span 300 px and more); what
/// remains different is the blur near the crop's edge. M-SURF searches only near its mask already
/// (msurf.h) and always gets the whole image with the box as mask, as every extractor does for
/// margin < 0: every keypoint kept, with its whole window. Keypoints are returned in the image's
/// coordinates. Throws std::invalid_argument for an rgb that is not CV_8UC3, a box that is not
/// inside it, or an `e` that names no extractor.
void DetectAndComputeInBox(FeatureExtractor e, cv::Feature2D& f, const cv::Mat& rgb,
                           const cv::Rect& box, int margin, std::vector<cv::KeyPoint>& keypoints,
                           cv::Mat& descriptors);

/// The descriptor width (M-SURF 64, SIFT 128, AKAZE/KAZE 64). A database learnt with one
/// extractor cannot be matched with another's descriptors, even of the same width: the map file
/// names the extractor.
int DescriptorWidth(FeatureExtractor e);

/// Side of the square a descriptor is computed from, per unit of keypoint size, so that ρ_S
/// (eq. 5.5) is measured over that window (ObjectLearnerOptions): M-SURF 24·s with size 10·s →
/// 2.4; SIFT 4 bins of 3σ with OpenCV's size 2σ → 6; KAZE 24·scale with scale = size/2 → 12.
double DescriptorWindowPerSize(FeatureExtractor e);

/// How the descriptor's window turns with the keypoint's angle: +1 M-SURF (msurf_descriptor.h)
/// and AKAZE's KAZE descriptor (M-SURF's pattern), −1 OpenCV's SIFT, which samples at
/// 360° − angle.
int DescriptorWindowAngleSign(FeatureExtractor e);

}  // namespace novelty::objects
