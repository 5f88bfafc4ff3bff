// The experiment of thesis 5.2 — how well the surprise-driven object database
// learnt in one room (I1 + I2) recognises its objects in another (I3).
//
// LEARN is novelty-run's output folder of the learning run (objects.csv, map.object_database),
// e.g. share/scenarios/object_learning.scn with --objects-from 361; the ground-truth folders are
// novelty-sim's. The output folder gets
//   focus.csv          per learning frame: focus box centre, the new object's true box centre,
//                          features extracted in the box (figs. 5.3 a–c), the share of the true
//                          box the focus box covers (where features can be learnt from)
//   features.csv       per learnt feature: object, the object's true name, its 3-D place,
//                          whether the place lies on that object (ground-truth ids and depth)
//   recognition.csv    per I3 frame and learnt object: pixels it shows, matches N_k, matches
//                          that agree on a pose (verified), the same with the ratio test's
//                          distinct second, the places where the features' K nearest keypoints
//                          agree on a pose (verified_nearest), the matches whose keypoints agree
//                          in orientation and metric size with the learnt ones within
//                          the consistency options (matches_consistent,
//                          keypoint_consistency.h), visible (fig. 5.5 a, b); where visible, the
//                          keypoints on the object (ground truth), N_k among them alone and the
//                          mean nearest distance (eval/matches_on_object.h)
//   findings.csv       finding,value,target,holds — the ROC over (frame, object) decisions
//                          sweeping the matches required (fig. 5.5 d), TPR at FPR 0.3/1/5 %, AUC,
//                          each object's TPR and false positives at the FPR 0.3 % threshold,
//                          the database's size, features on their object
//   report.html        the same with plots; panels/ frames with their matches drawn.
// With baseline_map (the appearance map after I1: novelty-run --frames 360 --map-out) and the
// learning rawlog, also the baseline of 5.2 — the eigenbackground of the seven nearest views
// segments the new object, whose features are all learnt — recognised the same way
// (recognition_baseline.csv, without verified_nearest and the on-object columns: 0, NaN)
// and compared in findings.csv and the ROC plots.
#pragma once

#include <cstdio>
#include <functional>
#include <string>

#include "eval/findings_table.h"
#include "maps/objects/keypoint_consistency.h"

namespace novelty::experiments {

struct ObjectExperimentOptions {
  std::string learnt;       ///< novelty-run's output folder of the learning run
  std::string learn_truth;  ///< the learning run's ground truth (novelty-sim's folder)
  std::string rawlog;       ///< the recognition run (I3), an RGB-D rawlog
  std::string truth;        ///< its ground truth
  int min_visible = 400;    ///< pixels an object must show to count as visible in a frame
  int frames = 0;           ///< only the first N recognition frames (0: all)
  int panels_every = 20;    ///< a panel every K-th recognition frame (0: none)
  std::string baseline_map, learn_rawlog;  ///< the baseline's I1 map and I1 + I2 rawlog
  int baseline_from = 361;                 ///< the first frame of I2 in the learning rawlog
  int verify_nearest = 2;  ///< nearest keypoints per feature for verified_nearest (0: none)
  /// The score "matches of consistent keypoints" (enabled, its bounds).
  objects::KeypointConsistencyOptions consistency;
  /// Told a line now and then on a long run.
  std::function<void(const std::string& line)> status;
  /// Gets the findings as they are judged (none: quiet).
  std::FILE* console = nullptr;
};

struct ObjectExperimentResult {
  eval::FindingsTable findings;   ///< as findings.csv holds them
  int objects = 0, features = 0;  ///< the learnt database
  int recognition_frames = 0, skipped = 0;
};

/// Runs the experiment into `out_dir` (an existing folder); throws std::runtime_error naming the
/// file or frame when an input cannot be used, std::invalid_argument for bad options.
ObjectExperimentResult RunObjectExperiment(const ObjectExperimentOptions& options,
                                           const std::string& out_dir);

}  // namespace novelty::experiments
