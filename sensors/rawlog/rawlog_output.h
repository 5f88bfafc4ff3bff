// Writes an MRPT rawlog in the "observations" format (a plain sequence of serialized
// observations) with images stored externally in MRPT's `<name>_Images/` folder beside it, so
// `rawlog-edit`, `RawLogViewer` and MRPT's CRawlog read it. Written to a new temporary beside it
// (core::TemporaryFile), the images to a new folder beside `<name>_Images/`, both renamed into
// place on Close(): a reader never sees half a rawlog, and a program that fails while writing
// publishes none and leaves an earlier rawlog and its images as they were. Used by the simulator
// and by the converters (novelty-depth, novelty-poses).
#pragma once

#include <mrpt/img/CImage.h>
#include <mrpt/serialization/CSerializable.h>

#include <Eigen/Geometry>
#include <exception>
#include <memory>
#include <opencv2/core.hpp>
#include <string>

#include "core/eigen_abi.h"
#include "core/pinhole_camera.h"
#include "core/temporary_file.h"

namespace novelty::sensors {

class RawlogOutput {
 public:
  /// Opens `path` (…/NAME.rawlog) via a temporary and a new images folder beside …/NAME_Images/
  /// (images_dir() until Close(), NAME_Images after). Throws
  /// std::runtime_error naming the file when it cannot be created.
  explicit RawlogOutput(const std::string& path);
  ~RawlogOutput();

  void Write(const mrpt::serialization::CSerializable& object);
  /// Saves an RGB image as a PNG under NAME_Images (file name `file`) and returns a CImage that
  /// refers to it.
  mrpt::img::CImage ExternalImage(const cv::Mat& rgb, const std::string& file) const;
  /// An RGB-D frame as CObservation3DRangeScan (rgbd_observation.h) with its range image and
  /// colour image stored externally under `stem`. `time`: seconds since the Unix epoch.
  void WriteRgbd(double time, const cv::Mat& rgb, const cv::Mat& depth,
                 const core::PinholeCamera& camera, const Eigen::Isometry3d& robot_from_camera,
                 const std::string& stem, const std::string& label = "RGBD");

  /// Makes the external images of `input_rawlog` (its NAME_Images/) available to this rawlog by
  /// hard-linking them (copying where links are not possible), for converters that copy
  /// observations through unchanged.
  void ShareImagesOf(const std::string& input_rawlog) const;

  /// Flushes and renames the temporary to the final name. The destructor does it too (swallowing
  /// errors) unless it runs because of an exception: then nothing is published.
  void Close();
  const std::string& path() const { return final_path_; }
  const std::string& images_dir() const { return images_dir_; }
  int objects() const { return count_; }

 private:
  class Impl;
  std::unique_ptr<Impl> impl_;
  std::string final_path_, images_dir_, final_images_dir_;
  std::unique_ptr<core::TemporaryFile> temp_;
  int uncaught_at_start_ = std::uncaught_exceptions();
  int count_ = 0;
};

}  // namespace novelty::sensors
