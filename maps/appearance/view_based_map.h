// The image-based skeleton shared by the appearance map and the differencing baseline (4.3):
// reference views holding named payload planes; prediction at any viewpoint by view selection,
// depth-mesh warping and blending (ch. 3); and the update policy that keeps the map current:
//   - a frame farther than `new_view_distance` from every view's anchor (the pose where the view
//     was created), or turned more than `new_view_angle` from the nearest anchor, becomes a new
//     reference view (the first pass over a trajectory creates the map). Anchors, not the
//     current poses, decide: a replacement moves a view's pose to the frame's, and measured
//     against current poses a view would be dragged along by every frame near it;
//   - otherwise the frame replaces the best-matching selected view — the one of least cost for
//     the virtual camera's central ray — with its payload, depth and pose. This is how 4.3's "the
//     latest reference parameter image selected" is read here: it keeps every region of the map
//     represented by its closest, freshest view.
// A camera exactly at a reference view's pose (a static camera) is predicted from that view's
// pixels without warping.
#pragma once

#include <Eigen/Geometry>
#include <map>
#include <opencv2/core.hpp>
#include <string>
#include <vector>

#include "maps/views/depth_mesh_warper.h"
#include "maps/views/reference_view_store.h"
#include "maps/views/view_blender.h"
#include "maps/views/view_selection.h"

namespace novelty::appearance {

struct ViewBasedMapOptions {
  /// A frame at least this far (m) from every reference view becomes a new view. 8 mm makes every
  /// frame of the first run of 4.3 a view (frames 13 mm apart on the 1.95 m arc Q1 → Q2: 151
  /// views; the thesis's 200 would need frames 10 mm apart).
  double new_view_distance = 0.008;
  /// … or turned at least this much (rad) from the nearest view's optical axis (5°).
  double new_view_angle = 5.0 * M_PI / 180.0;
  views::ViewSelectionOptions selection;
  views::WarpOptions warp;
  views::BlendOptions blend;  ///< the blend view synthesis uses (view_blender.h defaults)
};

class ViewBasedMap {
 public:
  explicit ViewBasedMap(const ViewBasedMapOptions& options = {});

  struct Prediction {
    std::vector<int> selected;  ///< views used, best for the central ray first
    /// Per requested plane: CV_32FC(n), NaN where no view covers. A camera at a view's pose (a
    /// static camera) gets that view's own planes, shared and in their stored depth (half floats
    /// possibly): read them, never write into them.
    std::vector<cv::Mat> value;
    cv::Mat valid;        ///< CV_8UC1
    bool warped = false;  ///< views were warped (not an empty map, not a static camera)
  };
  /// The planes `names` (with their channel counts) predicted at `T_world_cam`: one warp per
  /// selected view serves every plane. An empty map predicts nothing: all invalid.
  Prediction Predict(const views::PinholeCamera& camera, const Eigen::Isometry3d& T_world_cam,
                     const std::vector<std::pair<std::string, int>>& names);
  /// As Predict, but the caller blends the planes, rows at a time (BlendRows), where it uses
  /// them — a caller that works through the frame in row tiles then finds each tile's prior in
  /// cache: the value and valid images are sized but hold nothing until their rows are blended.
  /// A prediction that needs no blend (an empty map, a static camera) comes complete.
  Prediction PredictDeferred(const views::PinholeCamera& camera,
                             const Eigen::Isometry3d& T_world_cam,
                             const std::vector<std::pair<std::string, int>>& names);
  /// Blends rows `rows` of every plane of the last PredictDeferred's prediction (and of its valid
  /// image) on the calling thread; threads may blend different rows at once. Nothing when that
  /// prediction came complete.
  void BlendRows(const cv::Range& rows);

  struct UpdateResult {
    bool added = false;
    int view = -1;  ///< index of the view added or replaced
  };
  /// Applies the update policy with the frame's payload planes, depth and pose. The map keeps
  /// `depth` and the payload planes as given, sharing their buffers: pass images nobody writes to
  /// afterwards (a copy of a caller's depth, made where it is cheapest). `plan`: the mesh plan of
  /// `depth` (views::MeshPlanFor with the options' warp) if the caller made one, beside other
  /// work; otherwise (or if it was made for other options) it is made at the view's next warp.
  UpdateResult Update(const views::PinholeCamera& camera, const Eigen::Isometry3d& T_world_cam,
                      cv::Mat depth, std::map<std::string, cv::Mat> payload,
                      const std::vector<int>& selected, views::MeshPlan plan = {});

  const views::ReferenceViewStore& store() const { return store_; }
  /// The pose of each view when it was created (same order as the store).
  const std::vector<Eigen::Isometry3d>& anchors() const { return anchors_; }
  /// Replaces the whole content (for loading a saved map). Throws std::invalid_argument if the
  /// counts differ or a view is invalid; the map is then unchanged.
  void Restore(std::vector<views::ReferenceView> views, std::vector<Eigen::Isometry3d> anchors);

 private:
  ViewBasedMapOptions options_;
  views::ReferenceViewStore store_;
  std::vector<Eigen::Isometry3d> anchors_;  // pose of each view when it was created
  // Per view, its mesh plan for the warper (mesh_plan.h; a byte per pixel): made when a view is
  // loaded, given with it by Update, or else made at its first warp (a static camera replaces
  // its view every frame and never warps it).
  std::vector<views::MeshPlan> plans_;
  views::DepthMeshWarper warper_;
  std::vector<views::WarpField> warps_;  // reused from frame to frame
  // The last prediction's blend: the options' with the selected views' weights (ray counts).
  views::BlendOptions blend_;
  // Per requested plane, the blend's images, shared with the Prediction handed out and written
  // in place next frame when the caller has let it go (PrepareBlend): fresh megabytes every frame
  // cost a tenth of a seven-view frame in page faults.
  std::vector<views::BlendResult> blended_;
  // Per requested plane, the selected views' planes still to be blended (PredictDeferred). Held
  // until the next prediction, so a view that Update replaces keeps its old planes (2 MB for the
  // appearance map) one frame longer.
  std::vector<std::vector<cv::Mat>> pending_;
};

}  // namespace novelty::appearance
