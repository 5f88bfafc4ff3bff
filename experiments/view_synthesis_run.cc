#include "experiments/view_synthesis_run.h"

#include <chrono>
#include <fstream>
#include <stdexcept>
#include <vector>

#include "core/frame_stem.h"
#include "core/range_check.h"
#include "core/write_rgb_image.h"
#include "eval/psnr.h"
#include "eval/skipped_frames.h"
#include "maps/views/depth_mesh_warper.h"
#include "maps/views/reference_view_store.h"
#include "maps/views/view_selection.h"
#include "sensors/rawlog/rawlog_frame_reader.h"
#include "sim/output/ground_truth_reader.h"

namespace novelty::experiments {
namespace {

// The rawlog's frames with a true pose: every K-th into the store, the others the path.
void ReadFrames(const ViewSynthesisRunOptions& o, const std::map<int, Eigen::Isometry3d>& poses,
                views::ReferenceViewStore& store, std::vector<core::Frame>& path, int& skipped) {
  sensors::RawlogFrameReader reader(o.rawlog);
  int no_pose = 0;
  for (core::Frame f; reader.Next(f);) {
    const auto pose = poses.find(f.index);
    if (pose == poses.end()) {
      if (o.status)
        o.status(o.rawlog + ": frame " + std::to_string(f.index) +
                 " has no ground-truth pose, skipped");
      ++no_pose;
      continue;
    }
    f.T_world_cam = pose->second;
    if (f.index % o.every == 1) {
      views::ReferenceView v;
      v.camera = f.camera;
      v.T_world_cam = pose->second;
      v.depth = f.depth.clone();
      v.planes["rgb"] = f.rgb.clone();
      store.Add(std::move(v));
    } else {
      path.push_back(f);
      path.back().rgb = f.rgb.clone();
    }
  }
  if (reader.skipped() && o.status)
    o.status(eval::SkippedFramesSummary(reader.skipped() + store.size() + int(path.size()),
                                        reader.skip_reasons()));
  skipped = reader.skipped() + no_pose;
  if (store.size() == 0)
    throw std::runtime_error(o.rawlog + ": no RGB-D frame with a pose to use as reference");
}

}  // namespace

ViewSynthesisRunResult RunViewSynthesis(const ViewSynthesisRunOptions& o,
                                        const std::string& out_dir) {
  core::CheckInRange(o.every, 2, 1e6, "--every");
  const auto poses = sim::GroundTruthReader(o.groundtruth).CameraPoses();
  views::ReferenceViewStore store;
  std::vector<core::Frame> path;
  ViewSynthesisRunResult r;
  ReadFrames(o, poses, store, path, r.skipped);
  r.reference_views = store.size();
  views::DepthMeshWarper warper(o.synthesis.warp, views::WarpOutputsFor(o.synthesis.blend));
  std::ofstream csv(out_dir + "/frames.csv");
  csv << "frame,time_s,synthesis_ms,views,psnr_db,coverage\n";
  const double t_start = path.empty() ? 0.0 : path.front().time;
  const std::vector<Eigen::Isometry3d> ref_poses = store.Poses();
  // Each reference view's mesh plan once, not at every virtual view that warps it.
  std::vector<views::MeshPlan> plans;
  for (int j = 0; j < store.size(); ++j)
    plans.push_back(views::MeshPlanFor(store.view(j).depth, warper.options()));
  const views::ViewSelectionOptions selection;
  double psnr_sum = 0.0, coverage_sum = 0.0;
  for (const core::Frame& f : path) {
    const auto t0 = std::chrono::steady_clock::now();
    const views::ViewSelection selected =
        views::SelectViewsForRays(ref_poses, f.camera, *f.T_world_cam, selection);
    std::vector<const views::ReferenceView*> refs;
    std::vector<const views::MeshPlan*> ref_plans;
    for (int j : selected.views) {
      refs.push_back(&store.view(j));
      ref_plans.push_back(&plans[std::size_t(j)]);
    }
    if (refs.empty()) continue;
    const views::SynthesisResult s =
        views::SynthesiseView(warper, refs, ref_plans, selected.Weights(selection), f.camera,
                              *f.T_world_cam, o.synthesis);
    const double ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    const double psnr = eval::Psnr(s.rgb, f.rgb, s.valid);
    core::WriteRgbImage(out_dir + "/" + core::FrameStem(f.index) + ".png", s.rgb);
    csv << f.index << "," << f.time - t_start << "," << ms << "," << refs.size() << "," << psnr
        << "," << s.coverage << "\n";
    psnr_sum += psnr;
    coverage_sum += s.coverage;
    ++r.virtual_views;
    if (o.progress) o.progress(r.virtual_views, int(path.size()));
  }
  if (r.virtual_views) {
    r.mean_psnr_db = psnr_sum / r.virtual_views;
    r.mean_coverage = coverage_sum / r.virtual_views;
  }
  return r;
}

}  // namespace novelty::experiments
