// The surprise-driven object learner of thesis 5.1, one frame at a time, after the caller has
// found the focus of attention (focus_of_attention.h), extracted the selected features inside
// its box and reconstructed what it could of them (the rig's other camera: epipolar matching;
// RGB-D: the depth):
//   1. static features: selected features that an active feature explains (eq. 5.1, 5.2);
//   2. recognition: the database's object of most matches (eq. 5.3, 5.4) — with verify_pose, only
//      if the matched features' 3-D places agree on a camera pose; failing that, the
//      active features — the object being learnt; failing both, an unknown object, which gets a
//      new class if one of the static features lies mostly on surprise (ρ_S > T, eq. 5.5). The
//      thesis leaves open what the active features recognise before the object being learnt has
//      a class — static features exist only where active features match, so read literally no
//      object would ever get one: here the first static feature on surprise gives it its class;
//   3. learning: static features with ρ_S > T that the database does not hold join it under
//      the recognised or new object (eq. 5.6, 5.7);
//   4. reconstructed selected features that are neither static nor in the database become active
//      features (kept while an object is learnt); after `forget_after_frames` frames without
//      selected features they are all dropped — the object has gone.
#pragma once

#include <Eigen/Geometry>
#include <opencv2/core.hpp>
#include <optional>
#include <vector>

#include "core/eigen_abi.h"
#include "core/pinhole_camera.h"
#include "maps/objects/feature_database.h"
#include "maps/objects/focus_of_attention.h"
#include "maps/objects/object_pose_verification.h"
#include "maps/objects/static_features.h"

namespace novelty::objects {

struct ObjectLearnerOptions {
  double static_distance_px = 2.0;    ///< δ of eq. 5.1 (the thesis: 2 px)
  double match_ratio = 0.65;          ///< the ratio test of 5.1 (the thesis: 0.65)
  double min_surprising_share = 0.8;  ///< T of eq. 5.5 (the thesis: 0.8)
  /// Side of a descriptor's window in units of its scale s, over which ρ_S is measured (M-SURF:
  /// 24s; keypoint size = 10·s, msurf.h).
  double window_per_scale = 24.0;
  double size_per_scale = 10.0;  ///< keypoint size / s of the features given (msurf.h: 10)
  /// +1: the descriptor's window turns by the keypoint's angle (M-SURF); −1: by minus it
  /// (OpenCV's SIFT samples at 360° − angle).
  int window_angle_sign = 1;
  /// Frames without selected features (or without a new object in the focus) that drop the
  /// active ones (thesis 5.1: 10).
  int forget_after_frames = 10;
  /// Beyond the thesis: the database recognises an object only if the 3-D places of its matched
  /// features agree on a camera pose (object_pose_verification.h); false: eq. 5.4 alone.
  bool verify_pose = false;
  /// Beyond the thesis: the ratio test against the database compares with the second candidate
  /// of another place (ratio_matches.h); false: with any second candidate (the thesis).
  bool distinct_second_match = false;
  /// Beyond the thesis: the object being learnt is recognised by its active features wherever
  /// the frame has static features — eq. 5.1 and 5.2 have tied each to an active feature by
  /// place and descriptor — as well as where a selected feature passes the ratio test against
  /// the active features. That test fails where the active features hold similar descriptors
  /// (neighbouring places of one print), and the object then got a second class. Active features
  /// are whatever the focus box held, not only the object: like a ratio match, a static feature
  /// on what stands around it recognises the object being learnt too, until the active
  /// features are forgotten. false: the ratio test alone.
  bool static_features_recognise = false;
  PoseVerificationOptions verification;
};

/// The selected features of one frame and what the caller reconstructed of them.
struct SelectedFeatures {
  std::vector<cv::KeyPoint> keypoints;  ///< inside the focus of attention
  cv::Mat descriptors;                  ///< CV_32F, one row per keypoint
  /// Per keypoint: its 3-D position in the camera frame, if reconstructed.
  std::vector<std::optional<Eigen::Vector3d>> p_cam;
  /// Per keypoint: ‖d − d_m‖ to its match in the other camera (eq. 5.2's bound), where
  /// reconstructed.
  std::vector<double> max_descriptor_change;
};

struct LearnerStep {
  enum class Recognised { kNothing, kByDatabase, kByActiveFeatures, kNewObject };
  Recognised recognised = Recognised::kNothing;
  int object = -1;                      ///< the recognised or new object, −1 if none
  std::vector<int> matches_per_object;  ///< N_k of eq. 5.4
  int selected = 0, static_features = 0, learnt = 0, new_active = 0, active = 0;
  /// With verify_pose, for the object the database's matches name: whether a pose verified it
  /// (else it is not recognised by the database) and the object's pose in the camera.
  bool verification_tried = false;
  VerifiedPose verification;
};

class ObjectLearner {
 public:
  explicit ObjectLearner(const ObjectLearnerOptions& options = {});

  /// One frame: the focus of attention it was selected in, its selected features, and the
  /// camera and its pose. A frame without features counts towards `forget_after_frames`; the
  /// acquisition (object_acquisition.h) gives none where the focus holds no new object, so that
  /// the active features of an object that has gone do not live on in whatever the focus turns
  /// to next. Throws std::invalid_argument when the features' vectors disagree.
  LearnerStep Process(const FocusOfAttention& focus, const SelectedFeatures& features,
                      const core::PinholeCamera& camera, const Eigen::Isometry3d& T_world_cam);

  const FeatureDatabase& database() const { return database_; }
  FeatureDatabase& database() { return database_; }
  const std::vector<ActiveFeature>& active() const { return active_; }
  const ObjectLearnerOptions& options() const { return options_; }

 private:
  // Whether a selected feature passes the ratio test against the active features.
  bool MatchesActiveFeatures(const cv::Mat& descriptors) const;

  ObjectLearnerOptions options_;
  FeatureDatabase database_;
  std::vector<ActiveFeature> active_;
  int frames_without_features_ = 0;
  int learning_object_ = -1;  // the object the active features belong to, once it has a class
};

}  // namespace novelty::objects
