#include "sim/output/rawlog_writer.h"

#include "sensors/rawlog/led_observation.h"
#include "sensors/rawlog/rawlog_output.h"
#include "sensors/rawlog/rgbd_observation.h"

#include <mrpt/obs/CObservationImage.h>
#include <mrpt/obs/CObservationOdometry.h>
#include <mrpt/obs/CObservationStereoImages.h>

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

RawlogWriter::RawlogWriter(const std::string& dir, const std::string& name)
    : out_(std::make_unique<sensors::RawlogOutput>(dir + "/" + name + ".rawlog")) {}

RawlogWriter::~RawlogWriter() = default;

void RawlogWriter::Close() {
  out_->Close();
}

void RawlogWriter::WriteImage(double t, const std::string& label, const cv::Mat& rgb,
                              const core::PinholeCamera& camera,
                              const Eigen::Isometry3d& robot_from_camera, const std::string& stem) {
  mrpt::obs::CObservationImage obs;
  obs.timestamp = Stamp(t);
  obs.sensorLabel = label;
  obs.cameraParams = sensors::ToMrpt(camera);
  obs.cameraPose = sensors::ToMrpt(robot_from_camera);
  obs.image = out_->ExternalImage(rgb, stem + ".png");
  out_->Write(obs);
}

void RawlogWriter::WriteStereo(double t, const cv::Mat& left, const cv::Mat& right,
                               const core::PinholeCamera& camera,
                               const Eigen::Isometry3d& robot_from_left, double baseline,
                               const std::string& stem) {
  mrpt::obs::CObservationStereoImages obs;
  obs.timestamp = Stamp(t);
  obs.sensorLabel = "STEREO";
  obs.leftCamera = obs.rightCamera = sensors::ToMrpt(camera);
  obs.cameraPose = mrpt::poses::CPose3DQuat(sensors::ToMrpt(robot_from_left));
  obs.rightCameraPose = mrpt::poses::CPose3DQuat(mrpt::poses::CPose3D(baseline, 0, 0, 0, 0, 0));
  obs.imageLeft = out_->ExternalImage(left, stem + "_left.png");
  obs.imageRight = out_->ExternalImage(right, stem + "_right.png");
  obs.hasImageRight = true;
  out_->Write(obs);
}

void RawlogWriter::WriteRgbd(double t, const cv::Mat& rgb, const cv::Mat& depth,
                             const core::PinholeCamera& camera,
                             const Eigen::Isometry3d& robot_from_camera, const std::string& stem) {
  out_->WriteRgbd(kEpoch + t, rgb, depth, camera, robot_from_camera, stem);
}

void RawlogWriter::WriteTracker(double t, const sensors::LedMeasurement& leds, double noise_std) {
  out_->Write(sensors::MakeLedObservation(kEpoch + t, leds, noise_std));
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
  out_->Write(obs);
}

}  // namespace novelty::sim
