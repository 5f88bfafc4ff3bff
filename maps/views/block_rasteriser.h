// Drawing planar blocks of a view's mesh (planar_blocks.h, depth_mesh_warper.h): a planar block or run of blocks (top-left vertex, width × height quads), drawn as the convex
// quadrilateral between its corners, row span by row span. On a plane 1/z is affine on screen,
// and so is A/z for any A linear in 3-D: the source depth z_s and z_s·u_s, z_s·v_s
// (u_s = (fx·X_s + cx·Z_s)/Z_s). Interpolating those and dividing gives exact source coordinates
// across the block, where interpolating u_s itself would bend straight texture lines. A block
// with a corner behind the near plane, or seen edge-on (not convex on screen), is drawn quad by
// quad instead.
#pragma once

#include <opencv2/core.hpp>

#include "maps/views/mesh_vertices.h"
#include "maps/views/warp_target.h"

namespace novelty::views::mesh {

/// A block's corners on screen in order around it (p00, p10, p11, p01) with their attributes
/// 1/z, z_s/z, z_s·u_s/z, z_s·v_s/z, and whether the block can be drawn as one polygon: every
/// corner in front of the near plane, and convex with some area on screen.
struct BlockCorners {
  float x[4], y[4], attr[4][4];
  bool usable = true;
};

BlockCorners CornersOf(const Vertices& v, int w, const cv::Rect& block);

/// Draws the block (a quad at a time where CornersOf says it cannot be one polygon).
void RasteriseBlock(const Vertices& v, int w, const cv::Rect& block, float max_ratio,
                    const Target& t);

}  // namespace novelty::views::mesh
