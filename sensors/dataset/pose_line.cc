#include "sensors/dataset/pose_line.h"

#include <cmath>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "core/regular_file.h"

namespace novelty::sensors {

Eigen::Isometry3d ParsePoseLine(const std::vector<std::string>& fields, const std::string& where) {
  if (fields.size() < 7) throw std::runtime_error(where + ": expected 'tx ty tz qx qy qz qw'");
  double v[7];
  for (int k = 0; k < 7; ++k) {
    std::size_t used = 0;
    try {
      v[k] = std::stod(fields[std::size_t(k)], &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (used != fields[std::size_t(k)].size() || !std::isfinite(v[k]))
      throw std::runtime_error(where + ": '" + fields[std::size_t(k)] + "' is no number");
  }
  const Eigen::Quaterniond q(v[6], v[3], v[4], v[5]);
  if (std::abs(q.norm() - 1.0) > 1e-3)
    throw std::runtime_error(where + ": quaternion is not unit length");
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.linear() = q.normalized().toRotationMatrix();
  T.translation() = Eigen::Vector3d(v[0], v[1], v[2]);
  return T;
}

std::vector<Eigen::Isometry3d> ReadPoseLines(const std::string& path) {
  core::CheckRegularFile(path, std::uintmax_t(1) << 28);
  std::ifstream in(path);
  if (!in) throw std::runtime_error(path + ": cannot open");
  std::vector<Eigen::Isometry3d> poses;
  std::string line;
  for (int n = 1; std::getline(in, line); ++n) {
    if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
    std::istringstream s(line);
    std::vector<std::string> fields;
    for (std::string f; s >> f;) fields.push_back(f);
    poses.push_back(ParsePoseLine(fields, path + ":" + std::to_string(n)));
  }
  return poses;
}

}  // namespace novelty::sensors
