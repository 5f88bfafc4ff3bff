#include "sensors/dataset/rgbd_sequence.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <stdexcept>

#include "core/regular_file.h"
#include "sensors/dataset/image_header.h"
#include "sensors/dataset/pose_line.h"
#include "sensors/dataset/timestamp_association.h"

namespace novelty::sensors {
namespace {

namespace fs = std::filesystem;

constexpr double kFrameRate = 30.0;  // ICL-NUIM and 7-Scenes: Kinect-rate frames, no timestamps

core::PinholeCamera Camera(double fx, double fy, double cx, double cy) {
  core::PinholeCamera c;
  c.width = 640, c.height = 480;
  c.fx = fx, c.fy = fy, c.cx = cx, c.cy = cy;
  return c;
}

std::string Layout(const fs::path& dir, const std::string& asked) {
  if (asked != "auto") {
    if (asked != "tum" && asked != "icl-nuim" && asked != "7scenes")
      throw std::invalid_argument("layout '" + asked +
                                  "': expected auto, tum, icl-nuim or 7scenes");
    return asked;
  }
  if (fs::exists(dir / "rgb.txt") && fs::exists(dir / "depth.txt")) return "tum";
  if (fs::exists(dir / "pose.txt") && fs::is_directory(dir / "color")) return "icl-nuim";
  if (fs::exists(dir / "frame-000000.color.png")) return "7scenes";
  throw std::runtime_error(dir.string() +
                           ": no RGB-D layout recognised (TUM: rgb.txt and depth.txt; ICL-NUIM: "
                           "pose.txt and color/; 7-Scenes: frame-000000.color.png; a fixed "
                           "camera's images: --layout fixed-camera or cdnet)");
}

// The TUM camera from a folder name: "rgbd_dataset_freiburg3_cabinet", "tum-fr3-cabinet".
std::string TumCameraFromName(const fs::path& dir) {
  static const std::regex name(R"((freiburg|fr)([123]))");
  std::smatch m;
  const std::string folder = fs::absolute(dir).lexically_normal().filename().string();
  const std::string s =
      folder.empty() ? fs::absolute(dir).parent_path().filename().string() : folder;
  if (std::regex_search(s, m, name)) return "fr" + m[2].str();
  throw std::runtime_error(dir.string() +
                           ": which TUM camera took it? Give the camera (fr1, fr2, fr3) or the "
                           "intrinsics; the folder's name does not say");
}

void ReadTum(const fs::path& dir, const RgbdSequenceOptions& o, RgbdSequence& s) {
  const std::vector<TimedLine> rgb = ReadTimedLines((dir / "rgb.txt").string(), 1);
  const std::vector<TimedLine> depth = ReadTimedLines((dir / "depth.txt").string(), 1);
  std::vector<double> rgb_t, depth_t;
  for (const TimedLine& l : rgb) rgb_t.push_back(l.time);
  for (const TimedLine& l : depth) depth_t.push_back(l.time);
  const auto pairs = AssociateByTime(rgb_t, depth_t, o.max_time_difference);
  s.unmatched_rgb = int(rgb.size() - pairs.size());
  std::vector<TimedLine> truth;
  const fs::path truth_path = dir / "groundtruth.txt";
  if (fs::exists(truth_path)) truth = ReadTimedLines(truth_path.string(), 7);
  std::vector<double> truth_t;
  for (const TimedLine& l : truth) truth_t.push_back(l.time);
  std::vector<std::optional<Eigen::Isometry3d>> poses(rgb.size());
  for (const auto& [i, j] : AssociateByTime(rgb_t, truth_t, o.max_time_difference))
    poses[std::size_t(i)] =
        ParsePoseLine(truth[std::size_t(j)].fields,
                      truth_path.string() + ":" + std::to_string(truth[std::size_t(j)].line));
  for (const auto& [i, j] : pairs) {
    RgbdSequenceFrame f;
    f.time = rgb_t[std::size_t(i)];
    f.rgb = (dir / rgb[std::size_t(i)].fields[0]).string();
    f.depth = (dir / depth[std::size_t(j)].fields[0]).string();
    f.T_world_cam = poses[std::size_t(i)];
    if (!truth.empty() && !f.T_world_cam) ++s.unposed;
    s.frames.push_back(std::move(f));
  }
  s.camera_source = o.camera_name.empty() ? TumCameraFromName(dir) : o.camera_name;
  s.camera = NamedCamera(s.camera_source);
}

void ReadIclNuim(const fs::path& dir, const RgbdSequenceOptions& o, RgbdSequence& s) {
  for (const Eigen::Isometry3d& pose : ReadPoseLines((dir / "pose.txt").string())) {
    RgbdSequenceFrame f;
    const int index = int(s.frames.size()) + 1;
    f.time = (index - 1) / kFrameRate;
    f.rgb = (dir / "color" / (std::to_string(index) + ".png")).string();
    f.depth = (dir / "depth" / (std::to_string(index) + ".png")).string();
    f.T_world_cam = pose;
    s.frames.push_back(std::move(f));
  }
  s.camera_source = o.camera_name.empty() ? "icl-nuim" : o.camera_name;
  s.camera = NamedCamera(s.camera_source);
}

// A 4 × 4 (pose) or 3 × 3 (K) matrix of numbers, row by row.
Eigen::MatrixXd ReadMatrix(const fs::path& path, int n) {
  core::CheckRegularFile(path.string(), 1 << 16);
  std::ifstream in(path);
  if (!in) throw std::runtime_error(path.string() + ": cannot open");
  Eigen::MatrixXd m(n, n);
  for (int k = 0; k < n * n; ++k)
    if (!(in >> m(k / n, k % n)) || !std::isfinite(m(k / n, k % n)))
      throw std::runtime_error(path.string() + ": expected a " + std::to_string(n) + "x" +
                               std::to_string(n) + " matrix of numbers");
  return m;
}

void ReadSevenScenes(const fs::path& dir, const RgbdSequenceOptions& o, RgbdSequence& s) {
  for (int k = 0;; ++k) {
    char stem[32];
    std::snprintf(stem, sizeof stem, "frame-%06d", k);
    const fs::path colour = dir / (std::string(stem) + ".color.png");
    if (!fs::exists(colour)) break;
    RgbdSequenceFrame f;
    f.time = k / kFrameRate;
    f.rgb = colour.string();
    f.depth = (dir / (std::string(stem) + ".depth.png")).string();
    const fs::path pose = dir / (std::string(stem) + ".pose.txt");
    if (fs::exists(pose)) {
      const Eigen::MatrixXd m = ReadMatrix(pose, 4);
      Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
      T.matrix() = m;
      if ((T.linear().transpose() * T.linear() - Eigen::Matrix3d::Identity()).norm() > 1e-3 ||
          T.linear().determinant() < 0 || (m.row(3) - Eigen::RowVector4d(0, 0, 0, 1)).norm() > 1e-6)
        throw std::runtime_error(pose.string() +
                                 ": not a rigid pose (a rotation, a translation, 0 0 0 1)");
      f.T_world_cam = T;
    } else {
      ++s.unposed;
    }
    s.frames.push_back(std::move(f));
  }
  s.depth_scale = 1000.0;
  s.invalid_depth = 65535;
  const fs::path intrinsics = dir / "camera-intrinsics.txt";
  if (o.camera_name.empty() && fs::exists(intrinsics)) {
    const Eigen::MatrixXd K = ReadMatrix(intrinsics, 3);
    if (K(1, 0) != 0 || K(2, 0) != 0 || K(2, 1) != 0 || K(2, 2) != 1)
      throw std::runtime_error(intrinsics.string() +
                               ": not a camera matrix (fx 0 cx / 0 fy cy / 0 0 1)");
    s.camera = Camera(K(0, 0), K(1, 1), K(0, 2), K(1, 2));
    s.camera_source = intrinsics.string();
  } else {
    s.camera_source = o.camera_name.empty() ? "7scenes" : o.camera_name;
    s.camera = NamedCamera(s.camera_source);
  }
}

// Focal lengths from a twentieth to a hundred image widths (fields of view of about 170 to 0.6
// degrees), the principal point at most an image size outside the image: anything else is a
// typo, a transposed matrix or another unit.
void CheckIntrinsics(const core::PinholeCamera& c, const std::string& source) {
  const double w = c.width, h = c.height;
  const auto focal = [&](double f) { return std::abs(f) >= w / 20 && std::abs(f) <= 100 * w; };
  if (!focal(c.fx) || !focal(c.fy) || !(c.cx >= -w && c.cx <= 2 * w) ||
      !(c.cy >= -h && c.cy <= 2 * h))
    throw std::runtime_error(
        source + ": implausible intrinsics for " + std::to_string(c.width) + "x" +
        std::to_string(c.height) + " images (fx " + std::to_string(c.fx) + ", fy " +
        std::to_string(c.fy) + ", cx " + std::to_string(c.cx) + ", cy " + std::to_string(c.cy) +
        "; |f| from width/20 to 100 widths, the principal point within an image size of it)");
}

}  // namespace

core::PinholeCamera NamedCamera(const std::string& name) {
  // TUM RGB-D's calibrations (its file formats page); ICL-NUIM's and 7-Scenes' published ones.
  if (name == "fr1") return Camera(517.3, 516.5, 318.6, 255.3);
  if (name == "fr2") return Camera(520.9, 521.0, 325.1, 249.7);
  if (name == "fr3") return Camera(535.4, 539.2, 320.1, 247.6);
  if (name == "icl-nuim") return Camera(481.2, -480.0, 319.5, 239.5);
  if (name == "7scenes") return Camera(585.0, 585.0, 320.0, 240.0);
  throw std::invalid_argument("camera '" + name + "': expected fr1, fr2, fr3, icl-nuim or 7scenes");
}

RgbdSequence ReadRgbdSequence(const std::string& folder, const RgbdSequenceOptions& o) {
  const fs::path dir(folder);
  if (!fs::is_directory(dir)) throw std::runtime_error(folder + ": no such folder");
  RgbdSequence s;
  s.layout = Layout(dir, o.layout);
  if (s.layout == "tum")
    ReadTum(dir, o, s);
  else if (s.layout == "icl-nuim")
    ReadIclNuim(dir, o, s);
  else
    ReadSevenScenes(dir, o, s);
  if (s.frames.empty())
    throw std::runtime_error(folder + ": no frame (" + s.layout +
                             (s.layout == "tum" ? " layout; no colour image has a depth image "
                                                  "within the time tolerance)"
                                                : " layout)"));
  const ImageHeader first = ReadImageHeader(s.frames.front().rgb);
  if (o.camera) {
    const core::PinholeCamera& c = *o.camera;
    s.camera.fx = c.fx, s.camera.fy = c.fy, s.camera.cx = c.cx, s.camera.cy = c.cy;
  } else if (first.size != cv::Size(s.camera.width, s.camera.height)) {
    throw std::runtime_error(s.frames.front().rgb + ": " + std::to_string(first.size.width) + "x" +
                             std::to_string(first.size.height) + ", but the " + s.layout +
                             " intrinsics are for 640x480: give the intrinsics of these images");
  }
  if (o.depth_scale > 0) s.depth_scale = o.depth_scale;
  if (o.camera) s.camera_source = o.camera_source;
  s.camera.width = first.size.width, s.camera.height = first.size.height;
  CheckIntrinsics(s.camera, s.camera_source);
  return s;
}

}  // namespace novelty::sensors
