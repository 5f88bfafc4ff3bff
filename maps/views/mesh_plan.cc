#include "maps/views/mesh_plan.h"

#include <algorithm>
#include <stdexcept>

#include "core/lanes.h"
#include "maps/views/planar_blocks.h"

namespace novelty::views {

namespace {

using core::lanes::F16;
using core::lanes::I16;
using core::lanes::kLanes;

// Marks the quads the planar blocks draw — all of a block's, except its outer row or column
// towards a neighbour that is not planar — and collects the runs of blocks on one plane.
void MarkPlanarBlocks(const cv::Mat& flags, int size, MeshPlan& plan) {
  const int w = plan.cols, h = plan.rows;
  // Whether a neighbour's quads are drawn apart from its block: it exists and is not planar.
  auto apart = [&](int bx, int by) {
    return bx >= 0 && by >= 0 && bx < flags.cols && by < flags.rows &&
           flags.at<uchar>(by, bx) == kNotPlanar;
  };
  for (int by = 0; by < flags.rows; ++by) {
    bool open = false;  // the last run continues into the next block
    for (int bx = 0; bx < flags.cols; ++bx) {
      const uchar flag = flags.at<uchar>(by, bx);
      if (flag == kNotPlanar) {
        open = false;
        continue;
      }
      const cv::Rect b = PlanarBlockRect(bx, by, w, h, size);
      if (open) {
        plan.runs.back() |= b;
      } else {
        plan.runs.push_back(b);
      }
      open = flag == kPlanarRunContinues;
      const int qu0 = apart(bx - 1, by) ? 1 : 0, qu1 = b.width - (apart(bx + 1, by) ? 1 : 0);
      const int qr0 = apart(bx, by - 1) ? 1 : 0, qr1 = b.height - (apart(bx, by + 1) ? 1 : 0);
      for (int r = qr0; r < qr1; ++r) {
        int8_t* skip = &plan.skip[std::size_t(b.y + r) * w + b.x];
        std::fill(skip + qu0, skip + qu1, -1);
      }
    }
  }
}

// Marks the quads with a vertex without depth, sixteen at a time: no surface there.
void SkipQuadsWithoutDepth(const cv::Mat& depth, MeshPlan& plan) {
  const int w = depth.cols;
  const F16 lane = core::lanes::Iota();
  for (int r = 0; r + 1 < depth.rows; ++r) {
    const float *d0 = depth.ptr<float>(r), *d1 = depth.ptr<float>(r + 1);
    for (int u = 0; u + 1 < w; u += kLanes) {
      const I16 quads = lane < float(w - 1 - u);  // quads u … w − 2 of this group
      I16 with_depth = quads;
      for (const float* p : {d0 + u, d0 + u + 1, d1 + u, d1 + u + 1}) {
        const F16 z = core::lanes::LoadMasked(p, quads);
        with_depth &= (z > 0.0f) & (z < 1e30f);
      }
      const I16 without = quads & ~with_depth;
      if (!core::lanes::Any(without)) continue;
      int8_t* skip = &plan.skip[std::size_t(r) * w + u];  // (bytes past the row: unchanged)
      core::lanes::StoreMaskBytes(reinterpret_cast<uint8_t*>(skip),
                                  (core::lanes::LoadBytes(skip) != 0) | without);
    }
  }
}

}  // namespace

bool MeshPlan::Fits(cv::Size depth_size, int block, double tolerance) const {
  return cols == depth_size.width && rows == depth_size.height &&
         planar_block == std::max(0, block) && (block <= 0 || planar_tolerance == tolerance);
}

MeshPlan PlanMesh(const cv::Mat& depth, int planar_block, double planar_tolerance) {
  if (depth.type() != CV_32FC1) {
    throw std::invalid_argument("PlanMesh: depth must be CV_32FC1");
  }
  MeshPlan plan;
  plan.cols = depth.cols;
  plan.rows = depth.rows;
  plan.planar_block = std::max(0, planar_block);
  plan.planar_tolerance = planar_tolerance;
  // Only real quads (not the last column or row, nor the padding) may be drawn: groups of
  // sixteen that reach past a row's last quad then cost nothing (mesh_plan.h).
  plan.skip.assign(depth.total() + MeshPlan::kPadding, -1);
  for (int r = 0; r + 1 < depth.rows; ++r) {
    std::fill_n(plan.skip.begin() + std::ptrdiff_t(r) * depth.cols, depth.cols - 1, int8_t{0});
  }
  if (plan.planar_block > 0) {
    MarkPlanarBlocks(FindPlanarBlocks(depth, plan.planar_block, planar_tolerance),
                     plan.planar_block, plan);
  }
  SkipQuadsWithoutDepth(depth, plan);
  return plan;
}

}  // namespace novelty::views
