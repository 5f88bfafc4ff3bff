// novelty-synth: view synthesis from reference views with depth (thesis ch. 3).
//
// Folder mode (an RGB-D folder in the ICL-NUIM layout, see sensors/dataset/rgbd_folder_reader.h):
//   novelty-synth --frames DIR --fx FX --fy FY --cx CX --cy CY --depth-scale S
//                 --target N --sources A,B,C --out OUT.png
// synthesises frame N's view from the source frames, writes it (uncovered pixels black) and
// prints "PSNR=<dB> coverage=<fraction>" against the real frame N over the covered pixels.
//
// Rawlog mode (an RGB-D rawlog with ground truth, e.g. from novelty-sim):
//   novelty-synth --rawlog R.rawlog --groundtruth DIR/groundtruth --every K --out OUTDIR
// keeps every K-th frame as a reference view and renders virtual views along the path of the
// other frames (fig. 3.6-3.7): OUTDIR/NNNNNN.png and OUTDIR/frames.csv with, per frame, the time
// the synthesis took, the views selected, the PSNR against the real frame and the coverage.
//
// Blending defaults are views::BlendOptions' (see there for how they were chosen); the thesis's
// plain average is --depth-tolerance 0 --angle-power 0. PSNR is always printed with the coverage
// it was measured over.
#include <tclap/CmdLine.h>

#include <chrono>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <fstream>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <sstream>

#include "apps/command_line.h"
#include "apps/shell/output_folder.h"
#include "apps/shell/program.h"
#include "apps/shell/progress.h"
#include "core/frame_stem.h"
#include "core/range_check.h"
#include "core/write_rgb_image.h"
#include "eval/psnr.h"
#include "eval/skipped_frames.h"
#include "maps/views/depth_mesh_warper.h"
#include "maps/views/reference_view_store.h"
#include "maps/views/view_blender.h"
#include "maps/views/view_selection.h"
#include "maps/views/view_synthesis.h"
#include "sensors/dataset/rgbd_folder_reader.h"
#include "sensors/rawlog/rawlog_frame_reader.h"
#include "sim/output/ground_truth_reader.h"

namespace {

using namespace novelty;

std::vector<int> ParseList(const std::string& text) {
  std::vector<int> out;
  std::stringstream s(text);
  for (std::string item; std::getline(s, item, ',');) {
    try {
      out.push_back(std::stoi(item));
    } catch (const std::exception&) {
      throw std::invalid_argument("--sources: '" + item + "' is not a frame number");
    }
  }
  if (out.empty()) throw std::invalid_argument("--sources: no frame given");
  if (out.size() > 64)  // each is a whole frame in memory
    throw std::invalid_argument("--sources: " + std::to_string(out.size()) + " frames, at most 64");
  return out;
}

int FolderMode(const std::string& dir, const core::PinholeCamera& intrinsics, double depth_scale,
               int target, const std::string& sources, const std::string& out,
               views::DepthMeshWarper& warper, const views::SynthesisOptions& options) {
  const std::vector<int> source_frames = ParseList(sources);  // checked before any reading
  core::PinholeCamera cam = intrinsics;
  const std::string probe_path = dir + "/color/" + std::to_string(target) + ".png";
  const cv::Mat probe = cv::imread(probe_path);
  if (probe.empty()) throw std::runtime_error(probe_path + ": cannot read image");
  cam.width = probe.cols;
  cam.height = probe.rows;
  const sensors::RgbdFolderReader reader(dir, cam, depth_scale);
  const core::Frame truth = reader.Read(target);
  std::vector<views::ReferenceView> refs;
  for (int s : source_frames) refs.push_back(views::ReferenceViewOf(reader.Read(s)));
  std::vector<const views::ReferenceView*> ptrs;
  for (const auto& r : refs) ptrs.push_back(&r);
  const views::SynthesisResult r =
      views::SynthesiseView(warper, ptrs, {}, {}, cam, *truth.T_world_cam, options);
  core::WriteRgbImage(out, r.rgb);
  std::printf("PSNR=%.2f coverage=%.4f\n", eval::Psnr(r.rgb, truth.rgb, r.valid), r.coverage);
  return 0;
}

int RawlogMode(const std::string& rawlog, const std::string& truth_dir, int every,
               const std::string& out_dir, views::DepthMeshWarper& warper,
               const views::SynthesisOptions& options) {
  const auto poses = sim::GroundTruthReader(truth_dir).CameraPoses();
  sensors::RawlogFrameReader reader(rawlog);
  views::ReferenceViewStore store;
  std::vector<core::Frame> path;
  for (core::Frame f; reader.Next(f);) {
    const auto pose = poses.find(f.index);
    if (pose == poses.end()) {
      std::fprintf(stderr, "novelty-synth: %s: frame %d has no ground-truth pose, skipped\n",
                   rawlog.c_str(), f.index);
      continue;
    }
    if (f.index % every == 1) {
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
  if (reader.skipped())
    std::fprintf(stderr, "novelty-synth: %s\n",
                 eval::SkippedFramesSummary(reader.skipped() + store.size() + int(path.size()),
                                            reader.skip_reasons())
                     .c_str());
  if (store.size() == 0) throw std::runtime_error(rawlog + ": no RGB-D frame to use as reference");
  std::filesystem::create_directories(out_dir);
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
  int n = 0;
  apps::Progress progress("[novelty-synth] virtual views", int(path.size()));
  for (const core::Frame& f : path) {
    const Eigen::Isometry3d& pose = poses.at(f.index);
    const auto t0 = std::chrono::steady_clock::now();
    std::vector<const views::ReferenceView*> refs;
    std::vector<const views::MeshPlan*> ref_plans;
    const views::ViewSelection selected =
        views::SelectViewsForRays(ref_poses, f.camera, pose, selection);
    for (int j : selected.views) {
      refs.push_back(&store.view(j));
      ref_plans.push_back(&plans[std::size_t(j)]);
    }
    if (refs.empty()) continue;
    const views::SynthesisResult r = views::SynthesiseView(
        warper, refs, ref_plans, selected.Weights(selection), f.camera, pose, options);
    const double ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    const double psnr = eval::Psnr(r.rgb, f.rgb, r.valid);
    core::WriteRgbImage(out_dir + "/" + core::FrameStem(f.index) + ".png", r.rgb);
    csv << f.index << "," << f.time - t_start << "," << ms << "," << refs.size() << "," << psnr
        << "," << r.coverage << "\n";
    psnr_sum += psnr;
    coverage_sum += r.coverage;
    progress.Update(++n);
  }
  progress.Finish();
  std::printf(
      "%d virtual views from %d reference views, mean PSNR=%.2f dB over covered pixels, "
      "mean coverage=%.4f, %d frames skipped\n  frames: %s/frames.csv\n",
      n, store.size(), n ? psnr_sum / n : 0.0, n ? coverage_sum / n : 0.0, reader.skipped(),
      out_dir.c_str());
  return 0;
}

int Run(int argc, char** argv) {
  novelty::apps::CommandLine cmd(
      "Synthesises camera views from reference views with depth and poses.", "0.1");
  TCLAP::ValueArg<std::string> frames("", "frames", "RGB-D folder (color/, depth/, pose.txt)",
                                      false, "", "DIR", cmd);
  TCLAP::ValueArg<double> fx("", "fx", "Focal length x (pixels)", false, 0, "FX", cmd);
  TCLAP::ValueArg<double> fy("", "fy", "Focal length y (pixels, may be negative)", false, 0, "FY",
                             cmd);
  TCLAP::ValueArg<double> cx("", "cx", "Principal point x", false, 0, "CX", cmd);
  TCLAP::ValueArg<double> cy("", "cy", "Principal point y", false, 0, "CY", cmd);
  TCLAP::ValueArg<double> scale("", "depth-scale", "Depth PNG units per metre", false, 5000, "S",
                                cmd);
  TCLAP::ValueArg<int> target("", "target", "Frame whose view is synthesised", false, 0, "N", cmd);
  TCLAP::ValueArg<std::string> sources("", "sources", "Comma-separated source frames", false, "",
                                       "A,B,C", cmd);
  TCLAP::ValueArg<std::string> rawlog("", "rawlog", "RGB-D rawlog (rawlog mode)", false, "",
                                      "R.rawlog", cmd);
  TCLAP::ValueArg<std::string> truth("", "groundtruth", "Ground-truth folder with poses.csv", false,
                                     "", "DIR", cmd);
  TCLAP::ValueArg<int> every("", "every", "Rawlog mode: every K-th frame is a reference view",
                             false, 4, "K", cmd);
  TCLAP::ValueArg<std::string> out("", "out", "Output PNG (folder mode) or folder (rawlog mode)",
                                   true, "", "OUT", cmd);
  // Defaults are the library's (views::SynthesisOptions), which the appearance map's blend shares.
  const views::SynthesisOptions defaults;
  TCLAP::ValueArg<double> jump("", "max-depth-jump", "Relative depth jump that cuts the mesh",
                               false, defaults.warp.max_relative_depth_jump, "J", cmd);
  TCLAP::ValueArg<double> tolerance("", "depth-tolerance",
                                    "Blend only views within this relative depth of the nearest "
                                    "(0 = every view, the thesis's rule)",
                                    false, defaults.blend.depth_tolerance, "T", cmd);
  TCLAP::ValueArg<double> power("", "resolution-power",
                                "Weight views by (z_virtual/z_source)^P (0 = off)", false,
                                defaults.blend.resolution_power, "P", cmd);
  TCLAP::ValueArg<double> angle("", "angle-power",
                                "Weight views by (cos(angle between viewing rays) / that of the "
                                "pixel's best view)^A (0 = off, the thesis's average)",
                                false, defaults.blend.angle_power, "A", cmd);
  cmd.Parse(argc, argv);
  core::CheckInRange(jump.getValue(), 1e-6, 100, "--max-depth-jump");
  core::CheckInRange(tolerance.getValue(), 0, 100, "--depth-tolerance");
  core::CheckInRange(power.getValue(), 0, 100, "--resolution-power");
  core::CheckInRange(angle.getValue(), 0, 100, "--angle-power");
  core::CheckInRange(scale.getValue(), 1e-3, 1e9, "--depth-scale");
  core::CheckInRange(every.getValue(), 2, 1e6, "--every");
  views::SynthesisOptions options;
  views::WarpOptions& wo = options.warp;
  wo.max_relative_depth_jump = jump.getValue();
  views::BlendOptions& bo = options.blend;
  bo.depth_tolerance = tolerance.getValue();
  bo.resolution_power = power.getValue();
  bo.angle_power = angle.getValue();
  views::DepthMeshWarper warper(wo, views::WarpOutputsFor(bo));
  if (rawlog.isSet()) {
    if (!truth.isSet()) throw std::invalid_argument("--rawlog needs --groundtruth DIR");
    apps::OutputFolder folder("novelty-synth", out.getValue(),
                              {rawlog.getValue(), truth.getValue()});
    const int code = RawlogMode(rawlog.getValue(), truth.getValue(), every.getValue(),
                                folder.path(), warper, options);
    folder.Commit();
    std::printf("  → %s/\n", folder.final_path().c_str());
    return code;
  }
  if (!frames.isSet() || !fx.isSet() || !fy.isSet() || !cx.isSet() || !cy.isSet() ||
      !target.isSet() || !sources.isSet()) {
    throw std::invalid_argument(
        "give either --rawlog R --groundtruth DIR, or --frames DIR with "
        "--fx --fy --cx --cy --target --sources");
  }
  core::PinholeCamera cam;
  cam.fx = fx.getValue();
  cam.fy = fy.getValue();
  cam.cx = cx.getValue();
  cam.cy = cy.getValue();
  apps::CheckOutputFile("--out", out.getValue(), {frames.getValue()}, apps::HasExtension(".png"));
  return FolderMode(frames.getValue(), cam, scale.getValue(), target.getValue(), sources.getValue(),
                    out.getValue(), warper, options);
}

}  // namespace

int main(int argc, char** argv) {
  return novelty::apps::RunProgram("novelty-synth", [&] { return Run(argc, argv); });
}
