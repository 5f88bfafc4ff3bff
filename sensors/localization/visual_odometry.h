// Visual localization with a stereo camera (thesis 3.1.1, after [MSSB09] and the vision-based
// GPS of [BH04]): KLT features are tracked in the reference images; a feature is triangulated
// once, when it is new, and its world position kept; every frame the tracked features are
// triangulated again in the camera frame and the camera pose follows from fitting the two point
// sets by SVD with outlier weights (eq. 3.1–3.4). A new feature joins the map only when its
// second triangulation agrees with its first (corners at occlusion boundaries do not), and its
// world position is the mean of its triangulations. Features are detected on a grid so they cover
// the whole image. When too few features survive, the pose is recovered against kept keyframes
// (ORB matches + PnP with RANSAC; the thesis's [MMBS09] used SURF).
#pragma once

#include <Eigen/Geometry>
#include <memory>
#include <opencv2/core.hpp>
#include <optional>
#include <string>
#include <vector>

#include "core/eigen_abi.h"
#include "sensors/localization/keyframe_relocalizer.h"
#include "sensors/localization/stereo_pair.h"
#include "sensors/localization/stereo_triangulation.h"

namespace novelty::sensors {

struct VisualOdometryOptions {
  StereoTriangulationOptions stereo;
  int grid_columns = 8, grid_rows = 6;  ///< detection grid: features spread over the image
  int features_per_cell = 6;            ///< detection target per cell
  int min_features = 60;                ///< below this many tracked features new ones are detected
  int min_inliers = 12;                 ///< fewer inliers: tracking is lost (re-localize)
  /// Forward–backward KLT check between frames (pixels).
  double max_track_error = 1.0;
  /// Re-alignment with the feature's first appearance may move it at most this far (pixels);
  /// farther, the feature is dropped.
  double max_anchor_shift = 2.0;
  /// Outlier weighting of eq. 3.4: residuals are expressed as disparity error (pixels), since
  /// stereo depth noise grows with depth²; Tukey weights, 0 from this residual on.
  double outlier_threshold_px = 1.5;
  int fit_iterations = 6;
  /// RANSAC (PnP on the reprojections of the kept 3D points) first selects the inliers and gives
  /// the starting pose: a tracked "corner" where two surfaces meet at an occlusion boundary has
  /// no 3D point and would otherwise bias the fit. Threshold in pixels.
  double ransac_reprojection_px = 1.0;
  /// false (default): the pose is the thesis's weighted SVD fit of the 3D point sets on the
  /// RANSAC inliers; true: the reprojection error of the inliers is minimised instead.
  bool pose_from_reprojection = true;
  /// Keyframes for re-localization: one every this many frames (0 = none).
  int keyframe_every = 10;
  KeyframeRelocalizerOptions relocalizer;
};

struct VisualOdometryResult {
  Eigen::Isometry3d world_from_camera = Eigen::Isometry3d::Identity();
  int tracked = 0;  ///< features tracked into this frame
  int inliers = 0;  ///< features with non-zero weight in the final fit
  bool relocalized = false;
};

class VisualOdometry {
 public:
  /// `initial_pose`: T_world_cam of the first frame (the VGPS reference frame: identity).
  explicit VisualOdometry(const VisualOdometryOptions& options = {},
                          const Eigen::Isometry3d& initial_pose = Eigen::Isometry3d::Identity());
  ~VisualOdometry();

  /// The pose of this frame, or nullopt with the reason (lost and not re-localized; bad input).
  std::optional<VisualOdometryResult> Track(const StereoPair& pair, std::string* why);

 private:
  class Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace novelty::sensors
