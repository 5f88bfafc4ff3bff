// A folder of images from one fixed camera — the lightings of one viewpoint (thesis 6.1: the
// camera stays, the lamps move) or the frames a static camera took — as the RGB-D observations
// the maps read. A fixed camera needs no geometry: every image gets the same pose (the origin)
// and a plane `depth` metres in front as its depth map, so that the maps' warps between
// viewpoints are the identity and a view is compared pixel by pixel. Where the folder's mask.png
// is zero the depth is unknown, so those pixels are never covered. The intrinsics are nominal
// (focal length the image's larger side, principal point the centre): with one pose they only
// scale the plane.
//
// Images are listed by lighting_folder_reader.h's rules (name order, include/exclude patterns,
// mask/reflectance/shading/diffuse not frames) and read one at a time; 16-bit images are scaled
// to 8 bits (÷ 257) and grey ones repeated into R G B.
#pragma once

#include <mrpt/obs/CObservation3DRangeScan.h>

#include <opencv2/core.hpp>
#include <string>
#include <vector>

#include "core/pinhole_camera.h"
#include "sensors/dataset/image_header.h"
#include "sensors/dataset/lighting_folder_reader.h"

namespace novelty::sensors {

struct FixedCameraOptions {
  LightingFolderOptions pick;  ///< which image files are frames
  /// m, the plane every image is given as depth (any positive value serves one pose).
  double depth = 1.0;
  long long max_pixels = kDefaultMaxImagePixels;  ///< per image, checked before decoding
};

class FixedCameraFolder {
 public:
  /// Lists `folder` and reads the first image's size (and the mask). Throws std::runtime_error
  /// naming the folder or file: no such folder, no image the patterns pick, a mask of another
  /// size, an image over max_pixels.
  explicit FixedCameraFolder(const std::string& folder, const FixedCameraOptions& options = {});

  int size() const { return int(listing_.images.size()); }
  /// Image k's file name (0-based k).
  std::string name(int k) const;
  const core::PinholeCamera& camera() const { return camera_; }
  const ImageFolderListing& listing() const { return listing_; }

  /// Image k as 8-bit R G B (std::runtime_error naming the file when it cannot be read or is of
  /// another size than the first).
  cv::Mat Rgb(int k) const;
  /// The depth every image gets: the plane, 0 (unknown) outside the mask.
  const cv::Mat& depth() const { return depth_; }
  /// Image k as an observation (time k s, the camera on the robot as the importers mount it);
  /// insert it with the robot at the origin.
  mrpt::obs::CObservation3DRangeScan Observation(int k) const;

 private:
  std::string folder_;
  FixedCameraOptions options_;
  ImageFolderListing listing_;
  core::PinholeCamera camera_;
  cv::Mat depth_;
};

}  // namespace novelty::sensors
