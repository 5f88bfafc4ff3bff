// SURF's dominant orientation (Bay et al. 2008, 4.1) and the M-SURF descriptor (Agrawal,
// Konolige & Blas 2008, "CenSurE", 3.1), the variant of SURF the thesis's features (5.1) are.
//
// Orientation: Haar responses (side 4s) at the points of a radius-6s disc sampled every s,
// weighted by a Gaussian of σ = 2s; a window of π/3 slides around the circle in steps of
// 0.15 rad, and the longest sum of the responses within it gives the angle.
//
// Descriptor, in the keypoint's frame (rotated by its orientation, units of s): a 24s × 24s
// square of 4 × 4 sub-regions, each of 9 × 9 samples of Haar responses (side 2s) spaced s, their
// centres 5s apart, so that neighbours share samples — the overlap is M-SURF's answer to SURF's
// boundary effects. The
// responses d_u, d_v (along and across the orientation) are weighted by a Gaussian of σ = 2.5s
// centred on their sub-region; each sub-region contributes (Σd_u, Σd_v, Σ|d_u|, Σ|d_v|) weighted
// by a Gaussian of σ = 1.5 (in sub-regions) centred on the square. 64 values, unit length.
#pragma once

#include <opencv2/core.hpp>

namespace novelty::objects {

/// Orientation (rad, atan2 of the image's y-down axes, −π…π) of a keypoint at `pt` of scale
/// `scale` (px); `integral`: cv::integral of the 0…1 image, CV_64F.
float SurfOrientation(const cv::Mat& integral, cv::Point2f pt, float scale);

/// The 64 M-SURF values of a keypoint at `pt`, scale `scale` (px), orientation `angle` (rad;
/// 0 for upright SURF), into `out` (64 floats), of unit length (all 0 on a flat image).
void MSurfDescriptor(const cv::Mat& integral, cv::Point2f pt, float scale, float angle,
                     float* out);

}  // namespace novelty::objects
