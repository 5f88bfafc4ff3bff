#include "sensors/dataset/rgbd_folder_reader.h"

#include <fstream>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <sstream>
#include <stdexcept>
#include <vector>

#include "sensors/dataset/pose_line.h"

namespace novelty::sensors {

RgbdFolderReader::RgbdFolderReader(const std::string& folder, const core::PinholeCamera& camera,
                                   double depth_scale)
    : folder_(folder), camera_(camera), depth_scale_(depth_scale) {
  camera_.Check();
  if (!(depth_scale > 0)) throw std::invalid_argument("RgbdFolderReader: depth scale must be > 0");
  const std::string path = folder + "/pose.txt";
  poses_ = ReadPoseLines(path);
  if (poses_.empty()) throw std::runtime_error(path + ": no poses");
}

core::Frame RgbdFolderReader::Read(int index) const {
  if (index < 1 || index > size()) {
    throw std::out_of_range(folder_ + ": no frame " + std::to_string(index) + " (1…" +
                            std::to_string(size()) + ")");
  }
  core::Frame f;
  f.index = index;
  f.camera = camera_;
  f.T_world_cam = poses_[std::size_t(index - 1)];
  f.pose_source = "pose.txt";
  const std::string color = folder_ + "/color/" + std::to_string(index) + ".png";
  const std::string depth = folder_ + "/depth/" + std::to_string(index) + ".png";
  const cv::Mat bgr = cv::imread(color, cv::IMREAD_COLOR);
  const cv::Mat raw = cv::imread(depth, cv::IMREAD_ANYDEPTH);
  if (bgr.empty()) throw std::runtime_error(color + ": cannot read image");
  if (raw.empty() || raw.type() != CV_16UC1) {
    throw std::runtime_error(depth + ": cannot read a 16-bit depth image");
  }
  const cv::Size expected(camera_.width, camera_.height);
  if (bgr.size() != expected || raw.size() != expected) {
    throw std::runtime_error(color + ": image size does not match the camera's " +
                             std::to_string(camera_.width) + "x" + std::to_string(camera_.height));
  }
  cv::cvtColor(bgr, f.rgb, cv::COLOR_BGR2RGB);
  raw.convertTo(f.depth, CV_32F, 1.0 / depth_scale_);
  return f;
}

}  // namespace novelty::sensors
