// What a reference view's depth mesh draws, whatever the virtual camera: which quads are drawn
// on their own and which planar runs as one polygon each (planar_blocks.h). It depends on the
// view's depth and the block options only, so a caller whose views stay the same between frames
// (a map's reference views) keeps one per view and the warper does not redo it every frame — a
// pass over the depth and the block flags plus a cleared byte per quad, about a tenth of a warp.
#pragma once

#include <cstddef>
#include <cstdint>
#include <opencv2/core.hpp>
#include <vector>

namespace novelty::views {

struct MeshPlan {
  int cols = 0, rows = 0;         ///< the depth map's size (0 × 0: no plan yet)
  int planar_block = 0;           ///< the block size it was made for (0: no blocks)
  double planar_tolerance = 0.0;  ///< and the blocks' tolerance
  /// Per quad, indexed by its top-left vertex r·cols + u: 0 where the quad is drawn on its own,
  /// −1 where a planar run draws it or a vertex has no depth (0, negative or not finite). The
  /// last column and row (no quad there) and kPadding bytes after them, for sixteen-wide loads,
  /// hold −1 too. Memory: one byte per pixel (75 KiB at 320×240).
  std::vector<int8_t> skip;
  /// The planar runs, each a rectangle of quads drawn as one polygon.
  std::vector<cv::Rect> runs;
  static constexpr std::size_t kPadding = 64;

  /// Whether the plan was made for a depth map of this size with these block options.
  bool Fits(cv::Size depth_size, int block, double tolerance) const;
};

/// The plan of `depth` (CV_32FC1) with blocks of `planar_block` × `planar_block` quads within
/// `planar_tolerance` (FindPlanarBlocks; 0 = no blocks): a block's quads are skipped but its
/// outer row or column towards a neighbouring block that is not planar, which is drawn as well
/// so that no crack opens between the block's straight edge and the neighbour's vertices (at the
/// image's border there is no neighbour). Throws std::invalid_argument unless depth is CV_32FC1.
MeshPlan PlanMesh(const cv::Mat& depth, int planar_block, double planar_tolerance);

}  // namespace novelty::views
