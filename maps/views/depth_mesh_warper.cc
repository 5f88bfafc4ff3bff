#include "maps/views/depth_mesh_warper.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <functional>
#include <limits>
#include <memory>
#include <opencv2/core/utility.hpp>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "core/rigid_pose.h"
#include "maps/views/block_rasteriser.h"
#include "maps/views/mesh_vertices.h"
#include "maps/views/quad_rasteriser.h"
#include "maps/views/view_angles.h"
#include "maps/views/warp_target.h"

namespace novelty::views {

using namespace mesh;  // Vertices, Target, the rasterisers (maps/views/mesh_*.h, *_rasteriser.h)

MeshPlan MeshPlanFor(const cv::Mat& depth, const WarpOptions& options) {
  return PlanMesh(depth, options.planar_block, options.planar_tolerance);
}

struct DepthMeshWarper::Scratch {
  Vertices vertices;
  // The first target's z-buffer (inverse depth): all zeros between warps — Finalise clears what
  // it reads — so no warp clears it whole, and it stays in the cache of the core that warps.
  std::vector<float> zbuffer;
  bool zbuffer_dirty = false;        // a warp stopped between drawing and Finalise
  std::vector<TargetBuffers> extra;  // threads 1… of a view split between threads
  MeshPlan plan;                     // the plan of a view warped without a fitting one
};

namespace {

// The first target: the scratch's z-buffer (cleared whole only after a warp that did not finish)
// and the field's planes (its depth, if asked, is written by Finalise).
Target FieldTarget(WarpField& field, std::vector<float>& zbuffer, bool& zbuffer_dirty, int width,
                   int height, const WarpOutputs& o) {
  const std::size_t n = std::size_t(width) * height;
  if (zbuffer.size() != n || zbuffer_dirty) zbuffer.assign(n, 0.0f);
  zbuffer_dirty = true;
  field.map.create(height, width, CV_32FC2);
  if (o.depth) {
    field.depth.create(height, width, CV_32FC1);
  } else {
    field.depth.release();
  }
  const bool with_source_depth = o.source_depth;
  if (with_source_depth) {
    field.source_depth.create(height, width, CV_32FC1);
  } else {
    field.source_depth.release();
  }
  return {zbuffer.data(), with_source_depth ? field.source_depth.ptr<float>() : nullptr,
          field.map.ptr<float>(), width, height};
}

}  // namespace

DepthMeshWarper::DepthMeshWarper(const WarpOptions& options, const WarpOutputs& outputs)
    : options_(options), outputs_(outputs), scratch_(std::make_unique<Scratch>()) {
  outputs_.depth |= outputs_.view_angles;  // the view angles are found from the depth
}
DepthMeshWarper::~DepthMeshWarper() = default;

void DepthMeshWarper::set_outputs(const WarpOutputs& outputs) {
  outputs_ = outputs;
  outputs_.depth |= outputs_.view_angles;
}

void DepthMeshWarper::Warp(const core::PinholeCamera& src, const Eigen::Isometry3d& T_world_src,
                           const cv::Mat& depth, const core::PinholeCamera& dst,
                           const Eigen::Isometry3d& T_world_dst, WarpField& field) {
  WarpWith(*scratch_, ThreadCount(options_.threads), src, T_world_src, depth, nullptr, dst,
           T_world_dst, field);
}

void DepthMeshWarper::WarpMany(const std::vector<SourceView>& sources,
                               const core::PinholeCamera& dst, const Eigen::Isometry3d& T_world_dst,
                               std::vector<WarpField>& fields) {
  fields.resize(sources.size());
  const int threads = ThreadCount(options_.threads);
  if (threads < 2 || sources.size() < 2) {
    for (std::size_t k = 0; k < sources.size(); ++k) {
      WarpWith(*scratch_, threads, *sources[k].camera, *sources[k].T_world_cam, *sources[k].depth,
               sources[k].plan, dst, T_world_dst, fields[k]);
    }
    return;
  }
  // Whole views per thread: no thread waits for another or merges its z-buffer. Each takes the
  // next view not yet taken, so a thread that drew cheap views draws more of them. (Splitting the
  // view left over — seven on two cores — between the threads instead was no faster: the
  // merge and the extra synchronisation cost what the idle core loses.)
  const int workers = std::min(threads, int(sources.size()));
  std::atomic<std::size_t> next{0};
  while (int(worker_scratch_.size()) < workers) {
    worker_scratch_.push_back(std::make_unique<Scratch>());
  }
  std::vector<std::string> errors(static_cast<std::size_t>(workers));
  ParallelBlocks(workers, workers, [&](int w0, int w1) {
    for (int w = w0; w < w1; ++w) {
      try {
        for (std::size_t k = next++; k < sources.size(); k = next++) {
          WarpWith(*worker_scratch_[std::size_t(w)], 1, *sources[k].camera, *sources[k].T_world_cam,
                   *sources[k].depth, sources[k].plan, dst, T_world_dst, fields[k]);
        }
      } catch (const std::exception& e) {
        errors[std::size_t(w)] = e.what();  // rethrown below, not across the thread pool
      }
    }
  });
  for (const std::string& e : errors) {
    if (!e.empty()) throw std::invalid_argument(e);
  }
}

void DepthMeshWarper::WarpWith(Scratch& scratch, int threads, const core::PinholeCamera& src,
                               const Eigen::Isometry3d& T_world_src, const cv::Mat& depth,
                               const MeshPlan* kept_plan, const core::PinholeCamera& dst,
                               const Eigen::Isometry3d& T_world_dst, WarpField& field) const {
  const WarpOptions& o = options_;
  src.Check();
  dst.Check();
  if (!core::IsRigid(T_world_src) || !core::IsRigid(T_world_dst)) {
    throw std::invalid_argument("WarpView: a camera pose is not a rigid transform");
  }
  if (depth.type() != CV_32FC1 || depth.cols != src.width || depth.rows != src.height) {
    throw std::invalid_argument(
        "WarpView: source depth must be CV_32FC1 of the source camera's "
        "size " +
        std::to_string(src.width) + "x" + std::to_string(src.height));
  }
  const Eigen::Isometry3d T_vs = T_world_dst.inverse() * T_world_src;
  Vertices& v = scratch.vertices;
  v.Resize(std::size_t(src.width) * src.height);
  // The caller's plan if it was made for these options (else planned anew).
  const bool kept = kept_plan && kept_plan->Fits(depth.size(), o.planar_block, o.planar_tolerance);
  if (!kept) scratch.plan = MeshPlanFor(depth, o);
  const MeshPlan& plan = kept ? *kept_plan : scratch.plan;
  v.skip = plan.skip.data();
  const std::vector<cv::Rect>& blocks = plan.runs;
  // Only the vertices something draws from: block rows (the runs' corners) whole, other rows where
  // a quad is drawn on its own; a run that cannot be one polygon is drawn quad by quad, so its
  // rows are projected whole as well.
  const VertexProjector project(src, T_vs, depth, dst, o.near_plane, v);
  const int block_size = std::max(1, o.planar_block);
  ParallelBlocks(src.height, threads, [&](int r0, int r1) {
    for (int r = r0; r < r1; ++r)
      project.Row(r, !blocks.empty() && (r % block_size == 0 || r == src.height - 1));
  });
  for (const cv::Rect& b : blocks) {
    if (CornersOf(v, src.width, b).usable) continue;
    for (int r = b.y + 1; r < b.y + b.height; ++r) project.Row(r, true);
  }

  // Threads take blocks of source rows, each with its own target, merged by depth afterwards.
  const int n_threads = std::max(1, std::min(src.height - 1, threads));
  scratch.extra.resize(std::size_t(n_threads - 1));
  std::vector<Target> targets = {
      FieldTarget(field, scratch.zbuffer, scratch.zbuffer_dirty, dst.width, dst.height, outputs_)};
  for (TargetBuffers& b : scratch.extra) {
    targets.push_back(b.Clear(dst.width, dst.height, outputs_.source_depth));
  }
  const float max_ratio = float(1.0 + o.max_relative_depth_jump);
  const int w = src.width;
  ParallelBlocks(n_threads, n_threads, [&](int t0, int t1) {
    for (int ti = t0; ti < t1; ++ti) {
      const Target& view = targets[std::size_t(ti)];
      const int r_begin = (src.height - 1) * ti / n_threads;
      const int r_end = (src.height - 1) * (ti + 1) / n_threads;
      for (const cv::Rect& b : blocks) {
        if (b.y >= r_begin && b.y < r_end) RasteriseBlock(v, w, b, max_ratio, view);
      }
      for (int r = r_begin; r < r_end; ++r) RasteriseRowVectorised(v, w, r, max_ratio, view);
    }
  });
  if (n_threads > 1) Merge(targets, threads);
  field.covered =
      Finalise(targets[0], outputs_.depth ? field.depth.ptr<float>() : nullptr, threads);
  scratch.zbuffer_dirty = false;
  if (outputs_.view_angles) ViewAngles(field.depth, dst, T_vs.translation(), field.cos_angle);
}

WarpField WarpView(const core::PinholeCamera& source_camera,
                   const Eigen::Isometry3d& T_world_source, const cv::Mat& source_depth,
                   const core::PinholeCamera& virtual_camera,
                   const Eigen::Isometry3d& T_world_virtual, const WarpOptions& options,
                   const WarpOutputs& outputs) {
  WarpField field;
  DepthMeshWarper(options, outputs).Warp(source_camera, T_world_source, source_depth, virtual_camera,
                                T_world_virtual, field);
  return field;
}

}  // namespace novelty::views
