#include "sensors/dataset/rgbd_importer.h"

#include <algorithm>
#include <cmath>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <optional>
#include <stdexcept>

#include "core/frame_stem.h"
#include "core/range_check.h"
#include "sensors/rawlog/camera_pose_observation.h"
#include "sensors/rawlog/rawlog_output.h"
#include "sensors/rawlog/rgbd_observation.h"

namespace novelty::sensors {
namespace {

// Checks `path`'s header (size, layout) against what the frame needs, before decoding it.
void CheckHeader(const std::string& path, const core::PinholeCamera& camera, bool depth,
                 long long max_pixels) {
  const ImageHeader h = CheckImageHeader(path, max_pixels);
  if (h.size != cv::Size(camera.width, camera.height))
    throw std::runtime_error(path + ": " + std::to_string(h.size.width) + "x" +
                             std::to_string(h.size.height) + ", the sequence's images are " +
                             std::to_string(camera.width) + "x" + std::to_string(camera.height));
  if (depth && (h.channels != 1 || h.bit_depth != 16))
    throw std::runtime_error(
        path + ": a depth image must be 16-bit with one channel, this one is " +
        std::to_string(h.bit_depth) + "-bit with " + std::to_string(h.channels) + " channels");
  if (!depth && h.bit_depth != 8)
    throw std::runtime_error(path + ": a colour image must be 8-bit, this one is " +
                             std::to_string(h.bit_depth) + "-bit");
}

// The frame's colour (RGB) and depth (metres, 0 unknown).
void ReadFrame(const RgbdSequence& s, const RgbdSequenceFrame& f, long long max_pixels,
               cv::Mat& rgb, cv::Mat& depth) {
  CheckHeader(f.rgb, s.camera, false, max_pixels);
  CheckHeader(f.depth, s.camera, true, max_pixels);
  const cv::Mat bgr = cv::imread(f.rgb, cv::IMREAD_COLOR);
  if (bgr.empty()) throw std::runtime_error(f.rgb + ": cannot be decoded");
  cv::cvtColor(bgr, rgb, cv::COLOR_BGR2RGB);
  const cv::Mat raw = cv::imread(f.depth, cv::IMREAD_ANYDEPTH);
  if (raw.empty() || raw.type() != CV_16UC1)
    throw std::runtime_error(f.depth + ": cannot be decoded as 16-bit depth");
  raw.convertTo(depth, CV_32F, 1.0 / s.depth_scale);
  if (s.invalid_depth > 0) depth.setTo(0.0f, raw == s.invalid_depth);
}

// Depth beyond what a range image holds becomes unknown (else stored as 13.1 m); counted.
int DropDepthBeyondRange(cv::Mat& depth) {
  const cv::Mat beyond = depth > kRgbdMaxDepth;
  const int n = cv::countNonZero(beyond);
  depth.setTo(0.0f, beyond);
  return n;
}

// Visual odometry when asked, or for a sequence that gives no pose at all.
bool UseOdometry(const RgbdSequence& s, const RgbdImportOptions& o) {
  if (o.poses != ImportPoses::kAuto) return o.poses == ImportPoses::kVisual;
  return std::none_of(s.frames.begin(), s.frames.end(),
                      [](const RgbdSequenceFrame& f) { return f.T_world_cam.has_value(); });
}

}  // namespace

Eigen::Isometry3d HandHeldMount() {
  Eigen::Isometry3d m = Eigen::Isometry3d::Identity();
  m.linear() << 0, 0, 1, -1, 0, 0, 0, -1, 0;  // camera z → robot x, x → −y, y → −z
  return m;
}

int LastImportedFrame(const RgbdImportOptions& o, int n) {
  core::CheckInRange(o.first, 1, n, "first frame");
  core::CheckInRange(o.last, 0, n, "last frame");
  core::CheckInRange(o.every, 1, 1000000, "every");
  if (o.last && o.last < o.first) throw std::invalid_argument("last frame is before the first");
  return o.last ? o.last : n;
}

RgbdImportResult ImportRgbdSequence(const RgbdSequence& s, const std::string& path,
                                    const RgbdImportOptions& o) {
  const int last = LastImportedFrame(o, int(s.frames.size()));
  core::CheckInRange(o.max_pixels, 1, 1LL << 40, "max_pixels");
  core::CheckInRange(s.depth_scale, 1.0, 1e6, "depth_scale");
  const int total = (last - o.first) / o.every + 1;
  RawlogOutput out(path);
  RgbdImportResult r;
  double known = 0.0, pixels = 0.0, squared_error = 0.0;
  int compared = 0;
  const Eigen::Isometry3d mount = HandHeldMount();
  std::optional<RgbdOdometry> odometry;
  r.visual_odometry = UseOdometry(s, o);
  if (r.visual_odometry)
    odometry.emplace(
        s.camera, o.odometry,
        s.frames[std::size_t(o.first - 1)].T_world_cam.value_or(Eigen::Isometry3d::Identity()));
  for (int k = o.first; k <= last; k += o.every) {
    const RgbdSequenceFrame& f = s.frames[std::size_t(k - 1)];
    cv::Mat rgb, depth;
    ReadFrame(s, f, o.max_pixels, rgb, depth);
    r.beyond_range += DropDepthBeyondRange(depth);
    std::optional<Eigen::Isometry3d> pose = f.T_world_cam;
    if (odometry) {
      pose = odometry->Track(rgb, depth, nullptr);
      r.odometry_lost += !pose;
      if (pose && f.T_world_cam) {
        squared_error += (pose->translation() - f.T_world_cam->translation()).squaredNorm();
        ++compared;
      }
    }
    if (pose) {
      out.Write(MakeCameraPoseObservation(f.time, *pose, mount,
                                          odometry ? "POSE_VO" : "POSE_DATASET", 0.001, 0.002));
      ++r.posed;
    }
    out.WriteRgbd(f.time, rgb, depth, s.camera, mount, core::FrameStem(k));
    known += cv::countNonZero(depth > 0);
    pixels += double(depth.total());
    ++r.frames;
    if (o.progress) o.progress(r.frames, total);
  }
  out.Close();
  r.depth_coverage = pixels > 0 ? known / pixels : 0.0;
  r.odometry_rms_error = compared ? std::sqrt(squared_error / compared) : std::nan("");
  return r;
}

}  // namespace novelty::sensors
