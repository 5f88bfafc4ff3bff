// Writes a recorded RGB-D sequence (rgbd_sequence.h) as an MRPT rawlog the maps read: per frame
// a CObservation3DRangeScan (colour and depth stored externally in NAME_Images/, depth in metres)
// and, where the dataset gives the camera's pose, a CObservationRobotPose "POSE_DATASET" just
// before it (camera_pose_observation.h) — or "POSE_VO" from visual odometry for a sequence
// without poses (ImportPoses), so that `novelty-run --poses rawlog` and the other
// programs take it and rawlog-edit and RawLogViewer open it. The camera is mounted on the "robot"
// looking along its x axis (MRPT's optical frame: +Z forward, +X right, +Y down), so a hand-held
// camera's pose is the robot's.
//
// Every image's size is read from its header and checked against the camera (and the pixel
// limit) before it is decoded; colour must be 8-bit, depth 16-bit one channel. A frame whose
// files are missing, unreadable or of another size is an error naming the file, and nothing is
// published (the rawlog is written to a temporary and renamed at the end).
#pragma once

#include <Eigen/Geometry>
#include <functional>
#include <string>

#include "core/eigen_abi.h"
#include "sensors/dataset/image_header.h"
#include "sensors/dataset/rgbd_sequence.h"
#include "sensors/localization/rgbd_odometry.h"

namespace novelty::sensors {

/// Where the frames' poses come from.
enum class ImportPoses {
  kAuto,     ///< the dataset's; visual odometry for a sequence without any
  kDataset,  ///< the dataset's only (frames without one get none)
  kVisual,   ///< visual odometry (rgbd_odometry.h), from the first frame's dataset pose if any
};

struct RgbdImportOptions {
  int first = 1, last = 0;  ///< frames to write, 1-based inclusive; last 0: to the end
  int every = 1;            ///< every k-th of them
  long long max_pixels = kDefaultMaxImagePixels;
  ImportPoses poses = ImportPoses::kAuto;
  RgbdOdometryOptions odometry;
  /// Told frames written of the total.
  std::function<void(int done, int total)> progress;
};

struct RgbdImportResult {
  int frames = 0;               ///< RGB-D observations written
  int posed = 0;                ///< of them with a pose observation
  double depth_coverage = 0.0;  ///< share of depth pixels known (> 0), over all frames
  /// Depth pixels beyond a range image's 13.1 m (rgbd_observation.h), stored as unknown.
  long long beyond_range = 0;
  bool visual_odometry = false;  ///< the poses written are the odometry's ("POSE_VO")
  int odometry_lost = 0;         ///< frames the odometry could not place (written without pose)
  /// RMS distance (m) of the odometry's camera positions from the dataset's, over the frames
  /// that have both; NaN without dataset poses.
  double odometry_rms_error = 0.0;
};

/// The last frame `o` selects of `frames` (1-based), its first, last and every checked; throws
/// std::invalid_argument naming the bad option.
int LastImportedFrame(const RgbdImportOptions& o, int frames);

/// The camera's mounting written with every frame: optical axis along the robot's x.
Eigen::Isometry3d HandHeldMount();

/// Writes `sequence` to `rawlog` (…/NAME.rawlog). Throws std::runtime_error naming the file or
/// frame; std::invalid_argument for a bad option.
RgbdImportResult ImportRgbdSequence(const RgbdSequence& sequence, const std::string& rawlog,
                                    const RgbdImportOptions& options = {});

}  // namespace novelty::sensors
