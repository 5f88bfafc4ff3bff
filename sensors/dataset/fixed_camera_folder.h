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

#include <functional>
#include <opencv2/core.hpp>
#include <string>
#include <vector>

#include "core/pinhole_camera.h"
#include "sensors/dataset/image_header.h"
#include "sensors/dataset/lighting_folder_reader.h"
#include "sensors/dataset/rgbd_importer.h"

namespace novelty::sensors {

/// One image file as 8-bit R G B (16 bits ÷ 257, grey repeated), its size checked against
/// `max_pixels` from the header before decoding where the format allows (PNG, JPEG, BMP) and
/// handed to `check_size` (if given) before it is decoded. Throws std::runtime_error naming the
/// file.
cv::Mat ReadImageRgb8(const std::string& path, long long max_pixels = kDefaultMaxImagePixels,
                      const std::function<void(const cv::Size&)>& check_size = {});

/// The intrinsics of a camera nothing is known of: focal length the image's larger side (a field
/// of view of 53° across it), principal point the centre.
core::PinholeCamera NominalCamera(const cv::Size& size);

struct FixedCameraOptions {
  LightingFolderOptions pick;  ///< which image files are frames
  /// m, the plane every image is given as depth (any positive value serves one pose).
  double depth = 1.0;
  long long max_pixels = kDefaultMaxImagePixels;  ///< per image, checked before decoding
  /// A mask file to use instead of the folder's mask.png (CDnet's ROI.bmp lies beside input/).
  std::string mask;
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

/// A CDnet-layout folder (cdnet_folder.h) as a fixed camera: its input/ frames, ROI.bmp as the
/// mask. Throws std::runtime_error naming the folder or file (ReadCdnetFolder's checks).
FixedCameraFolder CdnetFixedCamera(const std::string& dir, FixedCameraOptions options = {});

/// Writes `folder`'s images (options.first…last, every k-th; their max_pixels is the folder's) to
/// `rawlog` as rgbd_importer.h writes a sequence: per image a CObservationRobotPose
/// "POSE_DATASET" with the robot at the origin (the camera where Observation puts it) and a
/// CObservation3DRangeScan with the plane as depth, so that
/// novelty-run, novelty-illumination-map (a lighting per frame: RAWLOG:each) and MRPT's tools take
/// it. Nothing is published when an image cannot be read. Throws std::runtime_error naming the
/// file, std::invalid_argument for a bad option.
RgbdImportResult ImportFixedCameraFolder(const FixedCameraFolder& folder, const std::string& rawlog,
                                         const RgbdImportOptions& options = {});

}  // namespace novelty::sensors
