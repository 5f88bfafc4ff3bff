// Writes a scenario's sensors into an MRPT rawlog (sensors/rawlog/rawlog_output.h: observations
// format, images external in `<name>_Images/`, atomic), so `rawlog-edit`, `RawLogViewer` and
// MRPT's CRawlog read it.
//
// What each sensor becomes:
//   camera (mono, trinocular)  CObservationImage; cameraPose = camera on the robot, camera frame
//                              +Z forward, +X right, +Y down (MRPT's optical frame)
//   stereo pair                CObservationStereoImages (cameraPose = left camera)
//   RGB-D                      CObservation3DRangeScan, range_is_depth, rangeUnits 0.2 mm, range
//                              image external (.bin), sensorPose in MRPT's +X-forward convention
//   LED tracker                CObservationBearingRange labelled "LED_TRACKER": the tracker is
//                              fixed to the room, so the "robot" is the world origin and each
//                              visible LED is one (range, yaw, pitch) entry with landmarkID =
//                              LED number 1…4; dropped LEDs are simply absent. This standard class
//                              keeps the LED identities, which a point cloud would lose.
//   wheel odometry             CObservationOdometry with encoder ticks and velocities
// Timestamps are seconds since the scenario start, offset to 2011-01-01 00:00 UTC.
// The file is written to a new temporary beside it and renamed on Close(): never a half rawlog.
#pragma once

#include <Eigen/Geometry>
#include <memory>
#include <opencv2/core.hpp>
#include <string>

#include "core/pinhole_camera.h"
#include "sim/world/led_tracker.h"
#include "sim/world/pioneer3dx.h"

#include "sensors/rawlog/rawlog_output.h"

namespace novelty::sim {

class RawlogWriter {
 public:
  /// Opens DIR/NAME.rawlog (via a temporary) and creates DIR/NAME_Images/.
  RawlogWriter(const std::string& dir, const std::string& name);
  ~RawlogWriter();

  /// `stem`: file name of the image without extension (unique per image).
  void WriteImage(double t, const std::string& label, const cv::Mat& rgb,
                  const core::PinholeCamera& camera, const Eigen::Isometry3d& robot_from_camera,
                  const std::string& stem);
  void WriteStereo(double t, const cv::Mat& left, const cv::Mat& right,
                   const core::PinholeCamera& camera, const Eigen::Isometry3d& robot_from_left,
                   double baseline, const std::string& stem);
  /// depth: CV_32F metres (0 = unknown).
  void WriteRgbd(double t, const cv::Mat& rgb, const cv::Mat& depth,
                 const core::PinholeCamera& camera, const Eigen::Isometry3d& robot_from_camera,
                 const std::string& stem);
  void WriteTracker(double t, const sensors::LedMeasurement& leds, double noise_std);
  void WriteOdometry(double t, const Odometry& odometry);

  /// Flushes and renames the temporary to the final name. Called by the destructor if needed,
  /// but call it to get errors as exceptions.
  void Close();
  std::string rawlog_path() const { return out_->path(); }
  std::string images_dir() const { return out_->images_dir(); }
  int observations() const { return out_->objects(); }

 private:
  std::unique_ptr<sensors::RawlogOutput> out_;
};

}  // namespace novelty::sim
