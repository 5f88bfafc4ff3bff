#include "sensors/rawlog/rawlog_frame_reader.h"
#include "sensors/rawlog/external_files.h"

#include "sensors/rawlog/camera_pose_observation.h"
#include "sensors/rawlog/rawlog_input.h"
#include "sensors/rawlog/rgbd_observation.h"

#include <mrpt/obs/CObservation3DRangeScan.h>

#include <cstdio>
#include <fstream>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <sstream>
#include <stdexcept>

namespace novelty::sensors {

class RawlogFrameReader::Impl {
 public:
  explicit Impl(const std::string& path) : input(path) {}
  RawlogInput input;
  mrpt::obs::CObservationRobotPose::Ptr last_pose;  // the latest camera pose seen
};

RawlogFrameReader::RawlogFrameReader(const std::string& path)
    : impl_(std::make_unique<Impl>(path)), path_(path) {}

RawlogFrameReader::~RawlogFrameReader() = default;

bool RawlogFrameReader::Next(core::Frame& frame) {
  while (true) {
    // A truncated or foreign file throws, naming the object; what was read is kept.
    const auto obj = impl_->input.Next();
    if (!obj) return false;
    if (auto pose = std::dynamic_pointer_cast<mrpt::obs::CObservationRobotPose>(obj)) {
      impl_->last_pose = pose;
      continue;
    }
    auto scan = std::dynamic_pointer_cast<mrpt::obs::CObservation3DRangeScan>(obj);
    if (!scan) continue;
    const int index = ++frames_;
    const std::string where = path_ + ": RGB-D frame " + std::to_string(index);
    CheckImageFolder(*scan, where);  // fatal: every frame would be skipped for it
    try {
      CheckExternalDepth(*scan);
      scan->load();
      DecodeRgbd(*scan, frame.rgb, frame.depth, frame.camera);
      frame.index = index;
      frame.time = mrpt::Clock::toDouble(scan->timestamp);
      frame.label = scan->sensorLabel;
      frame.T_world_cam.reset();
      frame.pose_source.clear();
      if (const auto& p = impl_->last_pose; p && p->timestamp == scan->timestamp) {
        frame.T_world_cam = RobotPoseOf(*p) * CameraOnRobot(*scan);
        frame.pose_source = p->sensorLabel;
      }
      scan->unload();
      return true;
    } catch (const std::exception& e) {
      skip_reasons_.push_back(where + ": " + e.what());
    }
  }
}

}  // namespace novelty::sensors
