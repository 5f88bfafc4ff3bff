#include "sim/output/rawlog_writer.h"

#include "maps/eval/write_rgb_image.h"
#include "sensors/rawlog/led_observation.h"
#include "sensors/rawlog/rgbd_observation.h"

#include <mrpt/io/CFileOutputStream.h>
#include <mrpt/obs/CObservation3DRangeScan.h>
#include <mrpt/obs/CObservationImage.h>
#include <mrpt/obs/CObservationOdometry.h>
#include <mrpt/obs/CObservationStereoImages.h>
#include <mrpt/serialization/CArchive.h>

#include <cmath>
#include <filesystem>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <stdexcept>

namespace novelty::sim {

namespace {

constexpr double kEpoch = 1293840000.0;  // 2011-01-01 00:00:00 UTC

mrpt::Clock::time_point Stamp(double t) {
  return mrpt::Clock::fromDouble(kEpoch + t);
}

}  // namespace

class RawlogWriter::Impl {
 public:
  explicit Impl(const std::string& path) : file(path) {
    if (!file.fileOpenCorrectly()) throw std::runtime_error(path + ": cannot open for writing");
  }
  mrpt::io::CFileOutputStream file;
};

RawlogWriter::RawlogWriter(const std::string& dir, const std::string& name)
    : final_path_(dir + "/" + name + ".rawlog"),
      temp_path_(final_path_ + ".tmp"),
      images_dir_(dir + "/" + name + "_Images") {
  std::filesystem::create_directories(images_dir_);
  impl_ = std::make_unique<Impl>(temp_path_);
}

RawlogWriter::~RawlogWriter() {
  try {
    Close();
  } catch (...) {  // a destructor must not throw; Close() reports errors when called directly
  }
}

void RawlogWriter::Close() {
  if (!impl_) return;
  impl_->file.close();
  impl_.reset();
  std::filesystem::rename(temp_path_, final_path_);
}

// Saves an RGB image as PNG under NAME_Images and returns a CImage that refers to it.
static mrpt::img::CImage External(const std::string& images_dir, const cv::Mat& rgb,
                                  const std::string& file) {
  eval::WriteRgbImage(images_dir + "/" + file, rgb);
  mrpt::img::CImage img;
  img.setExternalStorage(file);
  return img;
}

void RawlogWriter::WriteImage(double t, const std::string& label, const cv::Mat& rgb,
                              const views::PinholeCamera& camera,
                              const Eigen::Isometry3d& robot_from_camera, const std::string& stem) {
  mrpt::obs::CObservationImage obs;
  obs.timestamp = Stamp(t);
  obs.sensorLabel = label;
  obs.cameraParams = sensors::ToMrpt(camera);
  obs.cameraPose = sensors::ToMrpt(robot_from_camera);
  obs.image = External(images_dir_, rgb, stem + ".png");
  auto arch = mrpt::serialization::archiveFrom(impl_->file);
  arch << obs;
  ++count_;
}

void RawlogWriter::WriteStereo(double t, const cv::Mat& left, const cv::Mat& right,
                               const views::PinholeCamera& camera,
                               const Eigen::Isometry3d& robot_from_left, double baseline,
                               const std::string& stem) {
  mrpt::obs::CObservationStereoImages obs;
  obs.timestamp = Stamp(t);
  obs.sensorLabel = "STEREO";
  obs.leftCamera = obs.rightCamera = sensors::ToMrpt(camera);
  obs.cameraPose = mrpt::poses::CPose3DQuat(sensors::ToMrpt(robot_from_left));
  obs.rightCameraPose = mrpt::poses::CPose3DQuat(mrpt::poses::CPose3D(baseline, 0, 0, 0, 0, 0));
  obs.imageLeft = External(images_dir_, left, stem + "_left.png");
  obs.imageRight = External(images_dir_, right, stem + "_right.png");
  obs.hasImageRight = true;
  auto arch = mrpt::serialization::archiveFrom(impl_->file);
  arch << obs;
  ++count_;
}

void RawlogWriter::WriteRgbd(double t, const cv::Mat& rgb, const cv::Mat& depth,
                             const views::PinholeCamera& camera,
                             const Eigen::Isometry3d& robot_from_camera, const std::string& stem) {
  mrpt::obs::CObservation3DRangeScan obs =
      sensors::MakeRgbdObservation(kEpoch + t, rgb, depth, camera, robot_from_camera);
  obs.rangeImage_convertToExternalStorage(stem + "_depth.bin", images_dir_ + "/");
  obs.intensityImage = External(images_dir_, rgb, stem + ".png");  // in place of the in-memory one
  auto arch = mrpt::serialization::archiveFrom(impl_->file);
  arch << obs;
  ++count_;
}

void RawlogWriter::WriteTracker(double t, const sensors::LedMeasurement& leds, double noise_std) {
  auto obs = sensors::MakeLedObservation(kEpoch + t, leds, noise_std);
  auto arch = mrpt::serialization::archiveFrom(impl_->file);
  arch << obs;
  ++count_;
}

void RawlogWriter::WriteOdometry(double t, const Odometry& o) {
  mrpt::obs::CObservationOdometry obs;
  obs.timestamp = Stamp(t);
  obs.sensorLabel = "ODOMETRY";
  obs.odometry = mrpt::poses::CPose2D(o.x, o.y, o.phi);
  obs.hasEncodersInfo = true;
  obs.encoderLeftTicks = static_cast<int32_t>(o.left_ticks);
  obs.encoderRightTicks = static_cast<int32_t>(o.right_ticks);
  obs.hasVelocities = true;
  obs.velocityLocal = mrpt::math::TTwist2D(o.v, 0.0, o.w);
  auto arch = mrpt::serialization::archiveFrom(impl_->file);
  arch << obs;
  ++count_;
}

}  // namespace novelty::sim
