// The experiments of thesis 6.4: learn the illumination-invariant model from training frames
// under several lightings (6.1, 6.2), then measure novelty in the test frames (6.3) against the
// two baselines, normalised gradient correlation and the spherical coordinate transform (2.4,
// 6.4), each against one reference image of the first lighting, as the thesis compares them.
//
// Two kinds of experiment, told apart by the training phases:
// - one phase (the washing machine, the plate): a static camera, each training frame a lighting,
//   one viewpoint; the baselines' reference is `reference_frame` (default the first).
// - several phases (the table scene, the specular scene: I1, I2, ...): a moving camera, each
//   phase one lighting's sequence, learnt into the illumination-invariant map at common
//   viewpoints (maps/illumination/illumination_map.h) with the ground truth's camera poses (a
//   perfect tracker's: one frame for all sequences, 6.1.1) or, with `poses_from_rawlog`, the
//   rawlog's (novelty-poses: the LED tracker's or visual localization's; frames without one are
//   skipped and counted), and the rawlog's depth, or the ground truth's where the rawlog has none
//   (stereo rigs: novelty-depth makes it from the images). The baselines' reference is a virtual
//   image of the first sequence at each test frame's pose.
// The phases come from the ground truth (novelty-sim's scenarios name them). The output folder
// gets panels/ (camera, reference, invariant image, novelty Δ, NGC 1 - ρ, SCT distance, ground
// truth per test frame), roc.csv, findings.csv and report.html: the pixel ROC of each method over
// the test frames (the simulator's novelty masks are the truth; pixels the invariant image or a
// reference does not cover are left out and counted), TPR at FPR 1 % and 5 %, AUC, and the share
// of the lighting-only change (pixels outside the object whose intensity differs from the
// reference by more than 25 %: shadows, highlights) each method flags at the threshold that finds
// 90 % of the object. The baselines are also scored against every other lighting as the
// reference.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "eval/findings_table.h"
#include "maps/illumination/illumination_map.h"
#include "mrpt_plugins/illumination_invariant_map_options.h"

namespace novelty::experiments {

struct IlluminationExperimentOptions {
  std::string rawlog;       ///< the camera's frames: an RGB-D, stereo or trinocular rawlog
  std::string groundtruth;  ///< novelty-sim's folder: phases, novelty masks, poses, depth
  /// One phase: a static camera; several: a moving camera, one lighting's sequence each.
  std::vector<std::string> train_phases = {"training"};
  std::string test_phase = "test";
  /// Static camera: the baselines' reference frame (none: the first training frame).
  std::optional<int> reference_frame;
  /// The options of CIlluminationInvariantMap, its defaults (the best measured setting) unless
  /// set; share/thesis/illumination_invariant.ini holds the thesis's.
  illumination::IlluminationMapOptions map = mrpt_plugins::IlluminationInvariantMapConfig().map;
  /// Camera poses from the rawlog's pose observations instead of the ground truth's.
  bool poses_from_rawlog = false;
  /// Told a line of what was learnt (none: nothing is said).
  std::function<void(const std::string& line)> status;
  /// Told `done` of `total` steps of a stage ("lightings", "test frames").
  std::function<void(const std::string& stage, int done, int total)> progress;
};

struct IlluminationExperimentResult {
  eval::FindingsTable findings;  ///< as findings.csv holds them
  /// Per method (novelty, NGC, SCT): name, TPR at FPR 1 %, 5 %, 10 %, AUC, and the lighting-only
  /// change flagged at TPR 90 %.
  std::vector<std::vector<std::string>> methods;
  bool ahead = false;         ///< novelty's TPR above both baselines' at every FPR ≤ 10 %
  double scored_share = 0.0;  ///< share of the test frames' pixels evaluated (the coverage)
  int test_frames = 0;
  double ms_per_test_frame = 0.0;
};

/// Runs the experiment, writing its files into `out_dir` (an existing folder). Throws
/// std::invalid_argument naming the phase, frame or file when it cannot be evaluated (no test
/// frame, a test set without novelty or without background, no pose).
IlluminationExperimentResult RunIlluminationExperiment(const IlluminationExperimentOptions& options,
                                                       const std::string& out_dir);

}  // namespace novelty::experiments
