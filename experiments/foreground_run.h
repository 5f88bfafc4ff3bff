// A fixed camera's foreground, scored the CDnet way beside OpenCV's background subtractors (issue
// 52): every frame of a CDnet-layout folder, a folder of images or a video
// (sensors/dataset/fixed_camera_frames.h) goes through the appearance map as a static camera —
// foreground by maps/appearance/foreground_labels.h's rule, the background held there — and
// through OpenCV's MOG2 and KNN (video module) and the contrib GSOC and CNT (bgsegm), in the same
// run, each timed per frame. Masks are written as CDnet expects them (OUT/<method>/bin000001.png,
// 255 foreground); with ground truth, scores.csv gives per method recall, precision, F, PWC, FPR,
// the false-positive rate on shadows and ms a frame (eval/cdnet_scores.h), and findings.csv holds
// the targets: our F above KNN's at no more time than MOG2's.
#pragma once

#include <cmath>
#include <functional>
#include <string>
#include <vector>

#include "eval/cdnet_scores.h"
#include "eval/findings_table.h"
#include "maps/appearance/foreground_labels.h"
#include "sensors/dataset/image_header.h"

namespace novelty::experiments {

struct ForegroundRunOptions {
  /// A CDnet-layout folder, a plain folder of images or a video file
  /// (sensors/dataset/fixed_camera_frames.h); without ground truth nothing is scored.
  std::string folder;
  /// The map's decision rule: threshold, shadow label, small blobs (foreground_labels.h). Shadow
  /// pixels are not foreground in the masks.
  appearance::ForegroundLabelOptions labels;
  /// The map keeps its background where predictive novelty exceeds labels.threshold_nats
  /// (AppearanceMapOptions::hold_above_nats; shadows too); false: it learns every pixel, as the
  /// thesis's map does.
  bool hold_foreground = true;
  /// With hold_foreground: a pixel held this many frames in a row learns again
  /// (AppearanceMapOptions::max_hold_frames; 0: no limit). 200 (20 s at 10 fps) scored best on
  /// the simulated fixed-camera room: F 0.708, against 0.700 without a limit, 0.698 at 100 and
  /// 0.687 at 300 (docs/foreground.md).
  int max_hold_frames = 200;
  /// Methods to run, of "novelty", "mog2", "knn", "gsoc", "cnt".
  std::vector<std::string> methods = {"novelty", "mog2", "knn", "gsoc", "cnt"};
  int max_frames = 0;       ///< 0: all
  bool write_masks = true;  ///< OUT/<method>/binNNNNNN.png
  /// Every this many frames OUT/panels/NNNNNN.png: camera | truth | each method's mask scored
  /// against it (eval/cdnet_panel.h); 0: none.
  int panel_every = 50;
  long long max_pixels = sensors::kDefaultMaxImagePixels;
  std::function<void(int done, int total)> progress;
};

struct ForegroundMethod {
  std::string name;
  eval::CdnetCounts counts;  ///< over the scored frames
  eval::CdnetScores scores;
  double ms_per_frame = 0;
};

struct ForegroundRunResult {
  int frames = 0, scored = 0;  ///< frames run; of them with ground truth in the temporal ROI
  int unscored_in_roi = 0;     ///< a CDnet folder's frames in the temporal ROI without truth
  int expected_frames = 0;     ///< what the input said it holds (a video's container; 0: unsaid)
  bool cut_short = false;      ///< the input ended before expected_frames (a truncated video)
  std::vector<ForegroundMethod> methods;
  eval::FindingsTable findings;
};

/// Throws std::runtime_error naming the folder or file (FixedCameraFrames, an unreadable frame or
/// ground truth, a frame of another size), std::invalid_argument for no method, an unknown or
/// repeated one, or a threshold that is not positive.
ForegroundRunResult RunForeground(const ForegroundRunOptions& options, const std::string& out_dir);

}  // namespace novelty::experiments
