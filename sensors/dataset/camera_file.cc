#include "sensors/dataset/camera_file.h"

#include <mrpt/config/CConfigFile.h>
#include <mrpt/containers/yaml.h>
#include <mrpt/img/TCamera.h>

#include <cmath>
#include <filesystem>
#include <stdexcept>

#include "sensors/rawlog/brief_message.h"

namespace novelty::sensors {
namespace {

mrpt::img::TCamera Load(const std::string& path) {
  const std::string ext = std::filesystem::path(path).extension().string();
  if (ext == ".yaml" || ext == ".yml") {
    mrpt::containers::yaml y = mrpt::containers::yaml::FromFile(path);
    if (y.isMap() && !y.has("camera_name")) y["camera_name"] = "camera";  // optional in ROS
    return mrpt::img::TCamera::FromYAML(y);
  }
  const mrpt::config::CConfigFile ini(path);
  mrpt::img::TCamera c;
  c.loadFromConfigFile("CAMERA_PARAMS", ini);
  return c;
}

}  // namespace

core::PinholeCamera ReadCameraFile(const std::string& path) {
  if (!std::filesystem::is_regular_file(path)) throw std::runtime_error(path + ": no such file");
  mrpt::img::TCamera t;
  try {
    t = Load(path);
  } catch (const std::exception& e) {
    throw std::runtime_error(
        path + ": not a camera calibration (ROS YAML or MRPT [CAMERA_PARAMS]): " + BriefMessage(e));
  }
  for (double d : t.dist)
    if (d != 0.0)
      throw std::runtime_error(path +
                               ": the calibration has lens distortion; the maps take "
                               "undistorted images (rectify them first)");
  core::PinholeCamera c;
  c.width = int(t.ncols), c.height = int(t.nrows);
  c.fx = t.fx(), c.fy = t.fy(), c.cx = t.cx(), c.cy = t.cy();
  try {
    c.Check();
  } catch (const std::exception& e) {
    throw std::runtime_error(path + ": " + e.what());
  }
  return c;
}

}  // namespace novelty::sensors
