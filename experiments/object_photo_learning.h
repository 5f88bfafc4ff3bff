// Learning named objects from one's own photos into a CObjectDatabaseMap (issue 51 item 5): each
// object is an image or a folder of images (one database class per photo, all of the object's
// name; objects::LearnObjectFromPhoto), optionally with a box or a mask — `X.mask.png` beside an
// image `X.jpg` (non-zero = the object) — and its features are those of the map's extractor. The
// map file it is saved to is the one novelty-run takes (--objects-in) and novelty-find-objects
// recognises from.
#pragma once

#include <opencv2/core.hpp>
#include <optional>
#include <string>
#include <vector>

#include "maps/objects/photo_object_learner.h"
#include "mrpt_plugins/c_object_database_map.h"
#include "sensors/dataset/image_header.h"
#include "sensors/dataset/lighting_folder_reader.h"

namespace novelty::experiments {

/// One object as given on a command line: "[NAME=]PATH[@X,Y,W,H]" — without a name, the file's
/// stem or the folder's name; the box (pixels) applies to each of its photos.
struct ObjectPhotoSpec {
  std::string name, path;
  std::optional<cv::Rect> box;
};
/// Throws std::invalid_argument naming `text` for an empty name or path or a box that is not four
/// integers with a positive width and height.
ObjectPhotoSpec ParseObjectPhotoSpec(const std::string& text);

struct ObjectPhotoLearningOptions {
  std::vector<ObjectPhotoSpec> objects;
  sensors::LightingFolderOptions pick;  ///< which files of a folder are photos
  objects::PhotoObjectOptions photo;
  long long max_pixels = sensors::kDefaultMaxImagePixels;  ///< per photo, before decoding
};

struct LearntObjectPhoto {
  std::string name, photo;  ///< the object's name, the photo's path
  int object = -1, features = 0;
};

/// Adds every photo of every object to `map`'s database, in the order given. Throws
/// std::runtime_error naming the file (unreadable, over max_pixels, a box outside it, a mask of
/// another size, a folder without photos, too few features) — `map` then holds what was added
/// before; callers save only after success.
std::vector<LearntObjectPhoto> LearnObjectPhotos(mrpt_plugins::CObjectDatabaseMap& map,
                                                 const ObjectPhotoLearningOptions& options);

}  // namespace novelty::experiments
