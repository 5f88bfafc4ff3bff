// Surprise-driven acquisition of object features from an RGB-D frame (thesis 5.1, all steps):
//   1. the focus of attention on the frame's surprise map (focus_of_attention.h);
//   2. added or removed (change_kind.h): the focus region's observed depth against the depth the
//      appearance map expects there; a removed object's region shows the background it hid, and
//      an unchanged depth says the surprise is not an object (light, noise): in both, no feature
//      is extracted or learnt (the frame counts as one without selected features) — except that
//      an unchanged region within forget_after_frames of an added one is still the added
//      object: the map, which takes each frame's depth, soon expects it there;
//   3. features inside the focus box, by the chosen extractor (feature_extractor.h);
//   4. their 3-D positions from the frame's depth (the thesis matched along the other camera's
//      epipolar lines; sensors/localization/epipolar_feature_matching.h does that for a rig);
//   5. static features, recognition and learning (object_learner.h, eq. 5.1–5.7).
// No MRPT types: mrpt_plugins/c_object_database_map.h feeds it from rawlog observations.
#pragma once

#include <Eigen/Geometry>
#include <opencv2/features2d.hpp>

#include "core/eigen_abi.h"
#include "core/pinhole_camera.h"
#include "maps/objects/change_kind.h"
#include "maps/objects/feature_extractor.h"
#include "maps/objects/focus_of_attention.h"
#include "maps/objects/object_learner.h"

namespace novelty::objects {

/// Defaults: the thesis's algorithm (M-SURF, surprise alone). CObjectDatabaseMap's options, which
/// users set, default to the best measured setting instead (mrpt_plugins/
/// object_database_map_options.h).
struct ObjectAcquisitionOptions {
  /// M-SURF (the thesis's SURF), SIFT or AKAZE (feature_extractor.h).
  FeatureExtractor extractor = FeatureExtractor::kMSurf;
  FocusOfAttentionOptions focus;
  /// The learner's thresholds (δ, ratio, T, forgetting). Its window_per_scale, size_per_scale
  /// and window_angle_sign are set from the extractor (feature_extractor.h): what is given there
  /// is not used.
  ObjectLearnerOptions learner;
  ChangeKindOptions change;
  /// Eq. 5.2's bound ‖d_g − d_m‖ for a feature reconstructed from depth, where there is no second
  /// camera to match d_m in, as a share of ‖d_g‖ (M-SURF descriptors have norm 1, OpenCV's SIFT
  /// 512). 0.3: a match between neighbouring frames is nearer than that for M-SURF, unrelated
  /// features about 1 apart (msurf_test.cc on graf).
  double relative_descriptor_change = 0.3;
  /// SIFT and AKAZE extract features from the focus box grown by this many pixels on each side,
  /// not from the whole frame (DetectAndComputeInBox): they build their scale space over what they
  /// are given. Keypoints whose descriptor windows leave the crop are left out, so a larger margin
  /// keeps larger keypoints. 32: on graf1 at 320×240, in 96 × 80 boxes, SIFT returns every
  /// keypoint whose window fits, each the whole frame's with a descriptor within 20 % of its norm
  /// (the same feature by eq. 5.2's bound; identical away from the crop's edge;
  /// feature_extractor_test.cc). M-SURF, which searches only near the box already, always gets
  /// the whole frame. < 0: the whole frame with the box as mask, every keypoint kept.
  int extraction_margin = 32;
  /// Learn where the appearance map expects no depth, or too little of the region has both
  /// depths to tell added from removed (ChangeKind::kUnknown): the thesis always learnt. Where
  /// both depths are known and equal (kUnchanged) nothing is learnt, unless:
  bool learn_unknown_change = true;
  /// Learn where the depths are equal too (the thesis, which had no depth test). A map that
  /// takes each frame's depth into its views (appearance_map.h) expects an object's shape soon
  /// after it appeared, long before its look stops surprising; while the robot stands still, at
  /// once. Off, an unchanged region is learnt from only within forget_after_frames of an added
  /// one; later ones count towards forgetting the active features (object_learner.h).
  bool learn_unchanged_change = false;
  /// Beyond the thesis: in a region judged added, ρ_S (eq. 5.5) counts as surprising the pixels
  /// whose depth is nearer than the farthest surface the map's views saw there (NearerMask, the
  /// pixels that made the region added), as well as those above θ_S. Surprise on a new object
  /// has holes where its print happens to match the colours the map expects behind it, and few
  /// descriptor windows lie 80 % on it; the depth says the object is there all the same (and
  /// not on its shadow, which is not nearer). false: ρ_S from
  /// surprise alone (the thesis).
  bool nearer_is_surprising = false;
  /// Beyond the thesis: select only the features whose depth is nearer than the farthest
  /// surface the map's views saw at their pixel (NearerMask) — where something now stands that
  /// was not there. The new object's shadow and the table or cloth around it surprise too, at
  /// the depth the map expects, and a focus box that covers the object takes them in (it pays
  /// with a larger focus, morphology_size 7–12 px in the experiment; at 5 px it costs). A pixel
  /// where either depth is unknown is not known to be nearer: its feature is left out too, so a
  /// region the map does not cover (learn_unknown_change) gives none; an empty expected depth
  /// leaves every feature. What the map already expects is never nearer: a region judged
  /// unchanged gives few features (learn_unchanged_change does little), and a standing camera,
  /// whose map takes in the object's depth at once, learns nothing. Only the keypoint's centre
  /// pixel is tested, not its descriptor window. false: the thesis, every feature in the box.
  bool learn_only_nearer_features = false;
  /// Beyond the thesis: in a region judged added, the focus (FocusOfAttention::region and box)
  /// grows over the pixels nearer than the farthest surface the map's views saw (NearerMask)
  /// that touch it, as well as over surprise (GrowFocus). The flood fill of step 2 stops at the
  /// holes surprise has where an object's print matches what the map expects behind it, so its
  /// box may cover a patch of the object; the object's depth covers it whole. Whatever else
  /// stands nearer and touches the object, such as the hand that puts it down, is taken in too.
  /// Only features with ρ_S > T are learnt, so alone it adds little: pair it with
  /// nearer_is_surprising (ρ_S counts the object's depth) and learn_only_nearer_features (the
  /// table in the grown box is left out): the three together learnt the experiment's three
  /// objects as three classes at closings of 5–12 px (docs/objects.md). Regions judged
  /// unchanged do not grow: grown there too, the experiment recognised less. false: the region
  /// of surprise alone (the thesis).
  bool grow_focus_over_nearer = false;
};

struct AcquisitionStep {
  FocusOfAttention focus;  ///< grown if grow_focus_over_nearer grew it
  /// Of the focus region before it grew; kUnknown also when no expected depth was given.
  ChangeClassification change;
  bool learning = false;  ///< the box's features went to the learner (added, or unknown and
                          ///< learn_unknown_change; a box found)
  int extracted = 0;      ///< features extracted in the box
  int not_nearer = 0;     ///< of them, left out by learn_only_nearer_features
  int reconstructed = 0;  ///< of the rest, with a depth
  LearnerStep learner;
};

class ObjectAcquisition {
 public:
  /// Throws std::invalid_argument naming a bad option (extractor name, bound).
  explicit ObjectAcquisition(const ObjectAcquisitionOptions& options = {});

  /// One frame: rgb CV_8UC3 (R, G, B), depth CV_32FC1 (m, 0 or NaN unknown), the appearance
  /// map's surprise CV_32FC1 (NaN where it does not cover), the depth it expects — CV_32FC1, or
  /// CV_32FC2 with the nearest and farthest over its views (change_kind.h); 0 unknown; empty:
  /// none — all of `camera`'s size, and the pose T_world_cam. Throws
  /// std::invalid_argument naming the input that is wrong; the learner is then unchanged.
  AcquisitionStep Process(const cv::Mat& rgb, const cv::Mat& depth, const cv::Mat& surprise,
                          const cv::Mat& expected_depth, const core::PinholeCamera& camera,
                          const Eigen::Isometry3d& T_world_cam);

  const ObjectLearner& learner() const { return learner_; }
  ObjectLearner& learner() { return learner_; }
  const ObjectAcquisitionOptions& options() const { return options_; }

 private:
  // nearer: NearerMask whenever learn_only_nearer_features is on and an expected depth given;
  // empty, every feature is kept.
  SelectedFeatures Extract(const cv::Mat& rgb, const cv::Mat& depth, const cv::Mat& nearer,
                           const cv::Rect& box, const core::PinholeCamera& camera,
                           AcquisitionStep& step);

  ObjectAcquisitionOptions options_;
  cv::Ptr<cv::Feature2D> extractor_;
  ObjectLearner learner_;
  int frames_since_added_ = 1 << 30;  // frames since a focus region was added (or unknown)
};

}  // namespace novelty::objects
