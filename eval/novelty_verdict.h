// What a run without ground truth saw, in a sentence a report can give: the stretches of frames
// in which something new was in view, or "nothing new in frames a–b".
//
// Per frame the statistic is the surprise at its 50th most surprising predicted pixel
// (PredictionQuality::tail_surprise): a region of 50 pixels, a 7×7 blob, is the smallest worth
// telling a robot of. How high that tail runs on an unchanged scene depends on the sensor and the
// poses far more than on anything new — on the simulator 3–6 nats, on the hand-held TUM sequence
// 4–15 nats (docs/appearance.md) — so no level in nats serves both. A frame counts when its
// statistic stands out from the run's own: above median + z·σ̂ over the judged frames, where σ̂ is
// 1.4826 × the median deviation of the frames at or below the median (a standard deviation that
// frames with something new, which only raise the statistic, cannot move), and above an absolute
// floor. This presumes that at most half the frames of a run show something new. Frames the map
// did not predict (a first frame, a new place) have no say.
#pragma once

#include <string>
#include <vector>

#include "eval/prediction_quality.h"

namespace novelty::eval {

struct NoveltyVerdictOptions {
  /// The statistic's pixel: the tail_pixels-th most surprising (MeasurePrediction's argument).
  int tail_pixels = 50;
  /// Robust standard deviations above the run's median a frame's statistic must stand.
  double z = 3.0;
  /// Nats it must reach whatever the run (a run of a perfectly predicted scene has a tiny σ̂).
  double floor_nats = 5.0;
  /// Frames in a row it takes. One: a keyframe sequence shows a new thing surprising once, the
  /// map having learnt it by the next keyframe (the TUM cabinet's inserted box: 23.6 nats in its
  /// first frame, 15.9 in the next, against a threshold of 16.9); none of the unchanged runs
  /// measured has a single frame above its threshold.
  int min_frames = 1;
  /// Throws std::invalid_argument naming the option unless tail_pixels >= 1, z >= 0 and
  /// floor_nats >= 0 (both finite) and min_frames >= 1.
  void Check() const;
};

struct NovelStretch {
  int first = 0, last = 0;  ///< frame numbers, inclusive
  double peak_nats = 0.0;   ///< the highest statistic in it
};

struct NoveltyVerdict {
  int first_frame = 0, last_frame = 0;  ///< the predicted frames judged (0, 0: none)
  int frames_judged = 0;
  double median_nats = 0.0, sigma_nats = 0.0;  ///< the run's level and robust spread
  double threshold_nats = 0.0;                 ///< what a frame had to reach
  int tail_pixels = 50;                        ///< the statistic's pixel, as in the options
  double z = 3.0;                              ///< as in the options
  bool at_floor = false;                       ///< the floor, not the spread, set the threshold
  std::vector<NovelStretch> stretches;
  /// "Nothing new in frames 2–58 (…)." or "Something new in frames 64–80 (peak 12.3 nats), …".
  std::string Sentence() const;
};

/// Judges the frames `frame_numbers[k]` with their measured quality `frames[k]` (measured with
/// options.tail_pixels; the same length;
/// std::invalid_argument otherwise). Stretches are runs of counting frames among the predicted
/// ones, in order; a frame the map did not predict neither breaks nor extends a stretch.
NoveltyVerdict JudgeNovelty(const std::vector<int>& frame_numbers,
                            const std::vector<PredictionQuality>& frames,
                            const NoveltyVerdictOptions& options = {});

}  // namespace novelty::eval
