// novelty-illumination: the experiments of thesis 6.4 (experiments/illumination_experiment.h)
// on a simulated rawlog and its ground truth — the invariant model or map learnt from the
// training phases, novelty in the test phase against NGC and SCT.
//
//   novelty-illumination --rawlog IN.rawlog --groundtruth DIR --out OUT
//       [--train-phase training | --train-phase I1,I2,...] [--test-phase test]
//       [--reference-frame F] [--poses groundtruth|rawlog]
//       [--kappa K] [--colour per-channel|luminance-chromaticity] [--max-order N] [--grid N]
//       [--shape-scale frame|empty] [--viewpoint-distance M] [--missing-texture]
//       [--options FILE] [--set KEY=VALUE ...]   (the CIlluminationInvariantMap options, with
//       its defaults; --options share/thesis/illumination_invariant.ini: the thesis's Δ)
//
// OUT: panels/, roc.csv, findings.csv, report.html.
#include <tclap/CmdLine.h>

#include <cstdio>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "apps/command_line.h"
#include "apps/shell/output_folder.h"
#include "apps/shell/program.h"
#include "apps/shell/progress.h"
#include "apps/shell/table_flags.h"
#include "experiments/illumination_experiment.h"
#include "mrpt_plugins/illumination_invariant_map_options.h"

using namespace novelty;

namespace {

std::vector<std::string> SplitList(const std::string& list) {
  std::vector<std::string> out;
  std::stringstream ss(list);
  for (std::string item; std::getline(ss, item, ',');)
    if (!item.empty()) out.push_back(item);
  return out;
}

int Run(int argc, char** argv) {
  apps::CommandLine cmd("Novelty under changing light (thesis 6.4) against NGC and SCT.", "0.1");
  TCLAP::ValueArg<std::string> rawlog("", "rawlog", "Rawlog of the camera (RGB-D or stereo)", true,
                                      "", "IN.rawlog", cmd);
  TCLAP::ValueArg<std::string> truth_dir("", "groundtruth", "Ground-truth folder", true, "", "DIR",
                                         cmd);
  TCLAP::ValueArg<std::string> out("o", "out", "Output folder", true, "", "OUT", cmd);
  TCLAP::ValueArg<std::string> train_phase(
      "", "train-phase",
      "Phase of the training frames (static camera), or comma-separated phases, one per "
      "lighting (moving camera)",
      false, "training", "NAME[,NAME...]", cmd);
  TCLAP::ValueArg<std::string> test_phase("", "test-phase", "Phase of the test frames", false,
                                          "test", "NAME", cmd);
  TCLAP::ValueArg<int> reference_frame(
      "", "reference-frame",
      "Static camera: the baselines' reference image (default: first training frame)", false, 0,
      "F", cmd);
  // The illumination options are CIlluminationInvariantMap's, with its table's defaults.
  apps::TableFlags<mrpt_plugins::IlluminationInvariantMapConfig> options(
      cmd, {{"kappa", "kappa"},
            {"colour", "colour"},
            {"zernike_grid", "grid"},
            {"shape_scale", "shape-scale"},
            {"zernike_max_order", "max-order"},
            {"viewpoint_distance", "viewpoint-distance"},
            {"missing_texture", "missing-texture"}});
  std::vector<std::string> pose_sources = {"groundtruth", "rawlog"};
  TCLAP::ValuesConstraint<std::string> pose_names(pose_sources);
  TCLAP::ValueArg<std::string> poses(
      "", "poses",
      "Moving camera: camera poses from the ground truth (default) or from the rawlog's pose "
      "observations (novelty-poses: tracker or visual localization)",
      false, "groundtruth", &pose_names, cmd);
  cmd.Parse(argc, argv);
  experiments::IlluminationExperimentOptions o;
  o.rawlog = rawlog.getValue();
  o.groundtruth = truth_dir.getValue();
  o.train_phases = SplitList(train_phase.getValue());
  if (o.train_phases.empty()) throw apps::UsageError("--train-phase names no phase");
  o.test_phase = test_phase.getValue();
  if (reference_frame.isSet()) o.reference_frame = reference_frame.getValue();
  o.map = options.Values().map;
  o.poses_from_rawlog = poses.getValue() == "rawlog";
  o.status = [](const std::string& line) {
    std::fprintf(stderr, "[novelty-illumination] %s\n", line.c_str());
  };
  std::unique_ptr<apps::Progress> bar;
  std::string stage;
  o.progress = [&](const std::string& s, int done, int total) {
    if (s != stage)
      bar = std::make_unique<apps::Progress>("[novelty-illumination] " + (stage = s), total);
    bar->Update(done);
  };

  apps::OutputFolder folder("novelty-illumination", out.getValue(), {o.rawlog, o.groundtruth});
  const experiments::IlluminationExperimentResult r =
      experiments::RunIlluminationExperiment(o, folder.path());
  bar.reset();
  folder.Commit();
  for (const auto& m : r.methods)
    std::printf("%-24s TPR@1%% %s  TPR@5%% %s  TPR@10%% %s  AUC %s  lighting flagged %s\n",
                m[0].c_str(), m[1].c_str(), m[2].c_str(), m[3].c_str(), m[4].c_str(), m[5].c_str());
  std::printf(
      "ahead of both at every FPR <= 10 %%: %s; %.1f %% of pixels scored; %.1f ms per test "
      "frame\n→ %s/report.html\n",
      r.ahead ? "yes" : "no", 100 * r.scored_share, r.ms_per_test_frame,
      folder.final_path().c_str());
  return apps::kExitOk;
}

}  // namespace

int main(int argc, char** argv) {
  return novelty::apps::RunProgram("novelty-illumination", [&] { return Run(argc, argv); });
}
