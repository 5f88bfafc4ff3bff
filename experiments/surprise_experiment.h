// The experiment of thesis 4.3 and the project's main job: an RGB-D rawlog played, as an MRPT
// program would, into a CMultiMetricMap built from an .ini (a CAppearanceMap, and the
// CDifferencingMap that ground truth scores it against if the .ini declares one; per compare_views
// factor copies of both with reference views that many times sparser, fig. 4.13's R2 and R4; a
// CObjectDatabaseMap if the .ini declares one), every camera
// observation passed to insertObservation with the robot pose — from the ground truth, from the
// CObservationRobotPose novelty-poses put into the rawlog, or from wheel odometry — and the
// products read back from the maps. The output folder gets
//   panels/NNNNNN.png  camera | expected | surprise | uncertainty [| differencing]
//   metrics.csv        frame,phase,object,AS_surprise,PAS_surprise,AS_diff,PAS_diff,coverage
//                      (the share of pixels with a prediction, which AS is measured over) for every
//                      changed object in view (regions from the ground-truth novelty masks: added
//                      objects and the arm by id, "removed" where objects were taken)
//   findings.csv       the findings of thesis 4.3, each over the first run after its change, with
//                      its numbers and whether it holds (fig. 4.13 too with compare_views)
//   frames.csv         frame,coverage,psnr_db,mean_surprise,p95_surprise,tail_surprise: how well
//                      the map predicted each frame (eval/prediction_quality.h), with or without
//                      ground truth (metrics.csv and findings.csv need it)
//   report.html        the findings, plots of AS/PAS over frames, a table per object and phase,
//                      panels
//   map.3Dscene        the reference-view frusta, for SceneViewer3D
// and, with a CObjectDatabaseMap (thesis ch. 5), objects.csv (per frame its focus box,
// added/removed, features, recognition, from objects_from on) and map.object_database.
#pragma once

#include <functional>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "eval/novelty_verdict.h"
#include "eval/prediction_quality.h"
#include "eval/selectivity_findings.h"

namespace novelty::experiments {

struct SurpriseExperimentOptions {
  std::string rawlog;  ///< an RGB-D rawlog
  /// novelty-sim's folder: poses, novelty masks, phases; empty: nothing is scored (the products,
  /// panels, report and map all the same), and the poses come from the rawlog or odometry.
  std::string groundtruth;
  /// The maps as a CMultiMetricMap .ini; empty: one CAppearanceMap and one CDifferencingMap with
  /// their defaults.
  std::string config;
  std::string map_in;             ///< continue from this saved appearance map (empty: a new one)
  std::string objects_in;         ///< start the .ini's CObjectDatabaseMap from this saved database
  std::string map_out;            ///< save the appearance map here (empty: not saved)
  std::optional<int> max_frames;  ///< stop after this many frames inserted
  int panels_every = 10;          ///< a panel every K-th frame
  /// The CObjectDatabaseMap takes frames from this one on; before, the appearance map learns the
  /// room alone (the thesis's I1: 361 for share/scenarios/object_learning.scn).
  int objects_from = 1;
  /// After this frame the appearance and differencing maps judge without learning: built from the
  /// frames up to it, they judge the rest as they were (0: they learn throughout).
  int learn_until = 0;
  std::string pose_source = "groundtruth";  ///< groundtruth | rawlog | odometry
  /// Reference views this many times wider than configured (fig. 4.13's R2 and R4: 2 and 4).
  double view_reduction = 1.0;
  /// Also maps with reference views this many times sparser, side by side (ParseViewFactors).
  std::vector<double> compare_views;
  /// When a frame counts as showing something new, for the report's verdict (no ground truth
  /// needed).
  eval::NoveltyVerdictOptions verdict;
  /// Told a line of what happens (a map continued, frames skipped, an early end).
  std::function<void(const std::string& line)> status;
  /// Told the frame inserted last and the frames to expect.
  std::function<void(int frame, int total)> progress;
  /// Gets a line per finding as it is judged (none: quiet).
  std::ostream* console = nullptr;
};

struct SurpriseExperimentResult {
  int frames = 0, skipped = 0;
  double seconds = 0.0;
  bool ended_early = false;        ///< the rawlog ended early: the results cover what was read
  std::vector<std::string> notes;  ///< the skipped frames and an early end, as the report says
  std::vector<eval::SelectivityRow> rows;  ///< metrics.csv's rows of the main maps
  int views = 0;                           ///< reference views at the end
  std::string map_summary;                 ///< the appearance map's asString()
  std::string objects_summary;             ///< the object database's, empty without one
  double mean_warp_sigma_px = 0.0;         ///< the learnt warp-error floor s (0: off)
  int aligned_frames = 0;                  ///< align_to_prior: frames it turned
  double mean_aligned_deg = 0.0;
  /// How well the map predicted the frames (frames.csv per frame): medians of coverage, PSNR of
  /// the expected image and the surprise level, ground truth or not.
  eval::PredictionSummary prediction;
  /// Where something new was in view, from the surprise alone (eval/novelty_verdict.h), and the
  /// report's sentence for it.
  eval::NoveltyVerdict verdict;
  std::string verdict_sentence;
};

/// "2,4" -> {2, 4}; throws std::invalid_argument unless each is a finite factor >= 1 (at most 8).
std::vector<double> ParseViewFactors(const std::string& list);

/// Runs the experiment into `out_dir` (an existing folder); throws std::invalid_argument for bad
/// options and std::runtime_error naming the file when an input cannot be used or no frame was
/// inserted (then no map is saved).
SurpriseExperimentResult RunSurpriseExperiment(const SurpriseExperimentOptions& options,
                                               const std::string& out_dir);

/// What a program prints after a run whose results are in `out_dir` and whose appearance map was
/// saved to `map_out`: counts, where the files are, the prediction's medians and the verdict.
std::string SurpriseRunSummary(const SurpriseExperimentResult& r, const std::string& out_dir,
                               const std::string& map_out);

}  // namespace novelty::experiments
