// Blocks of a depth map whose pixels lie on one plane. A plane seen by a pinhole camera has an
// inverse depth that is affine in the pixel coordinates (n·X = d with X = z·K⁻¹(u, v, 1) gives
// 1/z = n·K⁻¹(u, v, 1)/d), so a block is planar when every pixel's inverse depth matches the
// affine function through three of its corners. The warper draws such a block as one convex
// quadrilateral instead of size² quads of two (depth_mesh_warper.h): the same surface, since the
// mesh vertices inside lie on its plane.
#pragma once

#include <opencv2/core.hpp>

namespace novelty::views {

/// Flags (CV_8UC1, 255 = planar) for blocks of `size`×`size` quads, i.e. (size+1)² pixels sharing
/// their border rows and columns with the neighbours: block (bx, by) covers pixels
/// [bx·size, bx·size + size] × [by·size, by·size + size]. The grid is
/// ⌊(rows−1)/size⌋ × ⌊(cols−1)/size⌋; remaining pixels belong to no block. A block is planar when
/// every depth is finite and positive and |z·ŵ − 1| ≤ `tolerance` for the affine inverse depth ŵ
/// through the corners (u0, v0), (u0+size, v0), (u0, v0+size) — the relative depth error.
/// Throws std::invalid_argument unless depth is CV_32FC1 and size ≥ 1.
cv::Mat FindPlanarBlocks(const cv::Mat& depth, int size, double tolerance);

}  // namespace novelty::views
