#include "sim/output/rawlog_writer.h"

#include <mrpt/io/CFileOutputStream.h>
#include <mrpt/obs/CObservation3DRangeScan.h>
#include <mrpt/obs/CObservationBearingRange.h>
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

mrpt::poses::CPose3D ToMrpt(const Eigen::Isometry3d& p) {
  mrpt::math::CMatrixDouble44 m;
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) m(r, c) = p.matrix()(r, c);
  return mrpt::poses::CPose3D(m);
}

mrpt::img::TCamera ToMrpt(const views::PinholeCamera& c) {
  mrpt::img::TCamera t;
  t.ncols = static_cast<uint32_t>(c.width);
  t.nrows = static_cast<uint32_t>(c.height);
  t.fx(c.fx);
  t.fy(c.fy);
  t.cx(c.cx);
  t.cy(c.cy);
  return t;
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
  cv::Mat bgr;
  cv::cvtColor(rgb, bgr, cv::COLOR_RGB2BGR);
  if (!cv::imwrite(images_dir + "/" + file, bgr)) {
    throw std::runtime_error(images_dir + "/" + file + ": cannot write image");
  }
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
  obs.cameraParams = ToMrpt(camera);
  obs.cameraPose = ToMrpt(robot_from_camera);
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
  obs.leftCamera = obs.rightCamera = ToMrpt(camera);
  obs.cameraPose = mrpt::poses::CPose3DQuat(ToMrpt(robot_from_left));
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
  mrpt::obs::CObservation3DRangeScan obs;
  obs.timestamp = Stamp(t);
  obs.sensorLabel = "RGBD";
  obs.cameraParams = obs.cameraParamsIntensity = ToMrpt(camera);
  // MRPT's 3D-scan sensor frame has +X forward, +Y left, +Z up.
  Eigen::Isometry3d camera_from_sensor = Eigen::Isometry3d::Identity();
  camera_from_sensor.linear() << 0, -1, 0, 0, 0, -1, 1, 0, 0;
  obs.sensorPose = ToMrpt(robot_from_camera * camera_from_sensor);
  obs.range_is_depth = true;
  obs.rangeUnits = 0.0002f;  // 0.2 mm steps, up to 13 m
  obs.hasRangeImage = true;
  obs.rangeImage_setSize(depth.rows, depth.cols);
  for (int r = 0; r < depth.rows; ++r) {
    for (int c = 0; c < depth.cols; ++c) {
      const float d = depth.at<float>(r, c);
      obs.rangeImage(r, c) = (d > 0 && std::isfinite(d))
                                 ? uint16_t(std::min(65535.0f, std::round(d / obs.rangeUnits)))
                                 : 0;
    }
  }
  obs.rangeImage_convertToExternalStorage(stem + "_depth.bin", images_dir_ + "/");
  obs.hasIntensityImage = true;
  obs.intensityImage = External(images_dir_, rgb, stem + ".png");
  auto arch = mrpt::serialization::archiveFrom(impl_->file);
  arch << obs;
  ++count_;
}

void RawlogWriter::WriteTracker(double t, const LedMeasurement& leds, double noise_std) {
  mrpt::obs::CObservationBearingRange obs;
  obs.timestamp = Stamp(t);
  obs.sensorLabel = "LED_TRACKER";
  obs.minSensorDistance = 0.0f;
  obs.maxSensorDistance = 20.0f;
  obs.fieldOfView_yaw = float(2 * M_PI);
  obs.fieldOfView_pitch = float(M_PI);
  obs.sensor_std_range = float(noise_std);
  for (int i = 0; i < 4; ++i) {
    if (!leds[i]) continue;
    const Eigen::Vector3d p = *leds[i];
    mrpt::obs::CObservationBearingRange::TMeasurement m;
    m.range = float(p.norm());
    m.yaw = float(std::atan2(p.y(), p.x()));
    m.pitch = float(std::atan2(-p.z(), std::hypot(p.x(), p.y())));  // MRPT: pitch = −elevation
    m.landmarkID = i + 1;
    obs.sensedData.push_back(m);
  }
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
