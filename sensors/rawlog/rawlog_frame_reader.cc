#include "sensors/rawlog/rawlog_frame_reader.h"

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

bool RawlogFrameReader::Next(Frame& frame) {
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
    try {
      scan->load();
      DecodeRgbd(*scan, frame.rgb, frame.depth, frame.camera);
      frame.index = index;
      frame.time = mrpt::Clock::toDouble(scan->timestamp);
      frame.label = scan->sensorLabel;
      frame.pose.reset();
      frame.pose_source.clear();
      if (const auto& p = impl_->last_pose; p && p->timestamp == scan->timestamp) {
        frame.pose = RobotPoseOf(*p) * CameraOnRobot(*scan);
        frame.pose_source = p->sensorLabel;
      }
      scan->unload();
      return true;
    } catch (const std::exception& e) {
      skip_reasons_.push_back(where + ": " + e.what());
    }
  }
}

std::map<int, Eigen::Isometry3d> LoadGroundTruthPoses(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error(path + ": cannot open ground-truth poses");
  std::map<int, Eigen::Isometry3d> poses;
  std::string line;
  std::getline(in, line);  // header
  for (int n = 2; std::getline(in, line); ++n) {
    std::vector<std::string> f;
    std::stringstream s(line);
    for (std::string item; std::getline(s, item, ',');) f.push_back(item);
    try {
      if (f.size() < 10) throw std::invalid_argument("too few columns");
      const Eigen::Quaterniond q(std::stod(f[9]), std::stod(f[6]), std::stod(f[7]),
                                 std::stod(f[8]));
      Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
      T.linear() = q.normalized().toRotationMatrix();
      T.translation() = Eigen::Vector3d(std::stod(f[3]), std::stod(f[4]), std::stod(f[5]));
      poses[std::stoi(f[0])] = T;
    } catch (const std::exception& e) {
      throw std::runtime_error(path + ":" + std::to_string(n) + ": malformed row (" + e.what() +
                               ")");
    }
  }
  return poses;
}

cv::Mat LoadGroundTruthDepth(const std::string& groundtruth_dir, int frame) {
  char name[32];
  std::snprintf(name, sizeof name, "/depth/%06d.png", frame);
  const cv::Mat png = cv::imread(groundtruth_dir + name, cv::IMREAD_UNCHANGED);
  cv::Mat depth;
  if (!png.empty()) png.convertTo(depth, CV_32F, 1.0 / 5000);
  return depth;
}

}  // namespace novelty::sensors
