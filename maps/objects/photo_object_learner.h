// Learning a named object from a photo (beyond the thesis, whose robot learns objects only where
// surprise points): the features the extractor finds inside the object's mask enter the database
// as a new class with the object's name, at their places in the photo's plane (metres, the
// mask's bounding box's corner at the origin) and the mask's convex outline there — what planar
// verification (planar_object_verification.h) maps into an image where the object is found. An
// object photographed from several sides is one class per photo, all of its name.
#pragma once

#include <opencv2/features2d.hpp>
#include <string>

#include "maps/objects/feature_database.h"

namespace novelty::objects {

struct PhotoObjectOptions {
  /// The photo's scale in the object's plane: the metres one pixel spans. It scales the pose a
  /// recognition reports (not whether it is found); 1 mm a pixel is a hand-held photo of a box
  /// a few decimetres wide taken from about half a metre.
  double metres_per_pixel = 0.001;
  /// Features fewer than this make no object: they could not be verified (PoseVerificationOptions'
  /// min_inliers is 6) even where the whole photo is seen again.
  int min_features = 12;
};

struct LearntPhoto {
  int object = -1;   ///< the class added
  int features = 0;  ///< its features
};

/// Adds `name`'s features in `image` (CV_8UC1 grey or CV_8UC3 B, G, R) inside `mask` (CV_8UC1 of
/// the image's size, non-zero = the object; empty: the whole image) to `database`, found and
/// described by `extractor` (the database's). Throws std::invalid_argument naming the problem: an
/// image of another type, a mask of another size or type or with nothing set, a name AddObject
/// refuses, a scale that is not positive and finite, fewer than min_features features (the
/// database is then unchanged).
LearntPhoto LearnObjectFromPhoto(FeatureDatabase& database, const std::string& name,
                                 const cv::Mat& image, const cv::Mat& mask,
                                 cv::Feature2D& extractor, const PhotoObjectOptions& options = {});

}  // namespace novelty::objects
