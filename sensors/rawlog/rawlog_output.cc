#include "sensors/rawlog/rawlog_output.h"

#include <mrpt/io/CFileOutputStream.h>
#include <mrpt/obs/CObservation3DRangeScan.h>
#include <mrpt/serialization/CArchive.h>

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

RawlogOutput::RawlogOutput(const std::string& path)
    : final_path_(path), temp_(std::make_unique<core::TemporaryFile>(path)) {
  images_dir_ = ImagesDirOf(path);
  std::filesystem::create_directories(images_dir_);
  impl_ = std::make_unique<Impl>(temp_->path());
}

RawlogOutput::~RawlogOutput() {
  // Left by an exception, the rawlog is not published: the temporary goes (the images stay).
  if (std::uncaught_exceptions() > uncaught_at_start_) return;
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
  impl_->file.close();
  impl_.reset();
  temp_->Commit();
}

}  // namespace novelty::sensors
