// Blocks of a depth map whose pixels lie on one plane. A plane seen by a pinhole camera has an
// inverse depth that is affine in the pixel coordinates (n·X = d with X = z·K⁻¹(u, v, 1) gives
// 1/z = n·K⁻¹(u, v, 1)/d), so a block is planar when every pixel's inverse depth matches the
// affine function through three of its corners. The warper draws such a block as one convex
// quadrilateral instead of size² quads of two (depth_mesh_warper.h): the same surface, since the
// mesh vertices inside lie on its plane.
#pragma once

#include <opencv2/core.hpp>

namespace novelty::views {

/// A block's flag: not planar, planar (the last or only block of a run), or planar and on one
/// plane with the block to its right — the warper draws such a run of blocks as one polygon.
constexpr unsigned char kNotPlanar = 0, kPlanar = 255, kPlanarRunContinues = 128;

/// Flags (CV_8UC1: kNotPlanar, kPlanar, kPlanarRunContinues) for blocks of `size`×`size` quads,
/// i.e. (size+1)² pixels sharing their border rows and columns with the neighbours: block (bx, by)
/// covers pixels [bx·size, bx·size + size] × [by·size, by·size + size], clipped to the image — the
/// last block column and row are narrower where size does not divide cols−1 or rows−1
/// (PlanarBlockRect). The grid is PlanarGrid(cols, rows, size). A block is planar when every depth
/// is finite and positive and |z·ŵ − 1| ≤ `tolerance` for the affine inverse depth ŵ through the
/// corners (u0, v0), (u1, v0), (u0, v1) — the relative depth error. Consecutive planar blocks of a
/// block row form a run when all their pixels pass the same test for the plane through the run's
/// corners (the longest such runs, found by halving those that fail). Throws std::invalid_argument
/// unless depth is CV_32FC1 and size ≥ 1.
cv::Mat FindPlanarBlocks(const cv::Mat& depth, int size, double tolerance);

/// The block grid of an image of cols × rows pixels: ⌈(cols−1)/size⌉ × ⌈(rows−1)/size⌉ blocks.
cv::Size PlanarGrid(int cols, int rows, int size);

/// The quads of block (bx, by): x, y = its top-left pixel, width × height quads (size × size but
/// at the image's right and bottom edges).
cv::Rect PlanarBlockRect(int bx, int by, int cols, int rows, int size);

}  // namespace novelty::views
