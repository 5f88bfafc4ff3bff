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

#include <cstdio>
#include <exception>
#include <filesystem>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <optional>
#include <sstream>

#include "apps/command_line.h"
#include "apps/shell/output_folder.h"
#include "apps/shell/program.h"
#include "apps/shell/progress.h"
#include "core/range_check.h"
#include "core/write_rgb_image.h"
#include "eval/psnr.h"
#include "experiments/view_synthesis_run.h"
#include "maps/views/depth_mesh_warper.h"
#include "maps/views/view_blender.h"
#include "maps/views/view_synthesis.h"
#include "sensors/dataset/rgbd_folder_reader.h"

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
  if (rawlog.isSet()) {
    if (!truth.isSet()) throw std::invalid_argument("--rawlog needs --groundtruth DIR");
    experiments::ViewSynthesisRunOptions o;
    o.rawlog = rawlog.getValue();
    o.groundtruth = truth.getValue();
    o.every = every.getValue();
    o.synthesis = options;
    o.status = [](const std::string& line) {
      std::fprintf(stderr, "novelty-synth: %s\n", line.c_str());
    };
    std::optional<apps::Progress> progress;
    o.progress = [&](int done, int total) {
      if (!progress) progress.emplace("[novelty-synth] virtual views", total);
      progress->Update(done);
    };
    apps::OutputFolder folder("novelty-synth", out.getValue(), {o.rawlog, o.groundtruth});
    const experiments::ViewSynthesisRunResult r = experiments::RunViewSynthesis(o, folder.path());
    if (progress) progress->Finish();
    folder.Commit();
    std::printf(
        "%d virtual views from %d reference views, mean PSNR=%.2f dB over covered pixels, mean "
        "coverage=%.4f, %d frames skipped\n  frames: %s/frames.csv\n",
        r.virtual_views, r.reference_views, r.mean_psnr_db, r.mean_coverage, r.skipped,
        folder.final_path().c_str());
    return apps::kExitOk;
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
  views::DepthMeshWarper warper(wo, views::WarpOutputsFor(bo));
  return FolderMode(frames.getValue(), cam, scale.getValue(), target.getValue(), sources.getValue(),
                    out.getValue(), warper, options);
}

}  // namespace

int main(int argc, char** argv) {
  return novelty::apps::RunProgram("novelty-synth", [&] { return Run(argc, argv); });
}
