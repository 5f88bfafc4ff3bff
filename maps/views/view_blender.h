// Blending warped reference data into the virtual view (3.3.2, second pass): each plane is
// sampled through each view's warp field (bilinear, border replicated) and the valid
// contributions are averaged per pixel — the thesis's rule. Pixels that no view covers are
// invalid: NaN in the result and 0 in the mask, never zeros that look like data.
//
// A view covers a pixel where its warp map holds source coordinates (not −1). The kernel runs
// sixteen pixels at a time over all views, summing in registers, and reads every plane in place
// (floats of other depths are converted): 8-bit planes a word per pixel and corner, from three row
// registers where the sixteen pixels' samples lie on two neighbouring rows, from wider windows
// (core/row_windows.h) where they fit those, else gathered; half and float planes of 2–8
// channels (the appearance map's parameters) a pixel at a time with one masked load per corner.
// Speed: view_synthesis_benchmark (BM_Blend*). The kernel's parts are in blend_*.h.
#pragma once

#include <opencv2/core.hpp>
#include <vector>

#include "maps/views/depth_mesh_warper.h"

namespace novelty::views {

struct BlendOptions {
  /// Weight per view (same order as the warps); empty = equal weights (the thesis's average).
  std::vector<double> weights;
  /// > 0: at each pixel only views whose warped depth is within this fraction of the nearest
  /// view's depth contribute, so a view that sees past an occluder (the surface behind it) does
  /// not ghost into the average. 0 = every valid view contributes (the thesis's rule), the
  /// default: on ICL-NUIM (frame 2 from 1, 4, 5) every tolerance of 1–10 % lowered the PSNR at
  /// the same coverage (31.4 → 30.2–30.8 dB), as did a band around the views' median depth.
  double depth_tolerance = 0.0;
  /// > 0: each contribution is weighted per pixel by (z_virtual / z_source)^power, favouring views
  /// that saw the surface from nearer — at higher resolution — than the virtual camera does, over
  /// distant views whose texture is magnified and blurred (needs WarpOutputs::
  /// source_depth). 0 = no such weighting (the thesis).
  double resolution_power = 0.0;
  /// > 0: each contribution is also weighted by (cos φ / cos φ_best)^power, φ the angle between
  /// the rays from the surface point to the virtual and to the source camera, φ_best the least
  /// such angle among the views that cover the pixel (needs WarpOutputs::view_angles):
  /// views that saw the surface from the same direction get more say, which keeps
  /// view-dependent effects (highlights) right. Relative to the best view, so a weighting never
  /// uncovers a pixel that a view covers. 0 = no such weighting (the thesis's average), the
  /// default: the weighting gains little on real data (view_synthesis_data_test.cc, ICL-NUIM) and
  /// nothing along the simulated path, and it takes the appearance map's seven-view frame over
  /// its budget (BM_AppearanceMapSevenViews); docs/appearance.md has the figures.
  double angle_power = 0.0;

  /// The thesis's rule: every covering view counts the same (3.3.2).
  static BlendOptions ThesisAverage() {
    BlendOptions o;
    o.depth_tolerance = 0.0;
    o.angle_power = 0.0;
    return o;
  }
};

struct BlendResult {
  cv::Mat value;  ///< CV_32FC(n) with the planes' channel count; NaN where invalid
  cv::Mat valid;  ///< CV_8UC1, 255 where at least one view contributed
  int covered = 0;
};

/// What warps must write for blending with `blend` — the depth for depth_tolerance and
/// resolution_power, the source depth for resolution_power, the view angles for angle_power — and
/// no depth when nothing reads it (a warp then writes the map only).
WarpOutputs WarpOutputsFor(const BlendOptions& blend);

/// planes[k] is view k's plane (any depth, n channels, the source camera's size). Throws
/// std::invalid_argument when counts, sizes or channel counts disagree.
BlendResult BlendPlanes(const std::vector<WarpField>& warps, const std::vector<cv::Mat>& planes,
                        const BlendOptions& options = {});

/// The same into `out`, whose images are written in place where they already have the result's
/// size and type and nothing else shares them (else allocated anew): a caller that blends every
/// frame keeps one BlendResult and so does not fault in megabytes of fresh pages per frame.
void BlendPlanes(const std::vector<WarpField>& warps, const std::vector<cv::Mat>& planes,
                 const BlendOptions& options, BlendResult& out);

/// The blend in parts, for a caller that works through a frame in row tiles and blends each
/// tile's rows where it uses them (in cache; the appearance map): PrepareBlend checks the input
/// as BlendPlanes and sizes `out` (in place as above; covered = 0), BlendRows then blends rows
/// `rows` of it on the calling thread — threads may blend different rows at once — and returns
/// the pixels covered there. Over all rows the result equals BlendPlanes'. BlendRows throws
/// std::invalid_argument as BlendPlanes, and for rows outside `out` or an `out` not sized for
/// these planes. Planes it must convert (neither 8-bit, half nor float, or not continuous) are
/// converted at each call.
void PrepareBlend(const std::vector<WarpField>& warps, const std::vector<cv::Mat>& planes,
                  const BlendOptions& options, BlendResult& out);
int BlendRows(const std::vector<WarpField>& warps, const std::vector<cv::Mat>& planes,
              const BlendOptions& options, const cv::Range& rows, BlendResult& out);

}  // namespace novelty::views
