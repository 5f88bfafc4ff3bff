// Each view's say in the blend at a pixel (view_blender.cc): where its warp covers the pixel,
// its weight (ray count, depth tolerance, resolution and view-angle weights relative to the best
// view) and the bilinear footprint it samples. Included by view_blender.cc only.
#pragma once

#include <cstdint>

#include <limits>
#include <type_traits>
#include <vector>

#include "maps/views/blend_lanes.h"
#include "maps/views/blend_sampling.h"
#include "maps/views/depth_mesh_warper.h"
#include "maps/views/view_blender.h"

namespace novelty::views::blend {

using core::lanes::F16;
using core::lanes::I16;
using core::lanes::kLanes;

// The least cosine angle_power weighs (a view seen edge-on or from behind counts as this).
constexpr float kMinCos = 1e-6f;
// Per-pixel bounds of the views' say (LimitsAt).
template <typename T>
struct PixelLimits {
  T nearest;   // depth limit of depth_tolerance; +inf without
  T best_cos;  // largest cos(view angle) among the contributing views; 1 without angle_power
};

// Where one view's bilinear samples at pixels [x, x + lanes) of row y read, and with what
// weights: the corners, and per corner the view's weight times the bilinear one (0 where the view
// does not cover the pixel).
template <typename T, typename I, typename M>
struct Footprint {
  M valid;   // the view covers the pixel (and lies within depth_tolerance)
  T weight;  // the view's weight at the pixel, 0 where not valid
  Corners<I> at;
  T w00, w10, w01, w11;
};

// The footprint of `w` at pixels [x, x + lanes) of row y in `p`, within `limits` (LimitsAt).
// Coordinates are clamped to the source image (the border replicated). T = float for one pixel,
// F16 for sixteen.
template <typename T, class Plane>
inline __attribute__((always_inline)) auto FootprintOf(const WarpField& w, const Plane& p,
                                                       float view_weight, const BlendOptions& o,
                                                       const PixelLimits<T>& limits, int y, int x) {
  T u, v;
  LoadMap(w.map.ptr<cv::Vec2f>(y) + x, u, v);
  // The map rows are streamed once per view; fetching ahead hides the misses. Every line the
  // pixels span is fetched: sixteen pixels' (u, v) fill two lines, and fetching only the first
  // left every other line a miss (BM_AppearanceMapSevenViews, docs/performance_history.md).
  // As an address, not a pointer: near the last row it lies past the map, and pointer
  // arithmetic beyond an array is undefined (a prefetch of any address is harmless).
  const std::uintptr_t ahead =
      reinterpret_cast<std::uintptr_t>(w.map.ptr<cv::Vec2f>(y) + x) + 64 * sizeof(cv::Vec2f);
  for (std::size_t b = 0; b < 2 * sizeof(T); b += 64)
    __builtin_prefetch(reinterpret_cast<const void*>(ahead + b));
  // Covered where the map holds source coordinates (uncovered: −1): the depth is read only when
  // an option needs it, which saves a third of what the kernel streams through.
  auto valid = u > -0.5f;
  T d{};
  if (o.depth_tolerance > 0.0 || o.resolution_power > 0.0) {
    d = LoadLane(w.depth.ptr<float>(y) + x, T{});
    valid = valid & (d <= limits.nearest);
  }
  T weight = T{} + view_weight;
  if (o.resolution_power > 0.0) {
    weight *= Pow(d / LoadLane(w.source_depth.ptr<float>(y) + x, T{}), float(o.resolution_power));
  }
  if (o.angle_power > 0.0) {  // relative to the best view: ≤ 1, and 1 for that view
    const T cos_angle = Max(LoadLane(w.cos_angle.ptr<float>(y) + x, T{}), kMinCos);
    weight *= Pow(cos_angle / limits.best_cos, float(o.angle_power));
  }
  weight = Select(valid, weight, T{});
  u = Clamp(u, 0.0f, float(p.cols - 1));
  v = Clamp(v, 0.0f, float(p.rows - 1));
  const auto x0 = ToInt(u), y0 = ToInt(v);  // non-negative: truncation is floor
  const auto x1 = Select(x0 < p.cols - 1, x0 + 1, x0), y1 = Select(y0 < p.rows - 1, y0 + 1, y0);
  const T fx = u - ToFloat(x0), fy = v - ToFloat(y0);
  using I = std::remove_const_t<decltype(x0)>;
  return Footprint<T, I, decltype(valid)>{valid,
                                          weight,
                                          {x0, x1, y0, y1},
                                          weight * (1.0f - fx) * (1.0f - fy),
                                          weight * fx * (1.0f - fy),
                                          weight * (1.0f - fx) * fy,
                                          weight * fx * fy};
}

// What bounds each view's say at pixels [x, x + lanes) of row y, over the views that cover
// them: the depth beyond which views do not contribute (the nearest view's depth stretched by
// depth_tolerance; +inf without), and the largest cosine of the view angle among the views that
// do (angle_power's reference; 1 without). Weighting relative to the best view keeps that
// view's weight at 1: cos^p of an absolute angle underflows to 0 for p = 10⁴ a few degrees off,
// which would uncover a pixel that views cover.
template <typename T>
inline PixelLimits<T> LimitsAt(const std::vector<const WarpField*>& warps, const BlendOptions& o,
                               int y, int x) {
  PixelLimits<T> limits{T{} + std::numeric_limits<float>::infinity(), T{} + 1.0f};
  if (o.depth_tolerance > 0.0) {  // only views within the tolerance of the nearest depth
    for (const WarpField* w : warps) {
      const T d = LoadLane(w->depth.ptr<float>(y) + x, T{});
      limits.nearest = Select((d > 0.0f) & (d < limits.nearest), d, limits.nearest);
    }
    limits.nearest *= float(1.0 + o.depth_tolerance);
  }
  if (o.angle_power > 0.0) {
    T best = T{} + kMinCos;
    for (const WarpField* w : warps) {
      T u, v;
      LoadMap(w->map.ptr<cv::Vec2f>(y) + x, u, v);
      auto counts = u > -0.5f;
      if (o.depth_tolerance > 0.0)
        counts = counts & (LoadLane(w->depth.ptr<float>(y) + x, T{}) <= limits.nearest);
      const T c = LoadLane(w->cos_angle.ptr<float>(y) + x, T{});
      best = Select(counts & (c > best), c, best);
    }
    limits.best_cos = best;
  }
  return limits;
}

}  // namespace novelty::views::blend
