#include "experiments/object_photo_learning.h"

#include <filesystem>
#include <opencv2/imgproc.hpp>
#include <stdexcept>

#include "maps/objects/feature_extractor.h"
#include "sensors/dataset/fixed_camera_folder.h"

namespace novelty::experiments {

namespace fs = std::filesystem;

namespace {

bool IsMaskFile(const fs::path& p) {
  return p.stem().extension() == ".mask";
}

// The photos of one object: the image, or the folder's images that are not masks.
std::vector<std::string> PhotosOf(const ObjectPhotoSpec& spec,
                                  const sensors::LightingFolderOptions& pick) {
  if (!fs::exists(spec.path)) throw std::runtime_error(spec.path + ": no such photo or folder");
  if (!fs::is_directory(spec.path)) return {spec.path};
  std::vector<std::string> photos;
  for (const std::string& p : sensors::ListImageFolder(spec.path, pick).images)
    if (!IsMaskFile(p)) photos.push_back(p);
  if (photos.empty()) throw std::runtime_error(spec.path + ": no photo of " + spec.name);
  return photos;
}

// Where the object is in `photo`: the spec's box and the photo's mask file, both if both.
cv::Mat MaskOf(const std::string& photo, const cv::Size& size, const ObjectPhotoSpec& spec) {
  cv::Mat mask;
  const fs::path p(photo);
  const fs::path mask_file = p.parent_path() / (p.stem().string() + ".mask.png");
  if (fs::exists(mask_file)) {
    mask = sensors::ReadFolderMask(mask_file.string());
    if (mask.size() != size)
      throw std::runtime_error(mask_file.string() + " is " + std::to_string(mask.cols) + "x" +
                               std::to_string(mask.rows) + ", its photo " +
                               std::to_string(size.width) + "x" + std::to_string(size.height));
  }
  if (spec.box) {
    const cv::Rect b = *spec.box;
    if ((b & cv::Rect(cv::Point(), size)) != b)
      throw std::runtime_error(
          photo + ": the box " + std::to_string(b.x) + "," + std::to_string(b.y) + "," +
          std::to_string(b.width) + "," + std::to_string(b.height) + " is not inside the " +
          std::to_string(size.width) + "x" + std::to_string(size.height) + " photo");
    cv::Mat in_box(size, CV_8UC1, cv::Scalar(0));
    in_box(b).setTo(255);
    if (!mask.empty() && cv::countNonZero(mask & in_box) == 0)
      throw std::runtime_error(photo + ": the box and " + mask_file.string() +
                               " select no common pixel");
    mask = mask.empty() ? in_box : (mask & in_box);
  }
  return mask;
}

int ParseInt(const std::string& text, const std::string& spec) {
  std::size_t used = 0;
  int v = 0;
  try {
    v = std::stoi(text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used == 0 || used != text.size())
    throw std::invalid_argument(spec + ": the box must be X,Y,W,H in pixels");
  return v;
}

}  // namespace

ObjectPhotoSpec ParseObjectPhotoSpec(const std::string& text) {
  ObjectPhotoSpec s;
  std::string rest = text;
  if (const std::size_t at = rest.rfind('@'); at != std::string::npos) {
    std::vector<int> v;
    std::string box = rest.substr(at + 1) + ",";
    for (std::size_t start = 0, comma; (comma = box.find(',', start)) != std::string::npos;
         start = comma + 1)
      v.push_back(ParseInt(box.substr(start, comma - start), text));
    if (v.size() != 4)
      throw std::invalid_argument(text + ": the box must be four numbers X,Y,W,H (pixels), got " +
                                  std::to_string(v.size()));
    if (v[0] < 0 || v[1] < 0)
      throw std::invalid_argument(text + ": the box's corner X,Y must be >= 0");
    if (v[2] <= 0 || v[3] <= 0)
      throw std::invalid_argument(text + ": the box's width W and height H must be > 0");
    s.box = cv::Rect(v[0], v[1], v[2], v[3]);
    rest = rest.substr(0, at);
  }
  if (const std::size_t eq = rest.find('='); eq != std::string::npos) {
    s.name = rest.substr(0, eq);
    if (s.name.empty()) throw std::invalid_argument(text + ": an empty name before '='");
    rest = rest.substr(eq + 1);
  }
  if (rest.empty()) throw std::invalid_argument(text + ": no photo or folder");
  s.path = rest;
  if (s.name.empty()) {
    const fs::path p = fs::path(rest).lexically_normal();
    s.name = (p.filename().empty() ? p.parent_path() : p).stem().string();
  }
  objects::ObjectInfo info;
  info.name = s.name;
  if (const std::string error = objects::FeatureDatabase::InfoError(info); !error.empty())
    throw std::invalid_argument(text + ": " + error);
  return s;
}

std::vector<LearntObjectPhoto> LearnObjectPhotos(mrpt_plugins::CObjectDatabaseMap& map,
                                                 const ObjectPhotoLearningOptions& options) {
  const cv::Ptr<cv::Feature2D> extractor =
      objects::CreateFeatureExtractor(map.config().map.extractor);
  std::vector<LearntObjectPhoto> learnt;
  for (const ObjectPhotoSpec& spec : options.objects) {
    for (const std::string& photo : PhotosOf(spec, options.pick)) {
      const cv::Mat rgb = sensors::ReadImageRgb8(photo, options.max_pixels);
      cv::Mat grey;
      cv::cvtColor(rgb, grey, cv::COLOR_RGB2GRAY);
      LearntObjectPhoto l;
      l.name = spec.name;
      l.photo = photo;
      try {
        const objects::LearntPhoto r = objects::LearnObjectFromPhoto(
            map.database(), spec.name, grey, MaskOf(photo, rgb.size(), spec), *extractor,
            options.photo);
        l.object = r.object;
        l.features = r.features;
      } catch (const std::invalid_argument& e) {
        throw std::runtime_error(photo + ": " + e.what());
      }
      learnt.push_back(l);
    }
  }
  return learnt;
}

}  // namespace novelty::experiments
