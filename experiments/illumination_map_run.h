// The illumination-invariant map (thesis ch. 6) from rawlogs, as a robot would use it: learn it
// from one pass per lighting and save it, then judge new frames with it — the library side of
// novelty-illumination-map.
//
// A pass (a lighting, or the frames to judge) is a rawlog path, optionally with ":FIRST-LAST" (its
// camera frames FIRST…LAST, 1-based) or ":PHASE" (a phase of the ground truth, novelty-sim's
// folder), so that one rawlog holding several passes serves too, and ":each" when each of its
// frames is a lighting of its own; or a folder of images from one fixed camera (photos: each a
// lighting when learning, a frame when judging). Frames are played
// into a CMultiMetricMap holding one CIlluminationInvariantMap (the .ini's, or one at its
// defaults), with poses from the rawlog's pose observations (novelty-poses), the wheel odometry or
// the ground truth's camera poses. Learning calls beginLighting() before each pass and
// finishAcquisition() after the last, then saves the map atomically. Judging writes into its output
// folder: novelty/FRAME.png (Δ in false colour, 0 to 2·T_Y), frames.csv (per frame: coverage,
// regions, matched regions, mean and largest Δ, the share of covered pixels above the map's
// decision threshold; with ground truth the pixel AUC of Δ against the novelty mask), findings.csv
// and report.html (plots of Δ, coverage and AUC per frame, the pixel ROC with ground truth, a panel
// every `panels_every` frames). Frames that cannot be used are skipped and counted.
#pragma once

#include <functional>
#include <limits>
#include <string>
#include <vector>

#include "eval/findings_table.h"
#include "sensors/dataset/fixed_camera_folder.h"
#include "sim/output/ground_truth_reader.h"

namespace novelty::experiments {

/// A rawlog and the camera frames of it to play, or a fixed camera's folder of images.
struct RawlogPass {
  std::string spec;  ///< as given, for messages
  std::string path;
  int first = 1, last = 0;  ///< 1-based, inclusive; last 0: to the end
  /// `path` is a folder of images from one fixed camera (sensors/dataset/fixed_camera_folder.h):
  /// learning takes each image as a lighting of its own, judging each as a frame.
  bool folder = false;
  /// Learning takes each frame as a lighting of its own (a folder, or a rawlog pass given with
  /// ":each", such as novelty-import's of a lighting folder); else the pass is one lighting.
  bool each = false;
};

/// Parses DIR, or RAWLOG, RAWLOG:FIRST-LAST or RAWLOG:PHASE (`truth` needed for a phase), each
/// optionally followed by ":each"; the rawlog must be a file. Throws std::invalid_argument naming
/// `spec`.
RawlogPass ParseRawlogPass(const std::string& spec, const sim::GroundTruthReader* truth);

struct IlluminationMapRunOptions {
  /// "rawlog" (pose observations), "odometry" or "groundtruth" (needs `truth`).
  std::string poses = "rawlog";
  const sim::GroundTruthReader* truth = nullptr;  ///< not owned; may be null
  /// A folder pass's images: which files (include/exclude), the plane's depth, the size limit.
  sensors::FixedCameraOptions fixed_camera;
  /// Told a line of what happens (none: nothing is said).
  std::function<void(const std::string& line)> status;
  /// Told frames played of a stage ("lighting 1/4", "judging"); total 0 when unknown.
  std::function<void(const std::string& stage, int frames, int total)> progress;
};

struct LearnIlluminationMapResult {
  std::string map_summary;  ///< the map's asString()
  int frames = 0, skipped = 0;
  double seconds = 0.0;
};

/// Learns the map from `lightings` (at least two lightings: the median of one is not invariant;
/// a folder pass gives one per image) with the maps of `ini` (empty: one CIlluminationInvariantMap
/// at its defaults) and saves it to `map_out`. Everything a typo can break is checked before the
/// first frame.
LearnIlluminationMapResult LearnIlluminationMap(const std::vector<std::string>& lightings,
                                                const std::string& ini, const std::string& map_out,
                                                const IlluminationMapRunOptions& options);

struct JudgeIlluminationMapResult {
  eval::FindingsTable findings;  ///< as findings.csv holds them
  std::string summary;           ///< one line: frames, skipped, ms a frame, AUC with ground truth
  int frames = 0, skipped = 0;
  double auc = -1.0;  ///< pixel AUC of Δ over all frames' covered pixels; -1 without truth
  /// Share of all frames' covered pixels above the map's decision threshold (NaN: it has none).
  double novel_share = std::numeric_limits<double>::quiet_NaN();
  /// With ground truth, the share of its unchanged covered pixels above the threshold.
  double false_alarm_rate = std::numeric_limits<double>::quiet_NaN();
  bool ended_early = false;  ///< the rawlog ended, or ended before the last frame asked
};

/// Judges the frames of `rawlog` (a pass) with the map saved in `map_in`, writing into `out_dir`
/// (an existing folder); a panel every `panels_every` frames (0: none). Throws
/// std::invalid_argument when no frame could be judged, naming the pass and why.
JudgeIlluminationMapResult JudgeIlluminationMap(const std::string& map_in,
                                                const std::string& rawlog,
                                                const std::string& out_dir, int panels_every,
                                                const IlluminationMapRunOptions& options);

}  // namespace novelty::experiments
