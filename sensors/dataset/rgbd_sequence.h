// A recorded RGB-D sequence described by its files: the layouts of the public datasets read into
// one list of frames (colour file, depth file, time, camera pose if the dataset has one), with
// the camera's intrinsics and the depth images' scale. Nothing is decoded here; the importer
// (rgbd_importer.h) reads the images.
//
// Layouts (`layout` "auto" tells them by their files):
// - "tum": the TUM RGB-D benchmark — rgb.txt and depth.txt ("timestamp file"), associated by
//   nearest time within max_time_difference (associate.py's rule); groundtruth.txt ("timestamp
//   tx ty tz qx qy qz qw", T_world_cam) optional, its nearest line within the same tolerance
//   gives a frame's pose. Depth factor 5000. Intrinsics by name: fr1, fr2, fr3 (the benchmark's
//   calibrations), guessed from a folder name holding "freiburg1"…"3" or "fr1"…"3".
// - "icl-nuim": color/N.png, depth/N.png and pose.txt ("tx ty tz qx qy qz qw" per frame, frames
//   numbered from 1 in its order); depth factor 5000; intrinsics "icl-nuim" (fy negative: its y
//   axis points up). Frames are 1/30 s apart.
// - "7scenes": frame-NNNNNN.color.png, .depth.png (millimetres, 65535 unknown) and .pose.txt (a
//   4 × 4 T_world_cam); intrinsics from camera-intrinsics.txt (a 3 × 3 K) if there, else
//   "7scenes" (585, 585, 320, 240). Frames are 1/30 s apart.
#pragma once

#include <Eigen/Geometry>
#include <optional>
#include <string>
#include <vector>

#include "core/eigen_abi.h"
#include "core/pinhole_camera.h"

namespace novelty::sensors {

struct RgbdSequenceFrame {
  double time = 0.0;       ///< seconds (the dataset's, else from the frame rate)
  std::string rgb, depth;  ///< paths
  std::optional<Eigen::Isometry3d> T_world_cam;
};

struct RgbdSequence {
  std::string layout;           ///< "tum", "icl-nuim" or "7scenes"
  core::PinholeCamera camera;   ///< width and height from the first colour image's header
  std::string camera_source;    ///< where the intrinsics came from: a name, a file, the flags
  double depth_scale = 5000.0;  ///< depth image units per metre
  int invalid_depth = 0;        ///< depth value that means unknown besides 0 (7-Scenes: 65535)
  std::vector<RgbdSequenceFrame> frames;
  int unmatched_rgb = 0;  ///< colour images without a depth image within the tolerance
  int unposed = 0;        ///< frames without a pose (the dataset has poses, not for these)
};

struct RgbdSequenceOptions {
  std::string layout = "auto";  ///< auto, tum, icl-nuim, 7scenes
  /// TUM: seconds between associated colour, depth and pose lines (associate.py's default).
  double max_time_difference = 0.02;
  /// Intrinsics by name (fr1, fr2, fr3, icl-nuim, 7scenes); empty: the layout's or the folder
  /// name's.
  std::string camera_name;
  /// Intrinsics given (fx, fy, cx, cy; width and height are the images'): used over any name.
  std::optional<core::PinholeCamera> camera;
  std::string camera_source = "the intrinsics given";  ///< where `camera` came from, for errors
  /// Depth units per metre; 0: the layout's.
  double depth_scale = 0.0;
};

/// The intrinsics called `name` (fr1, fr2, fr3, icl-nuim, 7scenes) at 640 × 480; throws
/// std::invalid_argument listing the names.
core::PinholeCamera NamedCamera(const std::string& name);

/// Reads the sequence in `folder`. Throws std::runtime_error naming the file: a missing list or
/// image, a malformed line, a pose that is not rigid, no frame left after association, a layout
/// not told by its files, implausible intrinsics (focal lengths outside a twentieth to a hundred
/// image widths, the principal point more than an image size outside the image).
RgbdSequence ReadRgbdSequence(const std::string& folder, const RgbdSequenceOptions& options = {});

}  // namespace novelty::sensors
