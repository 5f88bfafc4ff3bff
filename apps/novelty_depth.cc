// novelty-depth: dense depth from stereo or trinocular images (thesis 3.2).
//
//   novelty-depth IN.rawlog --out OUT.rawlog [--near 0.5] [--far 5] [--hypotheses 64]
//                 [--window 5] [--min-confidence 0] [--groundtruth DIR/groundtruth] [--frames N]
//
// Every CObservationStereoImages or trinocular CObservationImage triple (CAM_CENTER, CAM_LEFT,
// CAM_RIGHT) becomes a CObservation3DRangeScan "STEREO_DEPTH" with the reference camera's colour
// image and the depth from plane sweep + belief propagation (sensors/stereo); every other
// observation (tracker, odometry, …) is copied through in order, so novelty-poses and novelty-run
// take the output as they take an RGB-D rawlog. With --groundtruth (novelty-sim's folder) it
// prints the depth accuracy per frame and overall (textured pixels within 3 %, as the sensors
// issue measures it). A frame that cannot be read is skipped and counted.
#include <tclap/CmdLine.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <optional>

#include "apps/command_line.h"
#include "apps/shell/output_folder.h"
#include "apps/shell/program.h"
#include "apps/shell/progress.h"
#include "core/frame_stem.h"
#include "core/range_check.h"
#include "core/same_file.h"
#include "eval/depth_accuracy.h"
#include "eval/skipped_frames.h"
#include "sensors/rawlog/rawlog_frame_reader.h"
#include "sensors/rawlog/rawlog_output.h"
#include "sensors/rawlog/rig_frame_reader.h"
#include "sensors/stereo/stereo_depth.h"
#include "sim/output/ground_truth_reader.h"

using namespace novelty;

namespace {

int Run(int argc, char** argv) {
  novelty::apps::CommandLine cmd(
      "Depth maps from stereo or trinocular rawlog images (plane sweep + BP).", "0.1");
  TCLAP::UnlabeledValueArg<std::string> in("input", "Input rawlog", true, "", "IN.rawlog", cmd);
  TCLAP::ValueArg<std::string> out("o", "out", "Output rawlog", true, "", "OUT.rawlog", cmd);
  const sensors::StereoDepthOptions defaults;
  TCLAP::ValueArg<double> near("", "near", "Nearest depth hypothesis (m)", false,
                               defaults.sweep.near, "M", cmd);
  TCLAP::ValueArg<double> far("", "far", "Farthest depth hypothesis (m)", false, defaults.sweep.far,
                              "M", cmd);
  TCLAP::ValueArg<int> hypotheses("", "hypotheses", "Depth planes", false,
                                  defaults.sweep.hypotheses, "N", cmd);
  TCLAP::ValueArg<int> window("", "window", "Cost averaging window (pixels)", false,
                              defaults.sweep.window, "N", cmd);
  TCLAP::ValueArg<double> min_confidence(
      "", "min-confidence", "Pixels whose BP confidence (0..1) is below this get depth 0 (unknown)",
      false, defaults.min_confidence, "C", cmd);
  TCLAP::ValueArg<std::string> truth("", "groundtruth", "Report accuracy against this folder",
                                     false, "", "DIR", cmd);
  TCLAP::ValueArg<int> max_frames("", "frames", "Convert only the first N rig frames", false, 0,
                                  "N", cmd);
  cmd.Parse(argc, argv);

  sensors::StereoDepthOptions options;
  options.sweep.near = near.getValue();
  options.sweep.far = far.getValue();
  options.sweep.hypotheses = hypotheses.getValue();
  options.sweep.window = window.getValue();
  core::CheckInRange(min_confidence.getValue(), 0, 1, "--min-confidence");
  options.min_confidence = static_cast<float>(min_confidence.getValue());
  if (core::SameFile(in.getValue(), out.getValue()))
    throw std::invalid_argument("--out " + out.getValue() + " is the input rawlog " +
                                in.getValue() + ": it would be overwritten");
  // Nothing but a rawlog is replaced, and nothing inside an input's folder (the ground truth).
  apps::CheckOutputFile("--out", out.getValue(), {in.getValue(), truth.getValue()},
                        apps::HasExtension(".rawlog"));

  std::optional<sim::GroundTruthReader> ground_truth;
  if (truth.isSet()) ground_truth.emplace(truth.getValue());
  sensors::RigFrameReader reader(in.getValue());
  sensors::RawlogOutput output(out.getValue());
  apps::Progress progress("[novelty-depth] depth frames",
                          max_frames.getValue() > 0 ? max_frames.getValue() : 0);
  int frames = 0, scored = 0;
  double within_sum = 0.0;
  std::vector<mrpt::serialization::CSerializable::Ptr> others;
  for (sensors::RigFrame f; reader.Next(f, &others);) {
    for (const auto& o : others) output.Write(*o);
    others.clear();
    if (max_frames.getValue() > 0 && frames >= max_frames.getValue()) break;
    std::vector<sensors::SweepView> views;
    for (size_t i = 1; i < f.images.size(); ++i)
      views.push_back({f.images[i], f.cameras[i], f.ref_from_camera[i]});
    const sensors::StereoDepth depth =
        sensors::ComputeStereoDepth(f.images[0], f.cameras[0], views, options);
    output.WriteRgbd(f.time, f.images[0], depth.depth, f.cameras[0], f.robot_from_reference,
                     core::FrameStem(f.index) + "_stereo", "STEREO_DEPTH");
    ++frames;
    if (ground_truth) {
      const cv::Mat true_depth = ground_truth->Depth(f.index);
      if (!true_depth.empty()) {
        const auto a = eval::MeasureDepthAccuracy(depth.depth, true_depth, f.images[0], {});
        within_sum += a.within_fraction;
        ++scored;
        std::printf(
            "  frame %d: %.1f %% of %d textured pixels within 3 %% (an estimate on %.1f %% of "
            "them; the others count as wrong)\n",
            f.index, 100 * a.within_fraction, a.textured_pixels,
            a.textured_pixels ? 100.0 * a.scored_pixels / a.textured_pixels : 0.0);
      }
    }
    progress.Update(frames);
  }
  progress.Finish();
  for (const auto& o : others) output.Write(*o);
  output.Close();
  std::printf("%d depth frames (%d rig frames skipped) → %s\n", frames, reader.skipped(),
              output.path().c_str());
  if (reader.skipped())
    std::printf(
        "  %s\n",
        eval::SkippedFramesSummary(frames + reader.skipped(), reader.skip_reasons()).c_str());
  if (scored > 0)
    std::printf("mean share of textured pixels within 3 %% of the true depth: %.1f %%\n",
                100 * within_sum / scored);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  return novelty::apps::RunProgram("novelty-depth", [&] { return Run(argc, argv); });
}
