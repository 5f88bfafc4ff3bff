// Where a warp draws (depth_mesh_warper.h): z-buffered planes per virtual pixel, one set per
// thread that draws part of a view, merged by depth; then the field's markers for uncovered
// pixels. Also the warper's way of running work on OpenCV's thread pool.
#pragma once

#include <cstddef>
#include <functional>
#include <opencv2/core.hpp>
#include <opencv2/core/utility.hpp>
#include <vector>

namespace novelty::views::mesh {

// Runs fn(begin, end) over [0, n) split into `blocks` stripes on OpenCV's persistent thread pool
// (no thread is created per call).
inline void ParallelBlocks(int n, int blocks, const std::function<void(int, int)>& fn) {
  cv::parallel_for_(
      cv::Range(0, n), [&](const cv::Range& r) { fn(r.start, r.end); }, blocks);
}

inline int ThreadCount(int requested) {
  return requested > 0 ? requested : std::max(1, cv::getNumThreads());
}

// What the rasteriser keeps per virtual pixel, in planes so that a span of sixteen pixels is
// z-tested and written with a few vector instructions: inverse depth (the z-buffer, 0 = empty —
// nearer is larger, so no division per pixel), the source depth and the source coordinates. The
// first thread's target writes the field's planes directly (its z-buffer, kept by the warper,
// becomes the field's depth in Finalise), so a view warped on one thread is never copied.
struct Target {
  float* inv_z;
  float* source_depth;  // null: not asked for (WarpOutputs::source_depth)
  float* uv;            // (u, v) interleaved, as WarpField::map
  int width, height;
};

// z-test and write of one pixel.
inline void WritePixel(const Target& t, std::size_t j, float iz, float zs, float u, float v) {
  if (iz <= t.inv_z[j]) return;  // z-test on inverse depth
  t.inv_z[j] = iz;
  if (t.source_depth) t.source_depth[j] = zs;
  t.uv[2 * j] = u;
  t.uv[2 * j + 1] = v;
}

// The buffers of a target other than the field (threads after the first of a split view).
struct TargetBuffers {
  std::vector<float> inv_z, source_depth, uv;
  Target Clear(int width, int height, bool with_source_depth);
};

/// Per virtual pixel, the nearest surface of the other targets into the first, sixteen pixels
/// at a time.
void Merge(const std::vector<Target>& targets, int threads);

/// The z-buffer becomes `depth` if asked (0 where uncovered, not 1/0) and is cleared again;
/// uncovered pixels get the field's markers (map −1, source depth 0). Returns the covered pixels.
int Finalise(const Target& t, float* depth, int threads);

}  // namespace novelty::views::mesh
