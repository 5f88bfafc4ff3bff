// Ground truth beside a simulated rawlog, in DIR/groundtruth/ (format.txt there repeats this;
// GroundTruthReader reads it; the constants: ground_truth_format.h):
//   poses.csv     frame,time,phase,x,y,z,qx,qy,qz,qw,robot_x,robot_y,robot_phi,odo_x,odo_y,odo_phi
//                 true T_world_cam of the rig's reference camera (mono/RGB-D camera, stereo left,
//                 trinocular centre) as translation + unit quaternion; robot/odometry in the plane
//                 (empty for a tripod). Frames are 1-based like the thesis's table 4.1.
//   rig.csv       camera,width,height,fx,fy,cx,cy,tx,ty,tz: intrinsics and each rig camera's
//                 offset from the reference camera (in the reference camera's frame)
//   depth/NNNNNN.png    uint16, metres × 5000 (as ICL-NUIM/TUM), 0 = no surface
//   ids/NNNNNN.png      uint16, object id + 1 (0 = nothing; 1 = room; arm = 1001)
//   novelty/NNNNNN.png  uint8: 255 = an object added since the start (or moved, or the arm),
//                       128 = where a removed (or moved) object was last seen, 0 = unchanged
//   events.csv    kind,name,first_frame,last_frame,time,description — phases and applied events
//   objects.csv   id,name — the object ids of ids/ (0 room, 1000 the person's arm)
#pragma once

#include <Eigen/Geometry>
#include <fstream>
#include <opencv2/core.hpp>
#include <string>
#include <vector>

#include "core/pinhole_camera.h"
#include "sim/scenario/scenario.h"
#include "sim/world/pioneer3dx.h"

namespace novelty::sim {

class GroundTruthWriter {
 public:
  GroundTruthWriter(const std::string& dir, const Scenario& scenario,
                    const std::vector<Eigen::Isometry3d>& rig_offsets);

  /// frame is 1-based. `robot` may be null (tripod). depth CV_32F m, ids CV_32S, novelty CV_8U.
  void WriteFrame(int frame, double t, const Eigen::Isometry3d& world_from_camera,
                  const Pioneer3dx* robot, const cv::Mat& depth, const cv::Mat& ids,
                  const cv::Mat& novelty);
  /// Writes events.csv from the phases and the applied events ("time kind target").
  void WriteEvents(const std::vector<std::string>& applied_events);
  /// Writes objects.csv: every object id with its name.
  void WriteObjects();

  /// Novelty mask from the current and reference id images (CV_32S) and the changed ids.
  static cv::Mat NoveltyMask(const cv::Mat& ids, const cv::Mat& reference_ids,
                             const std::vector<int>& added, const std::vector<int>& removed);

 private:
  std::string PhaseOf(int frame) const;
  std::string dir_;
  const Scenario& scenario_;
  std::ofstream poses_;
};

}  // namespace novelty::sim
