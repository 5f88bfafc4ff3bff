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
#include <memory>
#include <opencv2/core.hpp>
#include <string>
#include <vector>

#include "core/eigen_abi.h"
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
  /// How the views are held: compact (plane_codec.h) but for the 12 used last, which leaves
  /// room for the 7 a prediction selects and the views around them as the camera moves on.
  /// 200 appearance-map views at 320×240 take about 143 MB in memory instead of 461 MB
  /// (docs/map_storage.md).
  views::ReferenceViewStoreOptions storage{12, {}};
};

/// What a view-based map predicts at one viewpoint: the selected views and, per requested plane,
/// the values blended from them. A value that owns what its blend needs (the warps, the views'
/// planes, the weights), so that whoever uses the prior can blend it where it uses it, a few rows
/// at a time (BlendRows): a caller that works through a frame in row tiles then finds each tile's
/// prior in cache. The planes of a view that a later Update replaces stay alive as long as the
/// prediction does.
class Prediction {
 public:
  std::vector<int> selected;  ///< views used, best for the central ray first
  /// Per requested plane: CV_32FC(n), NaN where no view covers. A camera at a view's pose (a
  /// static camera) gets that view's own planes, shared and in their stored depth (half floats
  /// possibly): read them, never write into them. Rows hold nothing until blended, unless
  /// complete().
  std::vector<cv::Mat> value;
  cv::Mat valid;        ///< CV_8UC1, 255 where a view covers; as `value`, filled by BlendRows
  bool warped = false;  ///< views were warped (not an empty map, not a static camera)
  /// If asked for (`with_depth`): CV_32FC1, per pixel the depth (+Z, m) of the surface the map
  /// predicts there — that of the first selected view (best for the central ray first) whose
  /// warp covers the pixel; 0 where none does. Complete at once, blended or not.
  cv::Mat depth;
  /// With `depth`: CV_32FC2, per pixel the nearest and the farthest depth over the selected
  /// views whose warps cover it (0, 0 where none does; both `depth` for a static camera).
  cv::Mat depth_span;

  /// True when nothing is left to blend (an empty map, a static camera, or a Predict).
  bool complete() const { return blend_ == nullptr; }
  /// Blends rows `rows` of every plane and of `valid`, on the calling thread; threads may blend
  /// different rows at once. Nothing when complete().
  void BlendRows(const cv::Range& rows) const;

 private:
  friend class ViewBasedMap;
  struct Blend;  // the warps, the selected views' planes, the weights, the result images
  std::shared_ptr<Blend> blend_;
};

class ViewBasedMap {
 public:
  explicit ViewBasedMap(const ViewBasedMapOptions& options = {});
  ~ViewBasedMap();
  const ViewBasedMapOptions& options() const { return options_; }

  /// The planes `names` (with their channel counts) predicted at `T_world_cam`, complete: one
  /// warp per selected view serves every plane. An empty map predicts nothing: all invalid.
  Prediction Predict(const core::PinholeCamera& camera, const Eigen::Isometry3d& T_world_cam,
                     const std::vector<std::pair<std::string, int>>& names,
                     bool with_depth = false);
  /// As Predict, but the prediction is returned with its blend still to do (Prediction::
  /// BlendRows), unless it needs none. The map reuses the previous prediction's buffers when
  /// its caller has let it go.
  Prediction PredictDeferred(const core::PinholeCamera& camera,
                             const Eigen::Isometry3d& T_world_cam,
                             const std::vector<std::pair<std::string, int>>& names,
                             bool with_depth = false);

  /// The mesh plan (mesh_plan.h) this map's warps use for `depth`: a caller may make it for the
  /// frame it is about to Update with, beside other work, instead of the next warp making it.
  views::MeshPlan PlanMesh(const cv::Mat& depth) const;

  struct UpdateResult {
    bool added = false;
    int view = -1;  ///< index of the view added or replaced
  };
  /// Applies the update policy with the frame's payload planes, depth and pose. The map keeps
  /// `depth` and the payload planes as given, sharing their buffers: pass images nobody writes to
  /// afterwards (a copy of a caller's depth, made where it is cheapest). `plan`: PlanMesh(depth)
  /// if the caller made it; otherwise (or if it does not fit) it is made at the view's next warp.
  UpdateResult Update(const core::PinholeCamera& camera, const Eigen::Isometry3d& T_world_cam,
                      cv::Mat depth, std::map<std::string, cv::Mat> payload,
                      const std::vector<int>& selected, views::MeshPlan plan = {});
  /// Off: Update changes nothing (no view added, none replaced), so that frames are judged
  /// against the map as it was — learnt from one pass, judging the next. On by default.
  void set_learning(bool on) { learning_ = on; }
  bool learning() const { return learning_; }

  const views::ReferenceViewStore& store() const { return store_; }
  /// The pose of each view when it was created (same order as the store).
  const std::vector<Eigen::Isometry3d>& anchors() const { return anchors_; }
  /// Replaces the whole content (for loading a saved map). `encoded`: the views as the file held
  /// them encoded (EncodeView), kept by a compact map; empty: encoded as needed. Throws
  /// std::invalid_argument if the counts differ or a view is invalid; the map is then unchanged.
  void Restore(std::vector<views::ReferenceView> views, std::vector<Eigen::Isometry3d> anchors,
               std::vector<views::EncodedView> encoded = {});

 private:
  ViewBasedMapOptions options_;
  // Keeps the views the store evicts out of the plans too.
  void Trim(const std::vector<int>& keep);

  views::ReferenceViewStore store_;
  std::vector<Eigen::Isometry3d> anchors_;  // pose of each view when it was created
  bool learning_ = true;
  // Per view, its mesh plan for the warper (mesh_plan.h; a byte per pixel): given with it by
  // Update, or else made at its first warp (a static camera replaces its view every frame and
  // never warps it); dropped with the decoded view when the store evicts it.
  std::vector<views::MeshPlan> plans_;
  views::DepthMeshWarper warper_;
  // The last deferred prediction's blend, reused (warp fields and result images written in
  // place) when its caller has let go of it: fresh megabytes every frame cost a tenth of a
  // seven-view frame in page faults.
  std::shared_ptr<Prediction::Blend> last_blend_;
};

}  // namespace novelty::appearance
