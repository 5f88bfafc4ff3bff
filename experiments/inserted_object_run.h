// Novelty on a real recording with something new put into it (issue 51, item 6): a synthetic
// textured box is drawn into the frames of an RGB-D rawlog from a chosen frame on, with its depth
// and occluded by the real scene (sim/render/object_insertion.h), and the rawlog is played into
// the maps with the box's exact masks as ground truth — surprise against image differencing on
// real sensor data, scored as thesis 4.3 scores the simulator's glass.
//
// The box stands `standoff` in front of the surface the frame `insert_from` sees at its centre,
// facing that frame's camera; the frames before it teach the maps the room. The output folder
// gets
//   inserted.rawlog + inserted_Images/  the frames with the box (pose observation + RGB-D each)
//   groundtruth/                        poses, depth, ids, novelty masks (the box), phases A
//                                       (before) and X (with the box), as novelty-sim writes them
//   run/                                the surprise experiment's output over inserted.rawlog
//   findings.csv                        the box's AS and PAS for surprise and differencing, at
//                                       first sight and over the frames that see it, with the
//                                       coverage
#pragma once

#include <Eigen/Core>
#include <functional>
#include <optional>
#include <string>

#include "eval/findings_table.h"
#include "eval/selectivity_findings.h"
#include "experiments/surprise_experiment.h"

namespace novelty::experiments {

struct InsertedObjectRunOptions {
  std::string rawlog;  ///< RGB-D frames, each with a pose observation (novelty-import writes such)
  /// The maps as a CMultiMetricMap .ini; it must declare a CDifferencingMap (the baseline the
  /// box is scored against). Empty: both maps at their defaults.
  std::string config;
  int insert_from = 0;    ///< first frame with the box (1-based); 0: the middle frame
  double standoff = 0.3;  ///< m in front of the surface that frame sees at its centre
  /// The maps learn from the frames before the box only and judge the rest as they were (issue
  /// 51's "build the map from the first loop; predict and judge the second"). Off by default: on
  /// the TUM cabinet a map frozen after half the keyframes has seen each place once or twice, its
  /// prior stays uncertain and surprise trails differencing by 1.9-2.3 dB; learning throughout,
  /// as the thesis's robot does, it leads (docs/appearance.md).
  bool judge_only = false;
  Eigen::Vector3d size{0.3, 0.3, 0.3};  ///< the box's edge lengths (m)
  std::optional<int> max_frames;        ///< stop after this many frames
  int panels_every = 10;
  std::function<void(const std::string& line)> status;
  std::function<void(const std::string& stage, int frame, int total)> progress;
};

struct InsertedObjectRunResult {
  int frames = 0;  ///< frames written and played
  int insert_from = 0;
  int box_frames = 0;         ///< frames in which the box is seen (at least 30 pixels)
  double box_pixels = 0.0;    ///< its mean area there (pixels)
  eval::MeanSelectivity box;  ///< means over those frames where both measures are finite
  eval::MeanSelectivity
      first_sight;  ///< the first frame that sees it, before any map could learn it
  eval::FindingsTable findings;
  SurpriseExperimentResult run;
};

/// Runs it into `out_dir` (an existing folder). Throws std::invalid_argument for bad options or a
/// frame `insert_from` whose centre has no depth, std::runtime_error naming the file for a rawlog
/// that cannot be used (no frames, frames without poses).
InsertedObjectRunResult RunInsertedObject(const InsertedObjectRunOptions& options,
                                          const std::string& out_dir);

}  // namespace novelty::experiments
