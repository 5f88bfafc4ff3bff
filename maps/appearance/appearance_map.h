// The probabilistic appearance map (thesis ch. 4): reference views whose pixels hold, per
// channel Y, Cb, Cr, the normal-gamma hyperparameters of the colour seen there; per frame a prior
// interpolated from nearby views, the Bayesian update with forgetting (eq. 4.8-4.13) and the
// surprise KL(posterior ‖ prior) summed over channels (eq. 4.15-4.21).
//
// Storage: α does not depend on the data (eq. 4.10) and is the same for the three channels, so a
// view stores one α and three β and σ as half floats ("ab_sigma", 7 channels) and the three τ as
// floats ("tau"): τ must stay exact to a few hundredths, since a shift dτ adds dτ²α/(2σ0β) to
// the surprise (eq. 4.19) and σ0 goes down to σ_min = 0.01; half floats resolve τ ≈ 200 only to
// 0.125. That is 7·2 + 3·4 = 26 B/pixel + 4 B depth = 2.3 MB per decoded 320×240 view;
// appearance_map_test.cc measures the effect on surprise against all-float storage. All but the
// views used last are held compact (ViewBasedMapOptions::storage, about 7.4 B/pixel): 200 views
// take about 143 MB (docs/map_storage.md).
// Pixels no reference view covers get the initial prior (α=1, β=1, τ=0, σ=5) for the update, and
// no surprise (NaN): there is nothing to be surprised against.
#pragma once

#include <Eigen/Geometry>
#include <limits>
#include <memory>
#include <opencv2/core.hpp>
#include <vector>

#include "core/eigen_abi.h"
#include "maps/appearance/prior_alignment.h"
#include "maps/appearance/view_based_map.h"
#include "maps/stats/normal_gamma_batch.h"

namespace novelty::appearance {

struct AppearanceMapOptions {
  stats::SurpriseBatchOptions surprise;                      ///< f, ξ, σ_min, σ_max; KL options
  stats::NormalGamma initial_prior = stats::InitialPrior();  ///< 4.3: α=1, β=1, τ=0, σ=5
  bool half_precision = true;  ///< α, β, σ as CV_16F (τ always CV_32F); false: all CV_32F
  /// Standard deviation s (px) of where the warp puts a scene point: pose, depth and resampling
  /// error. A warped prior's variance is at least (s·|∇τ|)² per channel (warp_error_floor.h).
  /// With learn_warp_sigma, s is the larger of this and the learnt value; 0 and no learning =
  /// the thesis's prior as interpolated.
  double warp_sigma_px = 0.0;
  /// Learn s from the frames: each warped frame measures the shift its edges show against the
  /// prior (MeasureWarpSigma), and s² follows it with the forgetting factor f (eq. 4.10's f, a
  /// memory of about five frames); a frame's floor uses what the frames before it taught.
  bool learn_warp_sigma = false;
  /// Beyond the thesis: predict the prior again at the pose corrected by the small rotation that
  /// aligns the frame with it (prior_alignment.h), so that a pose error does not shift the prior
  /// against the frame. The frame is stored at the pose given (Insert). For pose sources whose
  /// error is mostly rotation (the LED tracker).
  bool align_to_prior = false;
  PriorAlignmentOptions alignment;
  /// Also compute predictive novelty (AppearanceProducts::predictive), the basis of a fixed
  /// camera's foreground mask. Off by default: on the AVX-512 host it adds about 0.35 ms to a
  /// static camera's 0.5 ms frame (BM_ForegroundStaticCamera) and 0.5–1 ms to seven views.
  bool predictive_novelty = false;
  /// With predictive_novelty: where a pixel's predictive novelty exceeds this (nats), the map
  /// keeps its prior there instead of learning the frame — a fixed camera's update policy, so
  /// that a person standing still is not absorbed into the background at once (the map adapts
  /// to a changed pixel within a frame otherwise, eq. 4.8). Infinite: learn everywhere (thesis).
  double hold_above_nats = std::numeric_limits<double>::infinity();
  /// With hold_above_nats: a pixel held this many frames in a row learns again (0: held as long
  /// as it stays novel). What stays that long is the new background — an exposure step, a
  /// window gone to white, a parked object. Counted per image pixel, for a fixed camera.
  int max_hold_frames = 0;
  ViewBasedMapOptions views;
};

struct AppearanceProducts {
  cv::Mat surprise;      ///< CV_32FC1, S = S_Y + S_Cb + S_Cr (eq. 4.21); NaN where not covered
  cv::Mat expected_rgb;  ///< CV_8UC3, the prior's τ in RGB (what the map expects to see)
  cv::Mat uncertainty;   ///< CV_32FC1, Σβ0 of the prior (fig. 4.4d); NaN where not covered
  /// CV_32FC1, predictive novelty −ln p(x | prior) summed over Y, Cb, Cr (nats;
  /// stats/predictive_novelty.h): how unexpected the frame is, where surprise says how much it
  /// changes the map. NaN where not covered; empty unless options.predictive_novelty.
  cv::Mat predictive;
  cv::Mat valid;  ///< CV_8UC1, covered by the map
  /// CV_32FC1, the depth (m) of the surface the map expects at each pixel, 0 where it expects
  /// none (Prediction::depth); only with set_predict_depth(true), else empty.
  cv::Mat expected_depth;
  /// CV_32FC2, per pixel the nearest and the farthest depth over the views that cover it
  /// (Prediction::depth_span); with expected_depth.
  cv::Mat expected_depth_span;
  double warp_sigma_px = 0.0;  ///< s of the prior's floor in this frame (0: none)
  /// align_to_prior: the rotation ω applied (camera frame, rad; zero if none) and the pose the
  /// prior was predicted at, T_world_cam·R(ω): the frame's pose relative to the map's views.
  Eigen::Vector3d aligned_rotation = Eigen::Vector3d::Zero();
  Eigen::Isometry3d T_world_cam = Eigen::Isometry3d::Identity();
  std::vector<int> selected;
  ViewBasedMap::UpdateResult update;
};

class AppearanceMap {
 public:
  explicit AppearanceMap(const AppearanceMapOptions& options = {});
  ~AppearanceMap();

  /// Processes one frame: rgb CV_8UC3 (R, G, B) and depth CV_32FC1 (m) of `camera`'s size, pose
  /// T_world_cam. Throws std::invalid_argument naming the problem (sizes, types, pose); the map
  /// is then unchanged.
  AppearanceProducts Insert(const cv::Mat& rgb, const cv::Mat& depth,
                            const core::PinholeCamera& camera,
                            const Eigen::Isometry3d& T_world_cam);

  const views::ReferenceViewStore& store() const { return map_.store(); }
  const AppearanceMapOptions& options() const { return options_; }
  /// Whether Insert also gives the expected depth (AppearanceProducts::expected_depth), for a
  /// consumer that tells added from removed objects (objects/change_kind.h). Not an option of
  /// the map and not saved: whoever reads the product asks for it.
  void set_predict_depth(bool on) { predict_depth_ = on; }
  bool predict_depth() const { return predict_depth_; }
  /// Throws std::invalid_argument naming the view and plane unless every view holds valid
  /// parameters: α, β, σ finite and > 0, τ finite (for maps read from files).
  void CheckStoredPlanes() const;
  /// The reference views and their anchors, for saving and loading a map.
  const ViewBasedMap& view_map() const { return map_; }
  ViewBasedMap& view_map() { return map_; }

  /// Channel layout of the working parameter image (stored as "ab_sigma": α, β×3, σ×3 and
  /// "tau": τ×3).
  enum Channel { kAlpha = 0, kBeta = 1, kTau = 4, kSigma = 7, kChannels = 10 };

 private:
  // learn_warp_sigma: the frame's measured shift (its Y against the prior τ) into the learnt s².
  void LearnWarpSigma(const cv::Mat& observed_y, const cv::Mat& tau);

  AppearanceMapOptions options_;
  ViewBasedMap map_;
  // s² learnt so far (learn_warp_sigma). Not saved with the map: a loaded map learns it again
  // within a few frames, and a different pose source may follow.
  double learnt_warp_variance_ = 0.0;
  bool predict_depth_ = false;
  // max_hold_frames: per pixel the frames held in a row (empty until needed; not saved).
  cv::Mat held_frames_;
  cv::Mat HeldFrames(int rows, int cols);
  // A frame runs in row tiles on all cores (appearance_map.cc): each tile converts its rows of
  // the frame and of the prior into small planes that stay in cache through the kernel, and
  // writes its rows of the products and of the posterior to be stored, always new images.
  struct TileWorkPool;  // the tiles' working planes, kept between frames
  std::unique_ptr<TileWorkPool> tile_work_;
};

/// Throws std::invalid_argument unless rgb is CV_8UC3 and depth CV_32FC1, both of the camera's
/// size, and the pose is rigid. `what` names the caller.
void CheckFrame(const cv::Mat& rgb, const cv::Mat& depth, const core::PinholeCamera& camera,
                const Eigen::Isometry3d& T_world_cam, const char* what);

}  // namespace novelty::appearance
