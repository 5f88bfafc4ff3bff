// Reads the ground truth that GroundTruthWriter writes beside a simulated rawlog (the format:
// ground_truth_writer.h; its constants: ground_truth_format.h): true camera poses, depth, object
// ids, novelty masks, phases and object names, and the changed regions the evaluation scores.
#pragma once

#include <Eigen/Geometry>
#include <map>
#include <opencv2/core.hpp>
#include <string>
#include <vector>

namespace novelty::sim {

class GroundTruthReader {
 public:
  /// Reads DIR/poses.csv (required) and DIR/objects.csv, DIR/events.csv (empty when absent).
  /// Throws std::runtime_error naming the file, and the line of a malformed row.
  explicit GroundTruthReader(const std::string& dir);

  struct Phase {
    std::string name;
    int first = 0, last = 0;  ///< frames, 1-based, inclusive
  };

  const std::string& dir() const { return dir_; }
  /// True T_world_cam per 1-based frame.
  const std::map<int, Eigen::Isometry3d>& CameraPoses() const { return poses_; }
  /// Object id → name (0 room, kArmId the person's arm).
  const std::map<int, std::string>& ObjectNames() const { return objects_; }
  const std::vector<Phase>& Phases() const { return phases_; }
  /// The phase holding `frame`, or "".
  std::string PhaseOf(int frame) const;

  /// True depth (CV_32F metres, 0 = no surface); empty if the frame's file is missing.
  cv::Mat Depth(int frame) const;
  /// Object ids (CV_32S, −1 = no surface); empty if missing.
  cv::Mat Ids(int frame) const;
  /// Novelty codes (CV_8U: kNoveltyAdded, kNoveltyRemoved, 0); empty if missing.
  cv::Mat Novelty(int frame) const;

  /// The changed regions of a frame, by name: each added object (and the arm) where it is seen,
  /// and "removed" where removed objects were; regions under `min_pixels` are left out. Empty
  /// when the frame has no masks.
  std::map<std::string, cv::Mat> ChangedRegions(int frame, int min_pixels) const;

 private:
  std::string dir_;
  std::map<int, Eigen::Isometry3d> poses_;
  std::map<int, std::string> objects_;
  std::vector<Phase> phases_;
};

}  // namespace novelty::sim
