// novelty-objects: the experiment of thesis 5.2 (experiments/object_experiment.h says what it
// measures and writes) — how well the surprise-driven object database learnt in one room
// (I1 + I2) recognises its objects in another (I3).
//
//   novelty-objects --learnt LEARN --learn-groundtruth DIR --rawlog I3.rawlog --groundtruth DIR
//                   --out OUT [--min-visible-pixels 400] [--frames N] [--panels-every K]
//                   [--verify-nearest 2] [--consistent-angle 20] [--consistent-size-ratio 1.3]
//                   [--baseline-map I1.map --learn-rawlog I1I2.rawlog [--baseline-from 361]]
//
// LEARN is novelty-run's output folder of the learning run (objects.csv, map.object_database),
// e.g. share/scenarios/object_learning.scn with --objects-from 361; the ground-truth folders are
// novelty-sim's. OUT: focus.csv, features.csv, recognition.csv (and recognition_baseline.csv),
// findings.csv, report.html, panels/.
#include <tclap/CmdLine.h>

#include <cstdio>
#include <stdexcept>
#include <string>

#include "apps/command_line.h"
#include "apps/shell/output_folder.h"
#include "apps/shell/program.h"
#include "experiments/object_experiment.h"
#include "maps/objects/keypoint_consistency.h"

using namespace novelty;

namespace {

// The command line as the experiment's options; `out` gets --out.
experiments::ObjectExperimentOptions Parse(int argc, char** argv, std::string& out_dir) {
  apps::CommandLine cmd(
      "Thesis 5.2: recognition, in another room, of the objects a CObjectDatabaseMap learnt where "
      "surprise pointed; the ROC over (frame, object) decisions.",
      "0.1");
  TCLAP::ValueArg<std::string> learnt(
      "", "learnt",
      "novelty-run's output folder of the learning run (objects.csv, map.object_database)", true,
      "", "DIR", cmd);
  TCLAP::ValueArg<std::string> learn_truth(
      "", "learn-groundtruth", "Ground truth of the learning run", true, "", "DIR", cmd);
  TCLAP::ValueArg<std::string> rawlog("", "rawlog", "The recognition run (I3), an RGB-D rawlog",
                                      true, "", "R.rawlog", cmd);
  TCLAP::ValueArg<std::string> truth("", "groundtruth", "Ground truth of the recognition run", true,
                                     "", "DIR", cmd);
  TCLAP::ValueArg<std::string> out("", "out", "Output folder", true, "", "OUT", cmd);
  TCLAP::ValueArg<int> min_visible("", "min-visible-pixels",
                                   "An object counts as visible in a frame from this many pixels "
                                   "on (default 400, 0.5 % of 320x240)",
                                   false, 400, "N", cmd);
  TCLAP::ValueArg<int> frames("", "frames", "Only the first N recognition frames", false, 0, "N",
                              cmd);
  TCLAP::ValueArg<int> panels("", "panels-every",
                              "Write every K-th recognition panel (default 20; 0 none)", false, 20,
                              "K", cmd);
  TCLAP::ValueArg<std::string> baseline_map(
      "", "baseline-map",
      "The baseline (eigenbackground, [WIS+10]): the appearance map after I1 (novelty-run --frames "
      "360 --map-out)",
      false, "", "M", cmd);
  TCLAP::ValueArg<std::string> learn_rawlog("", "learn-rawlog",
                                            "The baseline: the learning rawlog (I1 + I2)", false,
                                            "", "R.rawlog", cmd);
  TCLAP::ValueArg<int> baseline_from("", "baseline-from",
                                     "The baseline learns from this frame on (default 361, I2)",
                                     false, 361, "N", cmd);
  TCLAP::ValueArg<int> verify_nearest(
      "", "verify-nearest",
      "The score 'verified nearest keypoints': each database feature's K nearest keypoints, "
      "without the ratio test, that agree on the object's pose (default 2; 0: not computed, "
      "scored 0)",
      false, 2, "K", cmd);
  const objects::KeypointConsistencyOptions defaults;
  TCLAP::ValueArg<double> consistent_angle(
      "", "consistent-angle",
      "The score 'matches of consistent keypoints': degrees a match's keypoint may turn from the "
      "learnt one's (default 20)",
      false, defaults.max_angle_deg, "DEG", cmd);
  TCLAP::ValueArg<double> consistent_size(
      "", "consistent-size-ratio",
      "The same score: factor its metric size (size x depth / fx) may differ either way "
      "(default 1.3)",
      false, defaults.max_size_ratio, "R", cmd);
  cmd.Parse(argc, argv);
  experiments::ObjectExperimentOptions a;
  a.learnt = learnt.getValue();
  a.learn_truth = learn_truth.getValue();
  a.rawlog = rawlog.getValue();
  a.truth = truth.getValue();
  out_dir = out.getValue();
  a.min_visible = min_visible.getValue();
  a.frames = frames.getValue();
  a.panels_every = panels.getValue();
  a.baseline_map = baseline_map.getValue();
  a.learn_rawlog = learn_rawlog.getValue();
  a.baseline_from = baseline_from.getValue();
  a.verify_nearest = verify_nearest.getValue();
  if (a.baseline_map.empty() != a.learn_rawlog.empty())
    throw std::invalid_argument("--baseline-map and --learn-rawlog go together");
  if (a.min_visible < 1) throw std::invalid_argument("--min-visible-pixels must be >= 1");
  if (a.frames < 0) throw std::invalid_argument("--frames must be >= 0");
  if (a.panels_every < 0) throw std::invalid_argument("--panels-every must be >= 0");
  if (a.verify_nearest < 0) throw std::invalid_argument("--verify-nearest must be >= 0");
  a.consistency.enabled = true;
  a.consistency.max_angle_deg = consistent_angle.getValue();
  a.consistency.max_size_ratio = consistent_size.getValue();
  try {
    objects::CheckKeypointConsistencyOptions(a.consistency);
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(std::string("--consistent-angle / --consistent-size-ratio: ") +
                                e.what());
  }
  return a;
}

int Run(int argc, char** argv) {
  std::string out;
  experiments::ObjectExperimentOptions o = Parse(argc, argv, out);
  o.console = stdout;
  o.status = [](const std::string& line) {
    std::fprintf(stderr, "[novelty-objects] %s\n", line.c_str());
  };
  apps::OutputFolder folder(
      "novelty-objects", out,
      {o.learnt, o.learn_truth, o.rawlog, o.truth, o.learn_rawlog, o.baseline_map});
  const experiments::ObjectExperimentResult r = experiments::RunObjectExperiment(o, folder.path());
  folder.Commit();
  std::printf(
      "  %s/findings.csv, recognition.csv, features.csv, focus.csv, report.html (%d frames "
      "skipped)\n",
      folder.final_path().c_str(), r.skipped);
  return apps::kExitOk;
}

}  // namespace

int main(int argc, char** argv) {
  return novelty::apps::RunProgram("novelty-objects", [&] { return Run(argc, argv); });
}
