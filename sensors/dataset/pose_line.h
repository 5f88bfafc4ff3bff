// A camera pose written as the RGB-D datasets write it: "tx ty tz qx qy qz qw" (TUM RGB-D,
// ICL-NUIM; T_world_cam, p_world = R·p_cam + t, the quaternion Hamilton, w last).
#pragma once

#include <Eigen/Geometry>
#include <string>
#include <vector>

#include "core/eigen_abi.h"

namespace novelty::sensors {

/// From the seven numbers in `fields` (text, as read from the line); throws std::runtime_error
/// starting with `where` (file:line) when there are fewer, one is no finite number, or the
/// quaternion is not of unit length (within 1e-3).
Eigen::Isometry3d ParsePoseLine(const std::vector<std::string>& fields, const std::string& where);

/// Every non-blank line of `path` as a pose (ICL-NUIM's pose.txt), in order; throws
/// std::runtime_error naming the file (and line) when it cannot be opened or a line is bad.
std::vector<Eigen::Isometry3d> ReadPoseLines(const std::string& path);

}  // namespace novelty::sensors
