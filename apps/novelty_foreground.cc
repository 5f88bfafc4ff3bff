// novelty-foreground: a fixed camera's foreground from the appearance map's predictive novelty,
// scored the CDnet way beside OpenCV's MOG2, KNN, GSOC and CNT on the same frames
// (experiments/foreground_run.h).
//
//   novelty-foreground FOLDER --out OUT [--threshold 16.6] [--learn-foreground]
//       [--methods novelty,mog2,knn,gsoc,cnt] [--frames N] [--no-masks]
//
// FOLDER is in the CDnet layout: input/in000001.jpg …, optionally groundtruth/gt000001.png …,
// ROI.bmp and temporalROI.txt. OUT gets <method>/bin000001.png … (255 foreground), scores.csv and
// findings.csv; each method's F-measure and ms a frame are printed.
#include <tclap/CmdLine.h>

#include <cstdio>
#include <optional>
#include <sstream>
#include <string>

#include "apps/command_line.h"
#include "apps/shell/output_folder.h"
#include "apps/shell/program.h"
#include "apps/shell/progress.h"
#include "experiments/foreground_run.h"

using namespace novelty;

namespace {

// The summary: scores where there was ground truth, times always; exit 3 for a video cut short.
int Report(const experiments::ForegroundRunResult& r, const std::string& out) {
  if (r.scored > 0) {
    std::printf("%d frames, %d scored (CDnet: recall, precision, F; ms a frame)\n", r.frames,
                r.scored);
    for (const auto& m : r.methods)
      std::printf("  %-8s R %.3f  P %.3f  F %.3f  %.2f ms\n", m.name.c_str(), m.scores.recall,
                  m.scores.precision, m.scores.f_measure, m.ms_per_frame);
  } else {
    std::printf(
        "%d frames, none scored (no ground truth in the temporal ROI): masks and panels "
        "only; ms a frame:\n",
        r.frames);
    for (const auto& m : r.methods) std::printf("  %-8s %.2f ms\n", m.name.c_str(), m.ms_per_frame);
  }
  if (r.unscored_in_roi > 0)
    std::printf("note: %d frames of the temporal ROI have no ground truth and were not scored\n",
                r.unscored_in_roi);
  std::printf("→ %s/scores.csv\n", out.c_str());
  if (r.cut_short) {
    std::fprintf(stderr, "novelty-foreground: the input ended after %d of its %d frames\n",
                 r.frames, r.expected_frames);
    return apps::kExitPartial;
  }
  return apps::kExitOk;
}

int Run(int argc, char** argv) {
  apps::CommandLine cmd(
      "A fixed camera's foreground from predictive novelty, scored beside OpenCV's subtractors",
      "0.1");
  experiments::ForegroundRunOptions o;
  TCLAP::UnlabeledValueArg<std::string> in(
      "input", "A CDnet-layout folder, a folder of images or a video file", true, "", "INPUT", cmd);
  TCLAP::ValueArg<std::string> out("o", "out", "Output folder", true, "", "OUT", cmd);
  TCLAP::ValueArg<double> threshold(
      "", "threshold",
      "Foreground where -ln p(frame | background) exceeds this (nats; default 3 ln 256 = 16.6, "
      "the Bayes decision against a uniform foreground colour)",
      false, o.labels.threshold_nats, "NATS", cmd);
  TCLAP::SwitchArg no_shadows("", "no-shadow-label",
                              "Count shadows as foreground (default: a grey, darker illumination "
                              "image is shadow, maps/appearance/foreground_labels.h)",
                              cmd);
  TCLAP::ValueArg<int> min_blob("", "min-blob",
                                "Drop foreground blobs of fewer pixels (default 0: keep them)",
                                false, o.labels.min_blob_pixels, "PIXELS", cmd);
  TCLAP::SwitchArg learn_foreground(
      "", "learn-foreground", "Learn foreground pixels too (the thesis's update; default: hold)",
      cmd);
  TCLAP::ValueArg<int> max_hold("", "max-hold",
                                "A pixel held this many frames in a row learns again (default "
                                "200; 0: no limit)",
                                false, o.max_hold_frames, "FRAMES", cmd);
  TCLAP::ValueArg<std::string> methods("", "methods",
                                       "Comma-separated, of novelty, mog2, knn, gsoc, cnt", false,
                                       "novelty,mog2,knn,gsoc,cnt", "LIST", cmd);
  TCLAP::ValueArg<int> frames("", "frames", "Only the first N frames (0: all)", false, 0, "N", cmd);
  TCLAP::SwitchArg no_masks("", "no-masks", "Write no masks (scores and panels still)", cmd);
  cmd.Parse(argc, argv);
  if (!(threshold.getValue() > 0 && threshold.getValue() < 1e6))
    throw apps::UsageError("--threshold must be in (0, 1e6) nats");
  if (frames.getValue() < 0) throw apps::UsageError("--frames must be >= 0");
  o.folder = in.getValue();
  if (min_blob.getValue() < 0) throw apps::UsageError("--min-blob must be >= 0");
  if (max_hold.getValue() < 0 || max_hold.getValue() > 65000)
    throw apps::UsageError("--max-hold must be in 0…65000 frames");
  o.labels.threshold_nats = threshold.getValue();
  o.labels.shadow_label = !no_shadows.getValue();
  o.labels.min_blob_pixels = min_blob.getValue();
  o.hold_foreground = !learn_foreground.getValue();
  o.max_hold_frames = max_hold.getValue();
  o.max_frames = frames.getValue();
  o.write_masks = !no_masks.getValue();
  o.methods.clear();
  std::stringstream list(methods.getValue());
  for (std::string m; std::getline(list, m, ',');) o.methods.push_back(m);
  std::optional<apps::Progress> progress;
  o.progress = [&](int done, int total) {
    if (!progress) progress.emplace("[novelty-foreground] frames", total);
    progress->Update(done);
    if (done == total) progress->Finish();
  };
  apps::OutputFolder folder("novelty-foreground", out.getValue(), {o.folder});
  experiments::ForegroundRunResult r;
  try {
    r = experiments::RunForeground(o, folder.path());
  } catch (const std::invalid_argument& e) {
    throw apps::UsageError(e.what());
  }
  if (progress) progress->Finish();  // a video cut short ends before its count
  folder.Commit();
  return Report(r, folder.final_path());
}

}  // namespace

int main(int argc, char** argv) {
  return novelty::apps::RunProgram("novelty-foreground", [&] { return Run(argc, argv); });
}
