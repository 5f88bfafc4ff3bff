// Warping a reference view into a virtual camera (3.3.2): the view's depth map becomes a
// triangle mesh in world coordinates — every 2×2 block of pixels two triangles, vertices
// back-projected with their depth (eq. 3.6, 3.9) — which is rasterised into the virtual camera
// with a z-buffer. Triangles across depth discontinuities (vertex depths differing by more than
// `max_relative_depth_jump`) are not drawn, so foreground and background are never joined by
// stretched "rubber" triangles; what only the occluded side could show stays uncovered.
//
// The result is a warp field: for each virtual pixel the source pixel coordinates and the depth
// seen there. It is computed once per frame and applied to any number of planes (view_blender.h).
//
// The parts: mesh_vertices.h (projection of the source pixels), quad_rasteriser.h and
// block_rasteriser.h (drawing quads and planar blocks), warp_target.h (z-buffered targets, one
// per thread, merged), view_angles.h; this file schedules them over views and threads.
#pragma once

#include <Eigen/Geometry>
#include <memory>
#include <opencv2/core.hpp>
#include <vector>

#include "core/eigen_abi.h"
#include "core/pinhole_camera.h"
#include "maps/views/mesh_plan.h"

namespace novelty::views {

struct WarpOptions {
  /// Triangles whose largest vertex depth exceeds the smallest by more than this fraction are
  /// depth discontinuities and are skipped. 0.05 passes a plane seen at 80° from its normal at
  /// 320×240 (neighbouring depths differ by ~2 %) and cuts object silhouettes.
  double max_relative_depth_jump = 0.05;
  /// Surfaces nearer than this to the virtual camera (metres) are clipped.
  double near_plane = 0.05;
  /// Worker threads (blocks of source rows, merged by depth); 0 = OpenCV's thread count.
  int threads = 0;
  /// Blocks of this many × this many quads whose depths lie on one plane (within
  /// `planar_tolerance`, relative depth; planar_blocks.h) are drawn as one convex quadrilateral
  /// with perspective-correct source coordinates instead of 2·size² small triangles, and so is
  /// each run of such blocks in a block row that lie on one plane: walls, floors and table tops
  /// cost a fraction, and their inner vertices are not even projected. Where a block borders a
  /// non-planar one, its quads along that side are drawn as well, so no crack opens between the
  /// block's straight edge and the neighbour's vertices. Quads without depth are skipped.
  /// 0 = every quad on its own.
  int planar_block = 8;
  /// 0.002 moves a vertex by at most 0.2 % of its depth: 0.06 px of parallax for a 20 cm
  /// baseline at 2 m (fx 277).
  double planar_tolerance = 0.002;
};

/// What a warp writes into the field besides the map: what the blend that reads the field needs
/// (view_blender.h: WarpOutputsFor). Not options a user sets: derived from the blend's.
struct WarpOutputs {
  /// WarpField::depth (depth_tolerance, resolution_power and the view angles read it). Without
  /// it the field holds
  /// the map and `covered` only, and the z-buffer stays in the warper.
  bool depth = true;
  /// WarpField::source_depth (resolution_power): 4 bytes per pixel that only that weight reads.
  bool source_depth = false;
  /// WarpField::cos_angle (angle_power); implies `depth`.
  bool view_angles = false;
};

struct WarpField {
  cv::Mat map;    ///< CV_32FC2: source (u, v) for each virtual pixel; (-1, -1) where uncovered
  cv::Mat depth;  ///< CV_32FC1 (WarpOutputs): depth along the virtual camera's +Z; 0 uncovered
  cv::Mat source_depth;  ///< CV_32FC1 (if asked): the same surface's depth in the source view
                         ///< (its resolution there: far sources are blurrier); 0 uncovered
  cv::Mat cos_angle;     ///< CV_32FC1 (if asked): cosine of the angle at the surface point between
                         ///< the rays to the virtual and to the source camera centre; 0 uncovered
  int covered = 0;       ///< number of covered virtual pixels
};

/// One source view for DepthMeshWarper::WarpMany (pointers: the data stay where they are).
struct SourceView {
  const core::PinholeCamera* camera;
  const Eigen::Isometry3d* T_world_cam;
  const cv::Mat* depth;  ///< CV_32FC1, the camera's size
  /// MeshPlanFor(*depth, options) kept by a caller whose views do not change between frames (a
  /// map's reference views); null, or made for other options or another size: planned anew at
  /// each warp.
  const MeshPlan* plan = nullptr;
};

/// The mesh plan a warp with `options` uses for `depth` (PlanMesh with the options' block size
/// and tolerance): what a caller keeps in SourceView::plan.
MeshPlan MeshPlanFor(const cv::Mat& depth, const WarpOptions& options);

/// Warps views one after another, reusing its buffers (and the output field's) from call to
/// call: a robot warps seven views per frame, and fresh megabyte buffers each time cost more in
/// page faults than the rasterisation itself.
class DepthMeshWarper {
 public:
  explicit DepthMeshWarper(const WarpOptions& options = {}, const WarpOutputs& outputs = {});
  const WarpOptions& options() const { return options_; }
  const WarpOutputs& outputs() const { return outputs_; }
  /// What the next warps write (a caller that needs the depth later than the blend options
  /// said, e.g. a map asked for its predicted depth).
  void set_outputs(const WarpOutputs& outputs);
  ~DepthMeshWarper();
  DepthMeshWarper(const DepthMeshWarper&) = delete;
  DepthMeshWarper& operator=(const DepthMeshWarper&) = delete;

  /// Warps the source view (camera, pose, depth CV_32F) into the virtual camera, writing `out`.
  /// A pose that is not rigid or a depth map of the wrong size throws std::invalid_argument; a
  /// source that sees nothing of the virtual view gives an all-uncovered field.
  void Warp(const core::PinholeCamera& source_camera, const Eigen::Isometry3d& T_world_source,
            const cv::Mat& source_depth, const core::PinholeCamera& virtual_camera,
            const Eigen::Isometry3d& T_world_virtual, WarpField& out);

  /// Warps several source views into the same virtual camera, `fields[k]` from `sources[k]`
  /// (resized to match). With more than one thread each thread warps whole views, which scales
  /// better than splitting every view. Errors as Warp.
  void WarpMany(const std::vector<SourceView>& sources, const core::PinholeCamera& virtual_camera,
                const Eigen::Isometry3d& T_world_virtual, std::vector<WarpField>& fields);

 private:
  struct Scratch;
  void WarpWith(Scratch& scratch, int threads, const core::PinholeCamera& source_camera,
                const Eigen::Isometry3d& T_world_source, const cv::Mat& source_depth,
                const MeshPlan* plan, const core::PinholeCamera& virtual_camera,
                const Eigen::Isometry3d& T_world_virtual, WarpField& out) const;
  WarpOptions options_;
  WarpOutputs outputs_;
  std::unique_ptr<Scratch> scratch_;
  std::vector<std::unique_ptr<Scratch>> worker_scratch_;  // one per WarpMany worker
};

/// One warp with a temporary DepthMeshWarper (see there).
WarpField WarpView(const core::PinholeCamera& source_camera,
                   const Eigen::Isometry3d& T_world_source, const cv::Mat& source_depth,
                   const core::PinholeCamera& virtual_camera,
                   const Eigen::Isometry3d& T_world_virtual, const WarpOptions& options = {},
                   const WarpOutputs& outputs = {});

}  // namespace novelty::views
