#include "sensors/rawlog/rawlog_output.h"

#include <mrpt/io/CFileOutputStream.h>
#include <mrpt/obs/CObservation3DRangeScan.h>
#include <mrpt/serialization/CArchive.h>

#include <stdlib.h>

#include <exception>
#include <filesystem>
#include <stdexcept>

#include "core/temporary_file.h"
#include "core/write_rgb_image.h"
#include "sensors/rawlog/rawlog_input.h"
#include "sensors/rawlog/rgbd_observation.h"

namespace novelty::sensors {

class RawlogOutput::Impl {
 public:
  explicit Impl(const std::string& path) : file(path) {
    if (!file.fileOpenCorrectly()) throw std::runtime_error(path + ": cannot open for writing");
  }
  mrpt::io::CFileOutputStream file;
};

namespace {

// A new folder beside `final_dir`, named after it: the images are written there and it replaces
// `final_dir` when the rawlog is published, so that a failed run leaves an earlier rawlog's
// images as they were.
std::string MakeStagingDir(const std::string& final_dir) {
  std::string name = final_dir + ".partial.XXXXXX";
  if (!mkdtemp(name.data()))
    throw std::runtime_error(final_dir + ": cannot create a folder beside it for the images");
  return name;
}

}  // namespace

RawlogOutput::RawlogOutput(const std::string& path)
    : final_path_(path), temp_(std::make_unique<core::TemporaryFile>(path)) {
  final_images_dir_ = ImagesDirOf(path);
  images_dir_ = MakeStagingDir(final_images_dir_);
  impl_ = std::make_unique<Impl>(temp_->path());
}

RawlogOutput::~RawlogOutput() {
  // Left by an exception, the rawlog is not published: the temporary and the images go.
  if (std::uncaught_exceptions() > uncaught_at_start_) {
    std::error_code ec;
    if (impl_) std::filesystem::remove_all(images_dir_, ec);
    return;
  }
  try {
    Close();
  } catch (...) {  // a destructor must not throw; Close() reports errors when called directly
  }
}

void RawlogOutput::Write(const mrpt::serialization::CSerializable& object) {
  if (!impl_) throw std::logic_error(final_path_ + ": write after Close()");
  auto arch = mrpt::serialization::archiveFrom(impl_->file);
  arch << object;
  ++count_;
}

mrpt::img::CImage RawlogOutput::ExternalImage(const cv::Mat& rgb, const std::string& file) const {
  core::WriteRgbImage(images_dir_ + "/" + file, rgb);
  mrpt::img::CImage img;
  img.setExternalStorage(file);
  return img;
}

void RawlogOutput::WriteRgbd(double time, const cv::Mat& rgb, const cv::Mat& depth,
                             const core::PinholeCamera& camera,
                             const Eigen::Isometry3d& robot_from_camera, const std::string& stem,
                             const std::string& label) {
  mrpt::obs::CObservation3DRangeScan obs =
      MakeRgbdObservation(time, rgb, depth, camera, robot_from_camera);
  obs.sensorLabel = label;
  obs.rangeImage_convertToExternalStorage(stem + "_depth.bin", images_dir_ + "/");
  obs.intensityImage = ExternalImage(rgb, stem + ".png");  // in place of the in-memory one
  Write(obs);
}

void RawlogOutput::ShareImagesOf(const std::string& input_rawlog) const {
  namespace fs = std::filesystem;
  const fs::path dir = ImagesDirOf(input_rawlog);
  if (!fs::exists(dir)) return;  // no external images
  if (fs::equivalent(dir, images_dir_)) return;
  for (const auto& entry : fs::directory_iterator(dir)) {
    const fs::path target = fs::path(images_dir_) / entry.path().filename();
    if (fs::exists(target)) continue;
    std::error_code ec;
    fs::create_hard_link(entry.path(), target, ec);
    if (ec) fs::copy_file(entry.path(), target);
  }
}

void RawlogOutput::Close() {
  if (!impl_) return;
  namespace fs = std::filesystem;
  impl_->file.close();
  impl_.reset();
  // The images first, then the rawlog that refers to them: an earlier folder is moved aside
  // and removed only once the new one is in place.
  std::string old;
  if (fs::exists(final_images_dir_)) {
    old = MakeStagingDir(final_images_dir_);
    fs::remove(old);
    fs::rename(final_images_dir_, old);
  }
  fs::rename(images_dir_, final_images_dir_);
  images_dir_ = final_images_dir_;
  temp_->Commit();
  std::error_code ec;
  if (!old.empty()) fs::remove_all(old, ec);
}

}  // namespace novelty::sensors
