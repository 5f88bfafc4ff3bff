// View synthesis along a recorded path (thesis 3.3, figs. 3.6–3.7): every K-th RGB-D frame of a
// rawlog becomes a reference view at its ground-truth pose, and the view of each other frame is
// synthesised from the views selected for its rays and scored against the real frame by PSNR over
// the covered pixels, always with that coverage — the library side of novelty-synth's rawlog mode.
// The output folder gets NNNNNN.png per virtual view (uncovered pixels black) and frames.csv
// (frame, time since the first virtual view, synthesis ms, views blended, PSNR, coverage).
#pragma once

#include <functional>
#include <string>

#include "maps/views/view_synthesis.h"

namespace novelty::experiments {

struct ViewSynthesisRunOptions {
  std::string rawlog;       ///< RGB-D frames
  std::string groundtruth;  ///< novelty-sim's folder: the camera poses
  int every = 4;            ///< every K-th frame (1, K+1, …) is a reference view; K >= 2
  views::SynthesisOptions synthesis;  ///< warp and blend (the appearance map's defaults)
  /// Told a line of what was skipped (none: nothing is said).
  std::function<void(const std::string& line)> status;
  /// Told virtual views done of the total.
  std::function<void(int done, int total)> progress;
};

struct ViewSynthesisRunResult {
  int virtual_views = 0, reference_views = 0, skipped = 0;
  double mean_psnr_db = 0.0;   ///< over each view's covered pixels, averaged over the views
  double mean_coverage = 0.0;  ///< share of a virtual view's pixels covered, averaged
};

/// Runs it into `out_dir` (an existing folder). Throws std::invalid_argument for a bad option,
/// std::runtime_error naming the rawlog when it holds no RGB-D frame with a pose.
ViewSynthesisRunResult RunViewSynthesis(const ViewSynthesisRunOptions& options,
                                        const std::string& out_dir);

}  // namespace novelty::experiments
