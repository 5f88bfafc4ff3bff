#include "maps/views/planar_blocks.h"

#include <algorithm>
#include <cmath>
#include <opencv2/core/utility.hpp>
#include <stdexcept>
#include <string>

#include "core/lanes.h"

namespace novelty::views {
namespace {

using namespace core::lanes;  // F16, I16, Iota, LoadMasked, Any (core/lanes.h)

bool IsPlanar(const cv::Mat& depth, const cv::Rect& block, float tolerance) {
  const int u0 = block.x, v0 = block.y, u1 = block.x + block.width, v1 = block.y + block.height;
  const float z00 = depth.at<float>(v0, u0), z10 = depth.at<float>(v0, u1);
  const float z01 = depth.at<float>(v1, u0);
  if (!(z00 > 0.0f && z10 > 0.0f && z01 > 0.0f)) return false;
  // ŵ(u, v) = w00 + du·(u − u0) + dv·(v − v0)
  const float w00 = 1.0f / z00;
  const float du = (1.0f / z10 - w00) / float(block.width);
  const float dv = (1.0f / z01 - w00) / float(block.height);
  // Each row sixteen pixels at a time.
  const F16 lane = Iota();
  for (int y = 0; y <= block.height; ++y) {
    const float* z = depth.ptr<float>(v0 + y) + u0;
    const float row = w00 + dv * float(y);
    for (int x = 0; x <= block.width; x += kLanes) {
      const I16 in_block = lane < float(block.width + 1 - x);
      const F16 zx = LoadMasked(z + x, in_block);
      const F16 error = zx * (row + du * (lane + float(x))) - 1.0f;
      // Written so that NaN, infinite or non-positive depths fail.
      const I16 ok = (zx > 0.0f) & (error <= tolerance) & (error >= -tolerance);
      if (Any(in_block & ~ok)) return false;
    }
  }
  return true;
}

// Planar blocks [x0, x1) of block row y joined into runs: all of them if their union is planar,
// else each half on its own.
void JoinRuns(const cv::Mat& depth, int size, float tolerance, int y, int x0, int x1, uchar* row) {
  if (x1 - x0 < 2) return;
  const cv::Rect first = PlanarBlockRect(x0, y, depth.cols, depth.rows, size);
  const cv::Rect last = PlanarBlockRect(x1 - 1, y, depth.cols, depth.rows, size);
  if (IsPlanar(depth, first | last, tolerance)) {
    std::fill(row + x0, row + x1 - 1, kPlanarRunContinues);
    return;
  }
  const int mid = (x0 + x1) / 2;
  JoinRuns(depth, size, tolerance, y, x0, mid, row);
  JoinRuns(depth, size, tolerance, y, mid, x1, row);
}

}  // namespace

cv::Size PlanarGrid(int cols, int rows, int size) {
  return {std::max(0, (cols - 1 + size - 1) / size), std::max(0, (rows - 1 + size - 1) / size)};
}

cv::Rect PlanarBlockRect(int bx, int by, int cols, int rows, int size) {
  const int u0 = bx * size, v0 = by * size;
  return {u0, v0, std::min(size, cols - 1 - u0), std::min(size, rows - 1 - v0)};
}

cv::Mat FindPlanarBlocks(const cv::Mat& depth, int size, double tolerance) {
  if (depth.type() != CV_32FC1)
    throw std::invalid_argument("FindPlanarBlocks: depth must be CV_32FC1");
  if (size < 1)
    throw std::invalid_argument("FindPlanarBlocks: block size must be at least 1, got " +
                                std::to_string(size));
  const cv::Size grid = PlanarGrid(depth.cols, depth.rows, size);
  cv::Mat flags(grid, CV_8UC1, cv::Scalar(kNotPlanar));
  // Block rows on all cores: a loaded map plans every view,
  // and a view without a plan is planned at its warp, in the frame's time. (The appearance map
  // plans a frame's depth as one task among its tiles, where this loop runs on that thread.)
  cv::parallel_for_(cv::Range(0, grid.height), [&](const cv::Range& rows) {
    for (int y = rows.start; y < rows.end; ++y) {
      uchar* row = flags.ptr<uchar>(y);
      for (int x = 0; x < grid.width; ++x) {
        if (IsPlanar(depth, PlanarBlockRect(x, y, depth.cols, depth.rows, size), float(tolerance)))
          row[x] = kPlanar;
      }
      for (int x = 0; x < grid.width;) {  // each sequence of planar blocks into runs
        int end = x;
        while (end < grid.width && row[end] == kPlanar) ++end;
        JoinRuns(depth, size, float(tolerance), y, x, end, row);
        x = std::max(end, x + 1);
      }
    }
  });
  return flags;
}

}  // namespace novelty::views
